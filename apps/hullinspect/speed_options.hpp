#pragma once
// --speed and --climb-speed (docs/model.md, "Speed and time"): how long a step lasts and how many
// steps a plane change takes. A step stays one move; every time the user sees is in seconds.

#include <CLI/CLI.hpp>

#include <optional>

#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::cli {

struct SpeedArgs {
  std::optional<double> speed;        ///< m/s; empty = one cell per second (the paper's)
  std::optional<double> climb_speed;  ///< m/s; empty = the paper's plane change
};

/// Adds --speed M/S and --climb-speed M/S to a command.
void add_speed_options(CLI::App& cmd, SpeedArgs& args);

/// Copies the speeds into the mission's parameters (validate() checks them).
void apply_speed_options(const SpeedArgs& args, world::MissionParams& params);

}  // namespace hullinspect::cli
