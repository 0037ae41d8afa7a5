#pragma once
// The way to one target, searched only as far as it is asked about. DistanceService::next_step()
// reads a whole-grid field from its target; a UAV flying between two nearby waypoints of a large
// hull (the unrolled DTC: over 100 000 positions) needs only the positions nearer to the target
// than itself. This search runs from the target and stops as soon as the position asked about is
// settled; a later question (the UAV one step on, hence nearer) usually needs nothing more, and a
// farther one resumes the search where it stopped. Its answers are DistanceService::next_step()'s.
//
// One per follower (it holds one target at a time); not thread-safe.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hullinspect/grid/distance_service.hpp"

namespace hullinspect::grid {

class TargetSearch {
 public:
  /// Follows `service`'s allowed positions and neighbour flights (null: none bound). The service
  /// must outlive the search; binding forgets any search done.
  void bind(DistanceService* service);

  /// DistanceService::next_step(from, to) of the bound service, with the same answer.
  Cell next_step(Cell from, Cell to);

  /// Positions the current target's search has given a distance to (for tests and benchmarks).
  std::size_t reached() const { return touched_.size(); }

 private:
  /// Forgets the current search and starts one from `target`.
  void restart(int target);
  /// Searches until the distance at `index` is final (or every reachable position is settled).
  void settle(int index);

  DistanceService* service_ = nullptr;
  int target_ = -1;
  int settled_ = -1;  // every distance ≤ settled_ is final and its flights relaxed
  std::size_t pending_ = 0;
  Grid<int> dist_;
  std::vector<int> touched_;               // positions with a distance, reset on restart
  std::vector<std::vector<int>> buckets_;  // distance mod (longest flight + 1)
};

}  // namespace hullinspect::grid
