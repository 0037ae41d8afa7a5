#pragma once
// One step of the distance service's bucketed search over neighbour flights, shared by the
// whole-grid search and the search that stops at its targets.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/grid/grid.hpp"

namespace hullinspect::grid::detail {

/// Relaxes the flights out of cell `i`, settled at distance `d`: every neighbour (across a linked
/// seam included) that this shortens gets its new distance in `dist` and a place in the bucket of
/// that distance modulo buckets.size(); `first_reach(j)` runs when j had no distance before
/// (kUnreachable). Returns how many cells were pushed.
template <class Distances, class FirstReach>
std::size_t relax_flights(int i, int d, const Grid<std::uint8_t>& allowed, const EdgeSteps& steps,
                          Distances& dist, std::vector<std::vector<int>>& buckets,
                          FirstReach first_reach) {
  const Cell here = allowed.cell(i);
  const auto span = buckets.size();
  std::size_t pushed = 0;
  for (int n = 0; n < 4; ++n) {
    const Cell next = neighbour(here, n, allowed.width(), allowed.height(), steps);
    if (next == kNoCell) continue;
    const int j = allowed.index(next);
    const int reached = d + steps.between(here, next);
    if (dist[j] <= reached) continue;
    if (dist[j] == kUnreachable) first_reach(j);
    dist[j] = reached;
    buckets[static_cast<std::size_t>(reached) % span].push_back(j);
    ++pushed;
  }
  return pushed;
}

}  // namespace hullinspect::grid::detail
