#pragma once
// Sweep-Inspect's rejoining of a band after an inspection (docs/sweep-inspect.md, "Inspecting"):
// how far along the band a UAV may come back to it without leaving a cell of the band unobserved.

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/band_sweep.hpp"
#include "hullinspect/sim/planner_view.hpp"

namespace hullinspect::planners {

/// A band left for an inspection: where the UAV left it (on the band's centre line, at z = 2),
/// the band end it was flying to, and the sweep's axis (for a leg that is not straight).
struct LeftBand {
  grid::Cell left;
  grid::Cell end;
  BandAxis axis = BandAxis::kRows;
};

/// The point of `band`'s centre line where a UAV now at `pos` rejoins it. From `band.left` the
/// footprint (half-side `half`) saw the band up to `half` cells ahead, and on the way below it
/// saw more; from a point r of the centre line the footprint sees `half` cells behind r. So the
/// UAV may rejoin at any r, towards `band.end`, up to where it now is (along the band), that
/// leaves no hull cell of the band between the two footprints unobserved in `view` and that
/// `flights` allows; `band.left` when none is further on (or `end` is not on the left point's
/// line).
grid::Cell band_rejoin_point(const LeftBand& band, grid::Cell pos, int half,
                             const sim::PlannerView& view, const grid::DistanceService& flights);

}  // namespace hullinspect::planners
