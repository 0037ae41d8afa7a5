#pragma once
// Mission options shared by `run` and `view`-style commands: fleet, camera, instance, planner.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

#include "battery_options.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "mesh_options.hpp"

namespace hullinspect::cli {

/// Defaults are MissionParams{}'s and the scenario's declared ones (nothing retyped here).
struct MissionArgs {
  std::string algorithm = "lawnmower";
  std::string hull = "default";
  std::string scenario = "perfect";
  int uavs = world::MissionParams{}.uavs;
  int s1 = world::MissionParams{}.s1;
  int s2 = world::MissionParams{}.s2;
  double theta = world::MissionParams{}.theta_deg;
  int start_z = world::MissionParams{}.start_z;
  std::vector<std::string> starts;
  std::uint64_t seed = 1;
  std::optional<std::string> p_c, p_tp, p_fp, front_p_c, l_c, front_l_c;
  int time_limit = world::MissionParams{}.time_limit;
  int separation = world::MissionParams{}.separation;
  bool strict_separation = world::MissionParams{}.strict_separation;
  bool no_deconfliction = !world::MissionParams{}.deconflict;
  std::optional<std::string> partitioner, partition_seed, tsp_solver, r1, r2, alpha, beta;
  std::vector<std::string> planner_options;  // key=value
  std::string no_fly;                        // mask file of no-fly positions ("" = none)
  std::vector<std::string> no_fly_boxes;     // X0,Y0,X1,Y1 (cells, inclusive)
  std::vector<std::string> fail;             // UAV@STEP
  double fail_rate = 0;
  int fail_one_within = 0;
  MeshArgs mesh;                             // how a mesh --hull is imported
  std::string prior, truth;                  // the user's C′ and C (any hull-mask format)
  std::string prior_defects, truth_defects;  // the same from defects in ship coordinates
  std::optional<double> frame_spacing;       // metres between frames, for defects given by frame
  std::vector<std::string> launch;           // X,Y launch sites (none = the paper's model)
  double launch_transfer = world::MissionParams{}.launch_transfer_s;
  std::optional<double> takeoff_time;  // seconds; default u_z
  BatteryArgs battery;                 // --endurance, --reserve, --swap-time
};

/// Adds --no-fly FILE and --no-fly-box X0,Y0,X1,Y1 (repeatable) to a command.
void add_no_fly_options(CLI::App& cmd, std::string& file, std::vector<std::string>& boxes);
/// The no-fly mask the options describe for `hull`, or null when they name none.
std::shared_ptr<const grid::Grid<std::uint8_t>> build_no_fly(const std::string& file,
                                                             const std::vector<std::string>& boxes,
                                                             const world::HullMask& hull);

void add_mission_options(CLI::App& cmd, MissionArgs& args);
world::HullMask load_mission_hull(const MissionArgs& args);
/// Turns the arguments into a spec; throws ParameterError naming the option.
planners::MissionSpec build_spec(const MissionArgs& args, const world::HullMask& hull);

}  // namespace hullinspect::cli
