#pragma once
// Internal: the local search behind the "heuristic" solver, also the initial upper bound of the
// exact branch-and-cut. Nearest-neighbour construction from the UAV, then 2-opt (which reverses a
// run of visits and so flips each segment in it; a run of one is a plain flip) and Or-opt (moves a
// run of 1–3 visits elsewhere, in either direction) to a local optimum, then `kicks` rounds of
// iterated local search: a double-bridge perturbation of the best tour, local search, keep if
// shorter. Deterministic for a given seed.

#include <cstdint>
#include <vector>

#include "end_costs.hpp"

namespace hullinspect::tsp::detail {

class LocalSearch {
 public:
  /// Writes the best sequence of entry ends found into `best`; returns its length (segments
  /// included). Requires g ≥ 1.
  long long run(const EndCosts& costs, int kicks, std::uint64_t seed, std::vector<int>& best);

 private:
  void nearest_neighbour(const EndCosts& costs, std::vector<int>& tour);
  /// Applies improving moves until none is left; returns the total change (≤ 0).
  long long descend(const EndCosts& costs, std::vector<int>& tour);
  long long two_opt_pass(const EndCosts& costs, std::vector<int>& tour);
  long long or_opt_pass(const EndCosts& costs, std::vector<int>& tour);

  std::vector<int> current_;  // scratch, kept between calls
  std::vector<char> used_;
};

}  // namespace hullinspect::tsp::detail
