#pragma once
// Follows a list of waypoints cell by cell along the distance service's shortest flights (without
// no-fly positions: the fixed Manhattan rule, x first, then y).

#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/sim/types.hpp"

namespace hullinspect::planners {

class WaypointFollower {
 public:
  void assign(std::vector<grid::Cell> waypoints) {
    waypoints_ = std::move(waypoints);
    next_ = 0;
  }
  void clear() { assign({}); }
  /// The service whose paths to follow; null: the Manhattan rule.
  void set_distances(grid::DistanceService* distances) { distances_ = distances; }
  /// The move from `pos` towards the next waypoint not yet reached; kHover when all are reached.
  sim::Action next_action(grid::Cell pos) {
    while (next_ < waypoints_.size() && waypoints_[next_] == pos) ++next_;
    if (next_ >= waypoints_.size()) return sim::Action::kHover;
    if (distances_ == nullptr) return sim::step_towards(pos, waypoints_[next_]);
    return sim::move_to_neighbour(pos, distances_->next_step(pos, waypoints_[next_]));
  }
  /// Drops the next `count` waypoints not yet reached.
  void skip(std::size_t count) { next_ = std::min(waypoints_.size(), next_ + count); }
  /// Keeps only the first `count` waypoints not yet reached (the rest went to another UAV).
  void keep(std::size_t count) { waypoints_.resize(std::min(waypoints_.size(), next_ + count)); }
  /// Keeps the first `count` waypoints not yet reached, then ends at `last`.
  void keep(std::size_t count, grid::Cell last) {
    keep(count);
    waypoints_.push_back(last);
  }
  bool finished(grid::Cell pos) const {
    return next_ >= waypoints_.size() ||
           (next_ + 1 == waypoints_.size() && waypoints_[next_] == pos);
  }
  std::span<const grid::Cell> remaining() const {
    return std::span<const grid::Cell>(waypoints_).subspan(std::min(next_, waypoints_.size()));
  }
  grid::Cell target() const {
    return next_ < waypoints_.size() ? waypoints_[next_] : grid::Cell{-1, -1};
  }

 private:
  std::vector<grid::Cell> waypoints_;
  std::size_t next_ = 0;
  grid::DistanceService* distances_ = nullptr;
};

}  // namespace hullinspect::planners
