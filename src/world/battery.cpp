#include "hullinspect/world/battery.hpp"

#include <fmt/format.h>

#include <cmath>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::world {

namespace {

// Far beyond any mission, and far from overflow in steps.
constexpr double kMaxSeconds = 1e7;

void check_seconds(const char* name, double seconds, bool zero_allowed) {
  if (!std::isfinite(seconds) || seconds < 0.0 || (!zero_allowed && seconds == 0.0) ||
      seconds > kMaxSeconds) {
    throw ParameterError(name, fmt::format("must be a number of seconds in {}0, {}] (got {})",
                                           zero_allowed ? "[" : "(", kMaxSeconds, seconds));
  }
}

}  // namespace

BatterySteps battery_steps(const MissionParams& p) {
  BatterySteps b;
  if (!p.endurance_s) return b;
  b.limited = true;
  // A step lasts p.step_seconds(). The endurance rounds down (a battery never flies longer than
  // it is rated), the reserve and the swap round up.
  b.endurance = static_cast<int>(std::floor(*p.endurance_s / p.step_seconds() + 1e-9));
  b.reserve = p.steps_for_seconds(p.reserve_s ? *p.reserve_s : 0.1 * *p.endurance_s);
  b.swap = p.steps_for_seconds(p.swap_time_s);
  return b;
}

double battery_seconds(const MissionParams& params, int steps) {
  return params.seconds(steps);
}

int sortie_margin_steps(const MissionParams& p) {
  return 2 * p.plane_change_steps() + 1;
}

void validate_battery(const MissionParams& p, const HullMask& hull) {
  check_seconds("swap-time", p.swap_time_s, true);
  if (p.reserve_s) check_seconds("reserve", *p.reserve_s, true);
  if (!p.endurance_s) {
    if (p.reserve_s) throw ParameterError("reserve", "needs an endurance (--endurance)");
    if (p.swap_time_s != MissionParams{}.swap_time_s)
      throw ParameterError("swap-time", "needs an endurance (--endurance)");
    return;
  }
  check_seconds("endurance", *p.endurance_s, false);
  if (p.reserve_s && *p.reserve_s >= *p.endurance_s) {
    throw ParameterError("reserve", fmt::format("must be below the endurance of {} s (got {} s)",
                                                *p.endurance_s, *p.reserve_s));
  }
  if (p.launch_sites.empty()) {
    throw ParameterError("endurance",
                         "needs a launch site (--launch) where the UAVs land to swap batteries");
  }
  const auto starts = start_cells(p, hull);
  const auto reach = compute_reachability(hull, p.no_fly.get(), p.s1, p.s2, starts);
  check_endurance_reaches(p, hull, reach, plan_launch_legs(p, hull, reach, starts));
}

void check_endurance_reaches(const MissionParams& p, const HullMask& hull,
                             const Reachability& reach, const LaunchLegs& legs) {
  const BatterySteps b = battery_steps(p);
  if (!b.limited || legs.empty()) return;
  // The ground legs (take-off or landing, transfer) and a plane change are flown both ways too.
  const int ground = legs.takeoff_steps + legs.transfer_steps + legs.plane_change_steps;
  int worst = -1;
  grid::Cell cell{};
  int site = 0;
  std::vector<std::uint8_t> used(legs.sites.size(), 0);
  for (const int s : legs.site_of) used[static_cast<std::size_t>(s)] = 1;
  for (int i : hull.cells()) {
    if (reach.flyable[i] == 0) continue;
    for (std::size_t s = 0; s < legs.sites.size(); ++s) {
      if (used[s] == 0) continue;
      const int d = legs.flight_home[s][i];
      if (d >= grid::kUnreachable || d <= worst) continue;
      worst = d;
      cell = hull.mask().cell(i);
      site = static_cast<int>(s);
    }
  }
  if (worst < 0) return;
  // Out and back, the reserve, the layer's margin, and one step of work at the cell.
  const int need = 2 * (worst + ground) + b.reserve + sortie_margin_steps(p) + 1;
  if (b.endurance >= need) return;
  const grid::Cell s = legs.sites[static_cast<std::size_t>(site)];
  throw ParameterError(
      "endurance",
      fmt::format("{} s cannot reach the farthest hull cell ({}, {}) from launch site ({}, {}) "
                  "and come back: that needs at least {} s (the flight both ways down to plane 1, "
                  "a reserve of "
                  "{} s and a margin of {} s)",
                  battery_seconds(p, b.endurance), cell.x, cell.y, s.x, s.y,
                  battery_seconds(p, need), battery_seconds(p, b.reserve),
                  battery_seconds(p, sortie_margin_steps(p) + 1)));
}

}  // namespace hullinspect::world
