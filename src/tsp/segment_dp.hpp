#pragma once
// Internal: exact dynamic program over (set of visited segments, exit end), Held–Karp style with
// each segment's two directions folded into the exit end. O(2^g · (2g)²) time, 2^g · 2g ints of
// memory, so it is used for small g only.

#include <cstdint>
#include <vector>

#include "end_costs.hpp"

namespace hullinspect::tsp::detail {

class SegmentDp {
 public:
  /// Largest g the table is allowed to grow to (65536 × 32 ints = 8 MiB).
  static constexpr int kMaxSegments = 16;
  /// Writes an optimal sequence of entry ends into `entries`. Requires 1 ≤ g ≤ kMaxSegments.
  /// Ties go to the lowest end index, so the answer is deterministic.
  void solve(const EndCosts& costs, std::vector<int>& entries);

 private:
  std::vector<std::int32_t> table_;  // [mask][exit end]: cheapest path from the UAV
};

}  // namespace hullinspect::tsp::detail
