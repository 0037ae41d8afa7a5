#pragma once
// Follows a list of waypoints cell by cell along the distance service's shortest flights (without
// no-fly positions: the fixed Manhattan rule, x first, then y).

#include <algorithm>
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
    reached_ = false;
  }
  void clear() { assign({}); }
  /// The service whose paths to follow; null: the Manhattan rule.
  void set_distances(grid::DistanceService* distances) { distances_ = distances; }
  /// The move from `pos` towards the next waypoint not yet reached; kHover when all are reached.
  /// Without a service, a UAV moved off the straight lane between the waypoint it reached last
  /// and the next (a side-step that keeps its separation from another UAV) first returns to the
  /// lane beside where it is, so that every cell of the lane is flown.
  sim::Action next_action(grid::Cell pos) {
    while (next_ < waypoints_.size() && waypoints_[next_] == pos) {
      ++next_;
      reached_ = true;
    }
    if (next_ >= waypoints_.size()) return sim::Action::kHover;
    if (distances_ == nullptr) return sim::step_towards(pos, back_on_lane(pos));
    return sim::move_to_neighbour(pos, distances_->next_step(pos, waypoints_[next_]));
  }
  /// Drops the next `count` waypoints not yet reached.
  void skip(std::size_t count) {
    next_ = std::min(waypoints_.size(), next_ + count);
    reached_ = false;
  }
  /// Keeps only the first `count` waypoints not yet reached (the rest went to another UAV).
  void keep(std::size_t count) { waypoints_.resize(std::min(waypoints_.size(), next_ + count)); }
  /// Keeps the first `count` waypoints not yet reached, then ends at `last`.
  void keep(std::size_t count, grid::Cell last) {
    keep(count);
    if (count == 0) reached_ = false;  // `last` is no lane from the waypoint reached
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
  // The cell beside `pos` on the lane from the last waypoint reached to the next, when the lane
  // is straight and `pos` beside it but off it; else the next waypoint.
  grid::Cell back_on_lane(grid::Cell pos) const {
    const grid::Cell to = waypoints_[next_];
    if (!reached_ || next_ == 0) return to;
    const grid::Cell from = waypoints_[next_ - 1];
    const auto within = [](int v, int a, int b) {
      return std::min(a, b) <= v && v <= std::max(a, b);
    };
    if (from.y == to.y && pos.y != to.y && within(pos.x, from.x, to.x)) return {pos.x, to.y};
    if (from.x == to.x && pos.x != to.x && within(pos.y, from.y, to.y)) return {to.x, pos.y};
    return to;
  }

  std::vector<grid::Cell> waypoints_;
  std::size_t next_ = 0;
  bool reached_ = false;  ///< the waypoint before next_ was reached (not skipped)
  grid::DistanceService* distances_ = nullptr;
};

}  // namespace hullinspect::planners
