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
// axis, but an approach leg (approach-edge) may run across it; a leg that is not straight (or
// empty) is taken as the sweep's.
inline bool leg_along_x(BandAxis axis, grid::Cell a, grid::Cell b) {
  if (a.y == b.y && a.x != b.x) return true;
  if (a.x == b.x && a.y != b.y) return false;
  return axis == BandAxis::kRows;
}

inline int chebyshev(grid::Cell a, grid::Cell b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y));
}

/// Not yet observed: unknown, or expected corroded by the prior and not yet seen.
inline bool unobserved(const sim::PlannerView& view, int i) {
  return view.map[i] == sim::kUnknown || (view.map[i] == sim::kCorrosionSeen && view.seen[i] == 0);
}

/// Work left at cell i for a sweep: a cell not yet observed, or, for a sweep at z = 1 (`low`),
/// also a detected cell, which its footprint inspects on the way.
inline bool sweep_work(const sim::PlannerView& view, int i, bool low) {
  return unobserved(view, i) || (low && view.map[i] == sim::kCorrosionSeen);
}

}  // namespace hullinspect::planners::sweep_inspect_detail
