#include "hullinspect/sim/uav_rules.hpp"

#include <fmt/format.h>

#include "hullinspect/core/plural.hpp"
#include "hullinspect/grid/cell.hpp"

namespace hullinspect::sim {

std::optional<std::string> state_violation(const UavState& state, int plane_change_steps) {
  if (state.z != 1 && state.z != 2) return fmt::format("is on plane {} (expected 1 or 2)", state.z);
  if (state.transit_left < 0 || state.transit_left > plane_change_steps - 1) {
    return fmt::format("has {} plane-change steps left (at most {} with u_z = {})",
                       state.transit_left, plane_change_steps - 1, plane_change_steps);
  }
  return std::nullopt;
}

std::optional<std::string> step_violation(const UavState& before, const UavState& after,
                                          int plane_change_steps,
                                          const grid::FlightSteps& flights) {
  const bool same_place = before.pos == after.pos;
  const bool unchanged = same_place && before.z == after.z &&
                         before.transit_left == after.transit_left &&
                         before.flight_left == after.flight_left;
  if (before.failed && !after.failed) return std::string("came back after it failed");
  if (after.failed) {
    if (!unchanged) return std::string("moved or changed plane while failed");
    return std::nullopt;
  }
  const int moved = grid::manhattan(before.pos, after.pos);
  // Away at its launch site (on the ground, taking off, flying out or home, landing): the
  // simulator flies it along its leg, one cell a step at most, its plane following the flight.
  if (before.away_left > 0 || after.away_left > 0) {
    if (moved > 1) return fmt::format("moved {} cells in one step", moved);
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
