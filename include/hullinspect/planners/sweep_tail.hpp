#pragma once
// Sweep-Inspect's help with a sweep's tail (docs/sweep-inspect.md, "Help"): a UAV whose sweep is
// done takes the far end of another's — its last bands, or the far part of its last band — so
// that the bands' structure is kept where helping cell by cell would fly to scattered cells.

#include <span>
#include <vector>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/band_sweep.hpp"

namespace hullinspect::planners {

/// A sweep left to fly: its waypoints, where its UAV flies them from (its position, or the
/// point where it rejoins its band), the steps before it is back there (0 when sweeping), and
/// the sweep's axis (a leg along it is a band; any other, a flight between bands).
struct SweepLeft {
  std::span<const grid::Cell> rest;
  grid::Cell from;
  int back = 0;
  BandAxis axis = BandAxis::kRows;
};

/// The estimate of a sweep's steps per step of its waypoints' walk (Manhattan): inspections and
/// turns on the way.
inline constexpr double kTailWalkCost = 1.2;

/// When the sweep left alone ends: back + kTailWalkCost · the walk through its waypoints.
double sweep_left_end(const SweepLeft& left);

/// A split of a sweep left between its UAV and a helper.
struct TailSplit {
  double end = 0.0;       ///< the later of the two estimated ends
  int leg = -1;           ///< the split lies on the leg into rest[leg] (−1: no split)
  grid::Cell at{-1, -1};  ///< where the UAV stops and the helper's tail begins
  bool skip_leg = false;  ///< split at a leg between two bands: neither flies it
  bool backward = false;  ///< the helper flies the tail from its far end
};

/// The split of `left` that ends it earliest, the UAV flying up to a point and stopping there,
/// the helper (at `helper`, flights of `flights`) flying the rest from either end: anywhere
/// along a band, or at a leg between two bands (not flown); none (leg −1) unless it ends both
/// at least `min_saving` steps before the sweep alone would. `walk` is scratch.
TailSplit split_sweep_tail(const SweepLeft& left, grid::Cell helper, grid::DistanceService& flights,
                           int min_saving, std::vector<int>& walk);

}  // namespace hullinspect::planners
