#pragma once
// Fewer waypoints for the same coverage (docs/export.md "Simplification"): consecutive straight
// moves whose intermediate waypoints lie within a tolerance of the straight line between the
// first and the last become one leg — on a curved hull, the stair-steps of legs that end at every
// change of depth. Holds, plane changes and the first and last waypoints are kept. A simplified
// path is accepted only if it keeps coverage: every cell a footprint along the original path
// contains is contained in a footprint along the simplified one.

#include <optional>
#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/io/sorties.hpp"

namespace hullinspect::io {

struct ExportPlan;

/// The waypoints with every removable waypoint within `tolerance_m` of its merged leg removed
/// (greedy: each leg is extended while all the waypoints it skips stay within the tolerance).
std::vector<ExportWaypoint> simplify_waypoints(const ExportPlan& plan,
                                               std::span<const ExportWaypoint> waypoints,
                                               double tolerance_m);

/// The cells a camera sees flying straight legs between the waypoints: at points a quarter cell
/// apart (and every waypoint), the cells whose centres lie within the footprint's half-width less
/// half a cell of the camera's axis along the hull and in height, the half-width being the
/// distance from the surface times tan(θ/2). At the cell centres of a planned path this is the
/// model's s_z × s_z footprint. Marks result[y][x]; cells outside the grid are ignored.
void mark_seen(const ExportPlan& plan, std::span<const ExportWaypoint> waypoints,
               std::vector<std::vector<char>>& seen);

/// The first cell (in row-major order) that `original` sees and `simplified` does not, if any.
std::optional<grid::Cell> first_cell_lost(const ExportPlan& plan,
                                          std::span<const ExportWaypoint> original,
                                          std::span<const ExportWaypoint> simplified);

/// Simplifies a sortie's flight to the plan, the plan and the flight back separately (so photos
/// still start and stop where the plan does). Throws ParameterError("simplify") naming the first
/// cell the plan's part would no longer see.
void simplify_sortie(const ExportPlan& plan, Sortie& sortie, double tolerance_m);

}  // namespace hullinspect::io
