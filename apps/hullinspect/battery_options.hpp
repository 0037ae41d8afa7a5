#pragma once
// Battery options of a mission (docs/model.md, "Batteries and sorties"): --endurance, --reserve,
// --swap-time. Declared once here for the mission commands and the Python module.

#include <CLI/CLI.hpp>

#include <optional>

#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::cli {

struct BatteryArgs {
  std::optional<double> endurance;  // seconds of flight per battery; none = unlimited
  std::optional<double> reserve;    // seconds; default 10 % of the endurance
  double swap_time = world::MissionParams{}.swap_time_s;
};

void add_battery_options(CLI::App& cmd, BatteryArgs& args);
/// Copies the options into `params` (checked by world::validate).
void apply_battery_args(const BatteryArgs& args, world::MissionParams& params);

}  // namespace hullinspect::cli
