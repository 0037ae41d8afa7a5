#pragma once
// Sweep-Inspect's own battery returns (docs/sweep-inspect.md, "Planned returns"): where along the
// route still ahead of a UAV its sortie should end. The sortie layer would send the UAV home
// wherever its battery runs down (often at the far end of a band); ending the sortie a little
// earlier, or a little later, at a point nearer its launch site saves the flight home and back
// out, at the price of the battery left unused.

#include <span>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/sim/return_rule.hpp"

namespace hullinspect::planners {

/// A UAV on a battery and the route it is to fly (its waypoints still ahead, in order).
struct SortieRoute {
  int uav = 0;
  grid::Cell pos;
  int z = 2;
  int battery_left = 0;
  std::span<const grid::Cell> waypoints;
};

/// The cost of ending a sortie at a point of the route: the flight home and back out from there
/// (twice the flight home), plus `waste_weight` per step of battery left unused beyond what the
/// sortie layer keeps (ReturnRule::battery_needed). The weight is what a step of battery is worth
/// in swaps: a sortie's round trip and swap shared over the work steps of a battery,
/// (round trip + swap) / (endurance − reserve − margin − round trip), with the round trip
/// measured from the UAV's position.
double unused_battery_weight(const SortieRoute& route, const sim::ReturnRule& rule);

/// True when ending the sortie now costs less than ending it at any later point of the route
/// the battery reaches before the sortie layer would act there; false as well when the battery
/// lasts to the route's end (the route can be finished on this battery), when the battery is
/// not limited, or while the unused battery exceeds a third of the endurance (so the walk along
/// the route is done only near a sortie's end). Walks the route by `flights`' shortest flights.
bool end_sortie_now(const SortieRoute& route, const sim::ReturnRule& rule,
                    grid::DistanceService& flights);

/// False when end_sortie_now() is false whatever the route: the battery is not limited, or its
/// unused part exceeds a third of the endurance. Lets a caller skip building the route.
bool near_sortie_end(const SortieRoute& route, const sim::ReturnRule& rule);

}  // namespace hullinspect::planners
