#pragma once
// Internal to the TSP solvers: the problem's costs (node_distance) between the UAV and the 2g
// segment ends, in the numbering the solvers share. End 2l is segment l's `first`, end 2l+1 its
// `second`; a visit that enters segment l by end e leaves by end e ^ 1, so a tour is a sequence of
// entry ends. Index 2g is the UAV. Coordinates are grid cells, so every cost fits an int.

#include <chrono>
#include <span>
#include <vector>

#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp::detail {

class EndCosts {
 public:
  /// Fills the (2g+1)² table; reuses its storage across calls.
  void assign(const SegmentTsp& problem);
  int segments() const { return g_; }
  int ends() const { return 2 * g_; }
  int start() const { return 2 * g_; }
  /// Cost from end (or UAV) a to end (or UAV) b; symmetric.
  int operator()(int a, int b) const {
    return cost_[static_cast<std::size_t>(a) * static_cast<std::size_t>(stride_) +
                 static_cast<std::size_t>(b)];
  }
  /// Cell of end (or UAV) a.
  grid::Cell cell(int a) const { return cells_[static_cast<std::size_t>(a)]; }
  /// Sum of the segments' own lengths: a constant in every tour.
  long long segment_total() const { return segment_total_; }
  /// Path length of a sequence of entry ends (segments included).
  long long length(std::span<const int> entries) const;

 private:
  /// The table from the service's searches (not the Manhattan distances).
  void searched_costs(grid::DistanceService& distances);

  int g_ = 0;
  int stride_ = 1;
  long long segment_total_ = 0;
  std::vector<int> cost_;
  std::vector<grid::Cell> cells_;
};

inline int entry_end(Visit v) {
  return 2 * v.segment + (v.reversed ? 1 : 0);
}
inline Visit visit_of_entry(int entry) {
  return {entry >> 1, (entry & 1) != 0};
}

/// The solution for a sequence of entry ends; `seconds` measured from `started`.
TspSolution make_solution(const SegmentTsp& problem, std::span<const int> entries, bool optimal,
                          std::chrono::steady_clock::time_point started);
/// The same, its length read from the table `costs` of the problem (no distance computed again).
TspSolution make_solution(const EndCosts& costs, std::span<const int> entries, bool optimal,
                          std::chrono::steady_clock::time_point started);

/// A lower bound on every tour's length, O(g²): the segments, the cheapest first leg from the UAV,
/// and half of each end's cheapest link to another segment for all ends but the two most
/// expensive (a tour's g − 1 links between segments touch every end except its first entry and
/// its last exit, each once).
long long simple_lower_bound(const EndCosts& costs);
/// Seconds elapsed since `started`.
double seconds_since(std::chrono::steady_clock::time_point started);

/// Throws LogicError if `solution` is not a valid order of `problem` or its length is wrong: a
/// solver bug, never bad input.
void check_solution(const SegmentTsp& problem, const TspSolution& solution, const char* solver);

}  // namespace hullinspect::tsp::detail
