#pragma once
// A UAV's current Part-TSP plan: the segments in TSP order, each entered at one end and flown to
// the other along its flight row. Between consecutive waypoints the UAV follows the distance
// service's shortest flight (without no-fly positions: the project's fixed Manhattan rule,
// sim::step_towards: along x first, then along y).

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/grid/target_search.hpp"
#include "hullinspect/planners/part_tsp_segments.hpp"
#include "hullinspect/sim/types.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::planners::part_tsp {

struct PlannedVisit {
  StripSegment segment;
  grid::Cell entry;
  grid::Cell exit;
};

class SegmentPath {
 public:
  /// Replaces the plan: `order` visits `segments` (with their flown `ends`) in sequence.
  void assign(std::span<const StripSegment> segments,
              std::span<const std::pair<grid::Cell, grid::Cell>> ends,
              std::span<const tsp::Visit> order);
  void clear();
  /// The service whose paths to follow; null: the Manhattan rule.
  void set_distances(grid::DistanceService* distances) {
    distances_ = distances;
    towards_.bind(distances);
  }

  /// Passes over the waypoints already reached at `pos`.
  void advance(grid::Cell pos);
  /// Every waypoint reached (call advance() first).
  bool finished() const { return next_ >= waypoints_.size(); }
  /// The move towards the next waypoint; kHover when finished. The service's shortest flight,
  /// searched from the waypoint only as far as `pos` (its answer is the service's next_step).
  sim::Action next_action(grid::Cell pos);

  /// The visit the UAV heads for or is flying (valid while not finished).
  const PlannedVisit& current_visit() const { return visits_[next_ / 2]; }
  /// True while the UAV is past the entry of the current visit (flying its segment).
  bool on_segment() const { return next_ % 2 == 1; }
  /// Drops the current visit (the UAV goes on to the next one).
  void skip_current_visit() { next_ = (next_ / 2 + 1) * 2; }

  std::span<const PlannedVisit> visits() const { return visits_; }
  /// The next waypoint, or (−1, −1) when finished.
  grid::Cell target() const { return finished() ? grid::Cell{-1, -1} : waypoints_[next_]; }
  /// The waypoints still ahead (the next one first).
  std::span<const grid::Cell> remaining() const {
    return std::span<const grid::Cell>(waypoints_).subspan(std::min(next_, waypoints_.size()));
  }

 private:
  std::vector<PlannedVisit> visits_;
  std::vector<grid::Cell> waypoints_;  // entry, exit of each visit
  std::size_t next_ = 0;
  std::vector<std::uint8_t> used_;  // scratch: segments already in the order
  grid::DistanceService* distances_ = nullptr;
  grid::TargetSearch towards_;  // towards the next waypoint, kept while it stays the same
};

}  // namespace hullinspect::planners::part_tsp
