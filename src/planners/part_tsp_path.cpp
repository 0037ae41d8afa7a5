#include "hullinspect/planners/part_tsp_path.hpp"

#include "hullinspect/core/errors.hpp"

namespace hullinspect::planners::part_tsp {

void SegmentPath::assign(std::span<const StripSegment> segments,
                         std::span<const std::pair<grid::Cell, grid::Cell>> ends,
                         std::span<const tsp::Visit> order) {
  if (order.size() != segments.size() || ends.size() != segments.size()) {
    throw LogicError("SegmentPath: the TSP order does not visit every segment once");
  }
  clear();
  used_.assign(segments.size(), 0);
  for (const tsp::Visit& v : order) {
    if (v.segment < 0 || static_cast<std::size_t>(v.segment) >= segments.size() ||
        used_[static_cast<std::size_t>(v.segment)] != 0) {
      throw LogicError("SegmentPath: the TSP order does not visit every segment exactly once");
    }
    const auto s = static_cast<std::size_t>(v.segment);
    used_[s] = 1;
    const auto& [left, right] = ends[s];
    PlannedVisit visit{segments[s], v.reversed ? right : left, v.reversed ? left : right};
    visits_.push_back(visit);
    waypoints_.push_back(visit.entry);
    waypoints_.push_back(visit.exit);
  }
}

void SegmentPath::clear() {
  visits_.clear();
  waypoints_.clear();
  next_ = 0;
}

void SegmentPath::advance(grid::Cell pos) {
  while (next_ < waypoints_.size() && waypoints_[next_] == pos) ++next_;
}

sim::Action SegmentPath::next_action(grid::Cell pos) {
  if (finished()) return sim::Action::kHover;
  if (distances_ == nullptr) return sim::step_towards(pos, waypoints_[next_]);
  // Along a segment (towards its exit, an odd waypoint) straight, through any long neighbour
  // flight: a shorter way around it would leave the segment's cells unseen.
  if (distances_->has_long_flights() && next_ % 2 == 1) {
    return sim::step_towards(pos, waypoints_[next_]);
  }
  return sim::move_to_neighbour(pos, towards_.next_step(pos, waypoints_[next_]));
}

}  // namespace hullinspect::planners::part_tsp
