#pragma once
// Internal to Sweep-Inspect's sources (src/planners/sweep_inspect_*.cpp): small geometric and map
// tests they share.

#include <algorithm>
#include <cstdlib>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/band_sweep.hpp"
#include "hullinspect/sim/planner_view.hpp"

namespace hullinspect::planners::sweep_inspect_detail {

// Whether the leg from `a` to `b` runs along x (as a row band's). A band runs along its sweep's
// axis, but an approach leg may run across it; a leg that is not straight (or
// empty) is taken as the sweep's.
inline bool leg_along_x(BandAxis axis, grid::Cell a, grid::Cell b) {
  if (a.y == b.y && a.x != b.x) return true;
  if (a.x == b.x && a.y != b.y) return false;
  return axis == BandAxis::kRows;
}

using grid::chebyshev;

/// Not yet observed: unknown, or expected corroded by the prior and not yet seen.
inline bool unobserved(const sim::PlannerView& view, int i) {
  return view.map[i] == sim::kUnknown || (view.map[i] == sim::kCorrosionSeen && view.seen[i] == 0);
}

/// Whether a 4-neighbour of (x, y) is inspected: an unobserved cell there is likely corroded too
/// (corrosion comes in rectangles).
inline bool beside_inspected(const grid::Grid<std::int8_t>& map, int x, int y) {
  return (x > 0 && map(x - 1, y) == sim::kInspected) ||
         (x + 1 < map.width() && map(x + 1, y) == sim::kInspected) ||
         (y > 0 && map(x, y - 1) == sim::kInspected) ||
         (y + 1 < map.height() && map(x, y + 1) == sim::kInspected);
}

/// Work left at cell i for a sweep: a cell not yet observed, or, for a sweep at z = 1 (`low`),
/// also a detected cell, which its footprint inspects on the way.
inline bool sweep_work(const sim::PlannerView& view, int i, bool low) {
  return unobserved(view, i) || (low && view.map[i] == sim::kCorrosionSeen);
}

}  // namespace hullinspect::planners::sweep_inspect_detail
