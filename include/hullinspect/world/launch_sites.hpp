#pragma once
// Launch sites (docs/model.md, "Launch sites"): where the UAVs take off and land, which site each
// UAV uses, and the steps of its flight out to its start cell and home again.

#include <functional>
#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::world {

/// The one rule for a launch site on a width × height grid, the mission's and the exports': throws
/// ParameterError naming "launch" when `c` is outside the grid, a no-fly position, or a hull cell
/// off the grid's edge. The predicates are asked about cells on the grid only.
void check_launch_site(grid::Cell c, int width, int height,
                       const std::function<bool(grid::Cell)>& is_hull,
                       const std::function<bool(grid::Cell)>& is_no_fly);

/// Throws ParameterError naming "launch", "launch-transfer" or "takeoff-time": a site outside the
/// grid, on a no-fly position or on a hull cell inside the grid (a site is a non-hull cell or a
/// cell on the grid's edge), or a time that is negative, not finite or beyond the time limit.
void validate_launch_sites(const MissionParams& params, const HullMask& hull);

/// The legs of every UAV's flight between its launch site and the hull. Empty (no sites) in the
/// paper's model.
struct LaunchLegs {
  std::vector<grid::Cell> sites;
  std::vector<int> site_of;   ///< per UAV: index of its launch site
  std::vector<int> outbound;  ///< per UAV: steps from t = 0 until it is at its start cell, airborne
  int takeoff_steps = 0;      ///< ground to plane 2 at the site's cell (and back down)
  int transfer_steps = 0;     ///< the quay or deck beyond the grid, each way
  int plane_change_steps = 1;
  std::vector<grid::Grid<int>> flight_home;  ///< per site: flight steps from each position to it
  /// The neighbour flights of plane 2, where the legs are flown (empty: one step each).
  grid::EdgeSteps flights;

  bool empty() const { return sites.empty(); }
  /// Steps from `u`'s position and plane until it has landed at its site and been carried off the
  /// grid: climb to plane 2 (finishing a plane change first), fly home, descend, transfer.
  int homeward_steps(int uav, grid::Cell pos, int z, int transit_left) const;
  /// The positions of `uav`'s shortest flight from `from` to its site, one per step (`from`
  /// excluded, the site included; neighbours tried west, east, south, north). A neighbour flight
  /// of k steps is its position k times: the UAV is there at once and in transit for the rest, as
  /// on the hull (docs/model.md "Neighbour flights").
  std::vector<grid::Cell> path_home(int uav, grid::Cell from) const;
};

/// Assigns each UAV the launch site nearest in flight to its start cell (ties: the site given
/// first) and times its outbound leg: transfer, take-off, the flight to its start cell on plane 2,
/// and the descent when the mission starts on plane 1. Flights between neighbours take their
/// steps in `flights` (plane 2's of world::neighbour_flights: an unrolled hull's stand-off
/// lengths; empty: one step each). Throws ParameterError naming "launch" when a site cannot reach
/// the hull in flight (no-fly zones cut it off).
LaunchLegs plan_launch_legs(const MissionParams& params, const Reachability& reach,
                            std::span<const grid::Cell> starts,
                            const grid::EdgeSteps& flights = {});
/// plan_launch_legs with the flights of `hull`'s plane 2 (world::neighbour_flights): what the
/// simulator flies, for the lower bound and the battery checks.
LaunchLegs plan_launch_legs(const MissionParams& params, const HullMask& hull,
                            const Reachability& reach, std::span<const grid::Cell> starts);

}  // namespace hullinspect::world
