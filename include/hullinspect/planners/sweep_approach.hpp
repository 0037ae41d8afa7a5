#pragma once
// Sweep-Inspect's approach to its sweep (docs/beyond.md, approach-edge): the flight from where a
// UAV is to the first band of its sweep observes cells too. Flown along the middle of the bands
// (the x-then-y rule from a start cell in mid-region) it sees cells the bands will fly over
// again; flown along the region's edge row, it sees the bands' ends there, which the bands then
// need not fly to.

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/band_sweep.hpp"

namespace hullinspect::planners {

/// How a sweep is planned from a position over the cells where an owner grid holds the UAV (as
/// band_sweep, with the same band width, axis and band grid, and any reversal the caller makes).
struct SweepRequest {
  int uav = 0;
  int band = 1;  ///< the band width (odd): the footprint's side
  BandAxis axis = BandAxis::kColumns;
  bool trim_ends = true;
  std::span<const int> band_start;  ///< the band grid for column bands (empty: the region's own)
  bool nearer_end = true;           ///< fly the sweep backwards when its last waypoint is nearer
  int x_lo = 0;                     ///< only these columns hold the UAV's cells (band_sweep's)
  int x_hi = -1;
};

/// A sweep's waypoints, the first `approach` of them its approach's.
struct SweepPlan {
  std::vector<grid::Cell> waypoints;
  std::size_t approach = 0;
};

/// The waypoints of a sweep over `owner`'s cells of `request.uav` from `from`, led by an approach
/// when that makes the whole flight shorter (Manhattan): across to a band's centre line, along
/// it to the region's first or last row a footprint must reach, and along that edge to the
/// region's first or last band; the cells the approach's footprints see are left out of the
/// sweep, so the bands it passes are flown only as far as the rest needs. Without an approach
/// that helps, the plain sweep from `from`. `scratch` is reused for the owner grid less those
/// cells (same size as `owner`; only the region's columns are written).
SweepPlan approach_and_sweep(const grid::Grid<std::int16_t>& owner, const SweepRequest& request,
                             grid::Cell from, grid::Grid<std::int16_t>& scratch);

/// The plain sweep of `request` from `from` (band_sweep, reversed when its far end is nearer
/// and `nearer_end`).
std::vector<grid::Cell> plain_sweep(const grid::Grid<std::int16_t>& owner,
                                    const SweepRequest& request, grid::Cell from);

}  // namespace hullinspect::planners
