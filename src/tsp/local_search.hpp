#pragma once
// Internal: the local search behind the "heuristic" solver, also the first tour of the exact
// branch-and-cut. Nearest-neighbour construction from the UAV, then 2-opt (which reverses a run of
// visits and so flips each segment in it; a run of one is a plain flip) and Or-opt (moves a run of
// 1–3 visits elsewhere, in either direction) to a local optimum, then `kicks` rounds of iterated
// local search: a double-bridge perturbation of the best tour, local search, keep if shorter.
// The descent uses don't-look bits: only visits next to a change are re-examined, so a kick costs
// O(g) move evaluations per touched visit instead of full O(g²) passes. Deterministic for a seed.

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
  /// Applies improving moves around the active visits until none is left.
  void descend(const EndCosts& costs, std::vector<int>& tour);
  /// Applies the first improving move that touches position i, if any.
  bool improve_at(const EndCosts& costs, std::vector<int>& tour, int i);
  bool two_opt_at(const EndCosts& costs, std::vector<int>& tour, int i);
  bool or_opt_block(const EndCosts& costs, std::vector<int>& tour, int first, int last);
  void reverse(std::vector<int>& tour, int from, int to);  // visits from..to, flipped
  void activate_position(const std::vector<int>& tour, int position);
  void activate_all(const std::vector<int>& tour);

  std::vector<int> current_;  // scratch, kept between calls
  std::vector<char> used_, active_;
  std::vector<int> queue_;  // active segments
};

}  // namespace hullinspect::tsp::detail
