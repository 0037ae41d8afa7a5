#pragma once
// Sweep-Inspect's approach to its sweep (docs/sweep-inspect.md, "The sweep"): the flight from where
// a UAV is to the first band of its sweep observes cells too. Flown along the middle of the bands
// (the x-then-y rule from a start cell in mid-region) it sees cells the bands will fly over
// again; flown along the region's edge row, it sees the bands' ends there, which the bands then
// need not fly to.

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/band_sweep.hpp"
#include "hullinspect/planners/owned_runs.hpp"
#include "hullinspect/planners/sweep_chooser.hpp"

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
  bool edge_approach = true;    ///< consider approaches along the region's edge
  bool own_band_first = false;  ///< consider sweeps that begin at the UAV's band
};

/// Reused between plans: the region's runs, and the bands' cells along.
struct SweepScratch {
  OwnedRuns runs;
  std::vector<int> last_upto;   ///< per band and along: the last cell at or before it (−1)
  std::vector<int> first_from;  ///< per band and along: the first cell at or after it
  RegionBands first;
  RegionBands second;
};

/// The candidate sweeps over `owner`'s cells of `request.uav` from `from`, costed by their
/// Manhattan flight (reach: to the first band, the approach included): first the plain sweep,
/// then the plans below that the request allows.
/// - `edge_approach`: led by an approach — across to a band's centre line, along it to the
///   region's first or last row a footprint must reach, and along that edge to the region's
///   first or last band; the cells the approach's footprints see are left out of the sweep, so
///   the bands it passes are flown only as far as the rest needs.
/// - `own_band_first`: in two parts, so that a UAV starting in mid-region does not first cross
///   bands it will fly again: the bands from the UAV's own to one side of it (all of their
///   cells, or those on one side of a cut along the bands at, or h before or after, the UAV's
///   position) swept from `from`, then the rest from where they end.
std::vector<SweepCandidate> approach_candidates(const grid::Grid<std::int16_t>& owner,
                                                const SweepRequest& request, grid::Cell from,
                                                SweepScratch& scratch);

/// choose_plan's pick among approach_candidates.
SweepPlan approach_and_sweep(const grid::Grid<std::int16_t>& owner, const SweepRequest& request,
                             grid::Cell from, SweepScratch& scratch);

/// The plain sweep of `request` from `from` (band_sweep, reversed when its far end is nearer
/// and `nearer_end`).
std::vector<grid::Cell> plain_sweep(const grid::Grid<std::int16_t>& owner,
                                    const SweepRequest& request, grid::Cell from);

/// The candidate sweeps of `request`'s cells as two blocks of columns, one after the other,
/// after `plain` (the one boustrophedon, listed first): cut between two bands (at x_lo + j·band
/// for row bands, at a start of the band grid for column bands), either block first, each a
/// plain_sweep, costed by their Manhattan flight from `from`. A region swept in part is ragged,
/// and one boustrophedon over its bands can leave a band for last on its far side.
std::vector<SweepCandidate> two_block_candidates(const grid::Grid<std::int16_t>& owner,
                                                 const SweepRequest& request, grid::Cell from,
                                                 std::vector<grid::Cell> plain);

/// choose_plan's pick among two_block_candidates (`plain` when none is shorter).
std::vector<grid::Cell> two_block_sweep(const grid::Grid<std::int16_t>& owner,
                                        const SweepRequest& request, grid::Cell from,
                                        std::vector<grid::Cell> plain);

/// The two candidate sweeps of band_sweep over `owner`'s cells of `uav` from `from` (ends
/// trimmed): along rows, then along columns, costed by their Manhattan flight.
std::vector<SweepCandidate> axis_candidates(const grid::Grid<std::int16_t>& owner, int uav,
                                            int band, grid::Cell from,
                                            std::span<const int> band_start);

}  // namespace hullinspect::planners
