#pragma once
// The order in which Sweep-Inspect visits the prior's cells at z = 1 (docs/sweep-inspect.md, "The
// prior"): an open tour from the UAV over points it must see with a footprint, improved by local
// search.

#include <span>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners {

/// What a tour costs: a leg from a to b costs its Manhattan length less `reach` on each axis (the
/// footprint, Chebyshev half-width `reach`, sees b from that far: points within one footprint
/// cost nothing).
struct OpenTourCost {
  int reach = 0;

  int leg(grid::Cell a, grid::Cell b) const;
  /// The cost of visiting `points` in their order from `from`.
  int of(grid::Cell from, std::span<const grid::Cell> points) const;
};

/// Orders `points` (in place) into a short open tour from `from`: nearest neighbour, then 2-opt
/// (reversing a run) and Or-opt (moving a run of 1–3 points elsewhere, either way round) until no
/// such move lowers the cost. Deterministic (ties keep the earlier point); O(m²) per pass, no
/// allocation.
void plan_open_tour(grid::Cell from, std::span<grid::Cell> points, const OpenTourCost& cost);

}  // namespace hullinspect::planners
