#pragma once
// Follows a list of waypoints cell by cell under the fixed Manhattan rule (x first, then y).

#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/sim/types.hpp"

namespace hullinspect::planners {

class WaypointFollower {
 public:
  void assign(std::vector<grid::Cell> waypoints) {
    waypoints_ = std::move(waypoints);
    next_ = 0;
  }
  void clear() { assign({}); }
  /// The move from `pos` towards the next waypoint not yet reached; kHover when all are reached.
  sim::Action next_action(grid::Cell pos) {
    while (next_ < waypoints_.size() && waypoints_[next_] == pos) ++next_;
    return next_ < waypoints_.size() ? sim::step_towards(pos, waypoints_[next_]) : sim::Action::kHover;
  }
  bool finished(grid::Cell pos) const {
    return next_ >= waypoints_.size() || (next_ + 1 == waypoints_.size() && waypoints_[next_] == pos);
  }
  std::span<const grid::Cell> remaining() const {
    return std::span<const grid::Cell>(waypoints_).subspan(std::min(next_, waypoints_.size()));
  }
  grid::Cell target() const { return next_ < waypoints_.size() ? waypoints_[next_] : grid::Cell{-1, -1}; }

 private:
  std::vector<grid::Cell> waypoints_;
  std::size_t next_ = 0;
};

}  // namespace hullinspect::planners
