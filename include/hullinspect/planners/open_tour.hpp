#pragma once
// The order in which Sweep-Inspect visits the prior's cells at z = 1 (docs/sweep-inspect.md, "The
// prior"): an open tour from the UAV over points it must see with a footprint, improved by local
// search.

#include <cstddef>
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

/// Up to this many points every 2-opt and Or-opt move is tried; above, only moves that join a
/// point to one of its nearest points.
inline constexpr std::size_t kExhaustiveTourPoints = 400;

/// Orders `points` (in place) into a short open tour from `from`: plan_open_tour_exhaustive up to
/// kExhaustiveTourPoints points, plan_open_tour_neighbours above. Deterministic.
void plan_open_tour(grid::Cell from, std::span<grid::Cell> points, const OpenTourCost& cost);

/// Nearest neighbour, then 2-opt (reversing a run) and Or-opt (moving a run of 1–3 points
/// elsewhere, either way round) until no such move lowers the cost. Ties keep the earlier point;
/// O(m²) per pass, no allocation.
void plan_open_tour_exhaustive(grid::Cell from, std::span<grid::Cell> points,
                               const OpenTourCost& cost);

/// The same construction and moves restricted to each point's 16 nearest points and its 4
/// nearest in each quadrant around it (found through a grid of buckets), each point looked at
/// again only when an edge at it changed (don't-look bits): about linear work in the points for
/// points spread over a hull. Ties go to the earlier point.
void plan_open_tour_neighbours(grid::Cell from, std::span<grid::Cell> points,
                               const OpenTourCost& cost);

/// Improves a tour `points` from `from` where it changed (its start moved, points left it): the
/// exhaustive search's 2-opt and Or-opt moves, each the best that removes an edge at one node,
/// looked for at the `touched` nodes (the ends of the edges that changed: 0 the start, i ≥ 1
/// points[i − 1]) and then at the ends of
/// every edge a move changed (don't-look bits), until no such move shortens it. O(m) per node
/// looked at, so a tour kept short as it is flown costs far less than one planned anew.
void repair_open_tour(grid::Cell from, std::span<grid::Cell> points,
                      std::span<const std::size_t> touched, const OpenTourCost& cost);

}  // namespace hullinspect::planners
