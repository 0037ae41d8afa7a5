#include "hullinspect/sim/uav_rules.hpp"

#include <fmt/format.h>

#include "hullinspect/core/plural.hpp"
#include "hullinspect/grid/cell.hpp"

namespace hullinspect::sim {

std::optional<std::string> state_violation(const UavState& state, int plane_change_steps) {
  if (state.z != 1 && state.z != 2) return fmt::format("is on plane {} (expected 1 or 2)", state.z);
  if (state.battery_left < -1) return fmt::format("has {} battery steps left", state.battery_left);
  if (!state.airborne && state.transit_left != 0)
    return std::string("is changing plane on the ground");
  if (state.transit_left < 0 || state.transit_left > plane_change_steps - 1) {
    return fmt::format("has {} plane-change steps left (at most {} with u_z = {})",
                       state.transit_left, plane_change_steps - 1, plane_change_steps);
  }
  return std::nullopt;
}

namespace {

// Batteries and the ground (docs/model.md, "Batteries and sorties"): a step flown (or taken off or
// landed in) uses one step of battery, a step on the ground none unless it swaps the battery; only
// a UAV away at its site takes off or lands, and on the ground it stays where it is; airborne with
// an empty battery it crashes (fails) in the next step.
std::optional<std::string> battery_violation(const UavState& before, const UavState& after) {
  if (before.failed) return std::nullopt;
  if (before.airborne && before.battery_left == 0 && !after.failed)
    return std::string("flew on with an empty battery instead of crashing");
  if (after.failed) return std::nullopt;
  const bool away = before.away_left > 0 || after.away_left > 0;
  if (before.airborne != after.airborne && !away) {
    return fmt::format("{} away from a launch site", after.airborne ? "took off" : "landed");
  }
  if (!before.airborne && !after.airborne && before.pos != after.pos)
    return std::string("moved while on the ground");
  if ((before.battery_left < 0) != (after.battery_left < 0))
    return std::string("changed between a limited and an unlimited battery");
  if (before.battery_left < 0) return std::nullopt;
  const bool flew = before.airborne || after.airborne;
  if (flew && after.battery_left != before.battery_left - 1) {
    return fmt::format("flew a step and its battery went from {} to {} steps", before.battery_left,
                       after.battery_left);
  }
  if (!flew && after.battery_left < before.battery_left) {
    return fmt::format("used battery on the ground ({} to {} steps)", before.battery_left,
                       after.battery_left);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> step_violation(const UavState& before, const UavState& after,
                                          int plane_change_steps,
                                          const grid::FlightSteps& flights) {
  if (auto broken = battery_violation(before, after)) return broken;
  const bool same_place = before.pos == after.pos;
  const bool unchanged = same_place && before.z == after.z &&
                         before.transit_left == after.transit_left &&
                         before.flight_left == after.flight_left;
  if (before.failed && !after.failed) return std::string("came back after it failed");
  if (after.failed) {
    if (!unchanged) return std::string("moved or changed plane while failed");
    return std::nullopt;
  }
  // Cells apart: a move across the seam (grid::adjacent) is one.
  const int moved = grid::adjacent(before.pos, after.pos, flights.plane[0])
                        ? 1
                        : grid::manhattan(before.pos, after.pos);
  // Away at its launch site (on the ground, taking off, flying out or home, landing): the
  // simulator flies it along its leg, one cell a step at most, its plane following the flight.
  if (before.away_left > 0 || after.away_left > 0) {
    if (moved > 1) return fmt::format("moved {} cells in one step", moved);
    // A climb or descent happens at the cell where the UAV is, as on the hull.
    if (moved == 1 && before.airborne && after.airborne && after.z != before.z) {
      return fmt::format("moved from ({}, {}) on plane {} to ({}, {}) on plane {} in one step",
                         before.pos.x, before.pos.y, before.z, after.pos.x, after.pos.y, after.z);
    }
    return std::nullopt;
  }
  if (before.flight_left > 0) {
    if (moved != 0 || after.z != before.z || after.transit_left != 0) {
      return fmt::format("moved or changed plane with {} flight steps left", before.flight_left);
    }
    if (after.flight_left != before.flight_left - 1) {
      return fmt::format("went from {} flight steps left to {}", before.flight_left,
                         after.flight_left);
    }
    return std::nullopt;
  }
  if (after.flight_left > 0 && moved != 1) {
    return fmt::format("has {} flight steps left without moving", after.flight_left);
  }
  if (before.in_transit()) {
    if (moved != 0) return std::string("moved while changing plane");
    const bool arrives = before.transit_left == 1;
    if (after.transit_left != before.transit_left - 1 || (after.z != before.z) != arrives) {
      return fmt::format("went from plane {} with {} change steps left to plane {} with {}",
                         before.z, before.transit_left, after.z, after.transit_left);
    }
    return std::nullopt;
  }
  if (moved > 1) return fmt::format("moved {} cells in one step", moved);
  if (moved == 1) {
    if (after.z != before.z || after.transit_left != 0) {
      return std::string("moved and changed plane in one step");
    }
    const int steps = flights.between(before.pos, after.pos, before.z);
    if (after.flight_left != steps - 1) {
      return fmt::format(
          "moved from ({}, {}) to ({}, {}), a flight of {} on plane {}, with {} "
          "flight steps left",
          before.pos.x, before.pos.y, after.pos.x, after.pos.y, plural(steps, "step"), before.z,
          after.flight_left);
    }
    return std::nullopt;
  }
  // Hover, or the first step of a plane change (which lands at once when u_z = 1).
  const bool hover = after.z == before.z && after.transit_left == 0;
  const bool change = plane_change_steps == 1
                          ? after.z == 3 - before.z && after.transit_left == 0
                          : after.z == before.z && after.transit_left == plane_change_steps - 1;
  if (!hover && !change) {
    return fmt::format("went from plane {} to plane {} with {} change steps left in one step",
                       before.z, after.z, after.transit_left);
  }
  return std::nullopt;
}

std::optional<std::string> footprint_violation(long long s1, long long s2) {
  if (s1 < 1 || s1 % 2 == 0) return fmt::format("s1 = {} is not a positive odd integer", s1);
  if (s2 <= s1 || s2 % 2 == 0) {
    return fmt::format("s2 = {} is not an odd integer greater than s1 = {}", s2, s1);
  }
  return std::nullopt;
}

}  // namespace hullinspect::sim
