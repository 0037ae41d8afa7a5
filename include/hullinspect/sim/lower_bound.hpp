#pragma once
// Analytic lower bounds on T_c and T_m for one instance (docs/model.md §11): no planner —
// not even one that knows C — can finish earlier. Two arguments, the larger wins:
//  * rate: every observed cell lies in the z = 2 square around a position some UAV visited (the
//    z = 1 footprint is inside it), and each move grows that union by at most s2 cells, so the
//    fleet needs (hull cells − n·s2²)/s2 moves; every corroded cell must also lie in some z = 1
//    footprint, which costs arrivals at z = 1 (s1² cells, u_z transit steps each, 2·u_z between two
//    of one UAV) or z = 1 moves (s1 cells each).
//  * reach: a cell is observed only from a position whose footprint holds it, and a UAV needs at
//    least the Manhattan distance to get there (+ u_z to descend for a corroded cell); on a grid
//    that closes on itself, the shorter way round across the seam.
// With a battery, the rate argument also pays for the sorties the work forces (sortie_t_m).

#include <span>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::sim {

struct LowerBound {
  int t_c = 0;       ///< T_c >= t_c
  int t_m = 0;       ///< T_m >= t_m
  int rate_t_c = 0;  ///< the rate argument alone
  int rate_t_m = 0;
  int reach_t_c = 0;  ///< the reach argument alone
  int reach_t_m = 0;
  /// What endurance adds to rate_t_m (docs/model.md, "Batteries and sorties"): the fleet needs
  /// ceil(work / (E − legs)) sorties, and each after a UAV's first pays the flight from its site
  /// to the hull and back (ground legs included) and a swap. 0 with unlimited flight.
  int sortie_t_m = 0;
};

/// Bounds for the mission of `params` on `hull` with ground truth `truth` (1 = corroded), its UAVs
/// starting at `starts` (world::start_cells of the mission, computed once by its caller).
LowerBound lower_bound(const world::HullMask& hull, const grid::Grid<std::int8_t>& truth,
                       const world::MissionParams& params, std::span<const grid::Cell> starts);
/// The same on world::start_cells(params, hull).
LowerBound lower_bound(const world::HullMask& hull, const grid::Grid<std::int8_t>& truth,
                       const world::MissionParams& params);

}  // namespace hullinspect::sim
