#pragma once
// The mission options of `run` and `plan` (and the mesh and no-fly options other commands share)
// on the command line. They are declared once, in the library (planners/mission_input.hpp): this
// file only registers those declarations with CLI11, so the CLI and the Python module accept the
// same values with the same messages.

#include <CLI/CLI.hpp>

#include <initializer_list>
#include <string_view>
#include <vector>

#include "hullinspect/planners/mission_input.hpp"

namespace hullinspect::cli {

using MissionArgs = planners::MissionInput;
using planners::build_no_fly;
using planners::build_spec;
using planners::import_mesh_argument;
using planners::load_hull_argument;
using planners::load_mission_hull;
using planners::parse_xy;

/// Registers `decls` on `cmd`; each value is read into `input` by its declaration as it is parsed
/// (a refused value is the parse error "--KEY: problem").
void add_declared_options(CLI::App& cmd, MissionArgs& input,
                          const std::vector<const planners::MissionOptionDecl*>& decls);
/// The declarations of `keys` ("uavs", "start"), in that order.
std::vector<const planners::MissionOptionDecl*> declarations_named(
    std::initializer_list<std::string_view> keys);
/// Every mission option, and the planners' options in the footer.
void add_mission_options(CLI::App& cmd, MissionArgs& args);
/// How a mesh given as the hull is imported (read into args.mesh).
void add_mesh_options(CLI::App& cmd, MissionArgs& args);
/// --no-fly FILE and --no-fly-box X0,Y0,X1,Y1 (repeatable), read into args.no_fly(_boxes).
void add_no_fly_options(CLI::App& cmd, MissionArgs& args);

}  // namespace hullinspect::cli
