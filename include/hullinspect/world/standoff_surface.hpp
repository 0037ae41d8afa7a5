#pragma once
// Where a UAV stands off from an unrolled hull at every grid position (docs/hulls.md "The whole
// hull"): a cell with surface stands off from its own surface point along its normal; a grid
// position without surface (above the deck line, beyond the stern where a lower cut is shorter)
// has none of its own, yet UAVs fly over it, so it borrows the nearest surface point of its column
// (else of the nearest column that has one) raised or lowered to the row's height, with that
// point's normal: the flight continues the surface's stand-off straight up, down or along.

#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull_geometry.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::world {

struct StandoffSurface {
  grid::Grid<Point3> point;   ///< ship frame, metres
  grid::Grid<Normal> normal;  ///< outward unit normals
};

/// The stand-off surface of every grid position of an unrolled geometry (g.unrolled()); empty
/// grids for any other geometry.
StandoffSurface standoff_surface(const HullGeometry& g);

/// standoff_surface(g) in doubles, rounded as a trace's `ship_frame` records it (points to 0.1 mm,
/// normals to 1e-6), so that a trace's reader computes the same neighbour flights as the
/// simulator. Empty for a geometry that is not unrolled.
grid::StandoffPoints standoff_points(const HullGeometry& g);

/// The neighbour flights of a mission (docs/model.md "Neighbour flights"): on an unrolled hull from
/// its stand-off points at the planes of `params` (s1, s2, θ, cell size); empty for any other hull
/// and whenever every neighbour is one step away.
grid::FlightSteps neighbour_flights(const HullMask& hull, const MissionParams& params);

/// The seam of a hull whose grid closes on itself (geometry `seam`, at least three columns) as a
/// table of one-step flights linking every row's two ends: what connectivity asks of the grid
/// (grid::neighbour), without the flights' lengths. Empty for any other hull.
grid::EdgeSteps seam_links(const HullMask& hull);

}  // namespace hullinspect::world
