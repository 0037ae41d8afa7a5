#pragma once
// Batteries (docs/model.md, "Batteries and sorties"): endurance, reserve and swap time in steps,
// and the checks that refuse a battery no mission can fly with.

#include <span>

#include "hullinspect/world/launch_sites.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::world {

/// The battery of every UAV, in steps. `limited` false: unlimited flight (the paper's model).
struct BatterySteps {
  bool limited = false;
  int endurance = 0;  ///< steps of flight on a full battery
  int reserve = 0;    ///< steps the sortie layer keeps for landing
  int swap = 0;       ///< steps on the ground at a site to swap a battery
};

/// The battery in steps. Every conversion between the battery's seconds and steps goes through
/// battery_steps() and battery_seconds(), so that a step of another length changes only them.
BatterySteps battery_steps(const MissionParams& params);
/// Seconds of `steps` steps (MissionParams::seconds).
double battery_seconds(const MissionParams& params, int steps);

/// Steps the sortie layer keeps beyond the flight home and the reserve: one step's worst growth of
/// the flight home (a move away from the site, or a descent that must be climbed back).
int sortie_margin_steps(const MissionParams& params);

/// Throws ParameterError naming "endurance", "reserve" or "swap-time": a time that is not finite,
/// negative (or zero for the endurance), a reserve or swap time without an endurance, a reserve
/// not below the endurance, or an endurance without a launch site to swap batteries at. Call after
/// the launch sites are validated.
void validate_battery(const MissionParams& params);

/// With an endurance: check_endurance_reaches() for UAVs starting on `starts` (start_cells of the
/// mission, computed once by its caller). Call after validate_battery().
void validate_battery_reach(const MissionParams& params, const HullMask& hull,
                            std::span<const grid::Cell> starts);

/// Throws ParameterError naming "endurance" when a full battery cannot fly from a UAV's launch
/// site to the farthest flyable hull cell and back with the reserve and the margin left: the
/// message names that cell and the seconds it needs.
void check_endurance_reaches(const MissionParams& params, const HullMask& hull,
                             const Reachability& reach, const LaunchLegs& legs);

}  // namespace hullinspect::world
