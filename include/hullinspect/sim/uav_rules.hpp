#pragma once
// The rules of UAV motion (docs/model.md), in one place for everything that checks a flown mission:
// the trace reader applies them to every frame of a trace, and the tests' mission checker to every
// step of a simulated mission. The simulator enforces them by construction; these functions say
// whether a recorded sequence of states could have come from it.

#include <optional>
#include <string>

#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/sim/types.hpp"

namespace hullinspect::sim {

/// A state's own rules with u_z = `plane_change_steps` (≥ 1): z ∈ {1, 2}, transit_left in
/// [0, u_z − 1]. nullopt when they hold, else the broken rule, e.g. "has 99 plane-change steps
/// left (at most 2 with u_z = 3)".
std::optional<std::string> state_violation(const UavState& state, int plane_change_steps);

/// Whether `after` can follow `before` in one step: a failed UAV stays failed and does not move or
/// change plane; a UAV failing this step stays as it was; a UAV changing plane stays put, counts
/// down and arrives on the other plane when the count reaches 0; a UAV still flying to a distant
/// neighbour stays put and counts its flight down; otherwise it hovers, moves one cell on its
/// plane (with flight_left one less than that flight's steps in `flights`), or starts a plane
/// change. Batteries: a step airborne at its start or end uses one step of battery, one on the
/// ground none (a swap refills it); only a UAV away at its launch site takes off or lands, on the
/// ground it does not move, and airborne with an empty battery it fails in the next step. nullopt
/// when allowed, else the broken rule.
std::optional<std::string> step_violation(const UavState& before, const UavState& after,
                                          int plane_change_steps,
                                          const grid::FlightSteps& flights = {});

/// Footprint sides: s1 and s2 odd, 1 ≤ s1 < s2. nullopt when they hold.
std::optional<std::string> footprint_violation(long long s1, long long s2);

}  // namespace hullinspect::sim
