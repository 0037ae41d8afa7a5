#pragma once
// The mission front door: a mission as its user states it — the options of `hullinspect run` and
// `plan`, the keywords of the Python module — declared once here (name, value type, default, help,
// parser). The CLI registers its options from these declarations and Python fills a MissionInput
// through them, so both accept the same values with the same one-line messages; build_spec turns
// the input into the MissionSpec that run_mission runs.
//
// Adding a mission option is one entry in mission_option_declarations() (mission_input.cpp) plus
// its field in MissionInput and the line of set_mission_params (or build_spec) that carries it
// into the spec; with a config_key, experiment configs read it too.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::planners {

/// How a mesh given as the hull is imported; unset fields keep the importer's defaults (or a named
/// mesh hull's own).
struct MeshInput {
  std::optional<std::string> side;
  std::optional<double> cell_size;
  std::optional<double> scale;
  std::optional<std::string> axes;
  std::optional<double> waterline;
  std::optional<double> min_coverage;
  bool keep_largest = false;
  std::vector<std::string> include;  ///< transom (bottom is refused)
  std::optional<double> max_area_error;
};

/// One mission's inputs as text-level values. Defaults are MissionSpec{}'s and MissionParams{}'s
/// (nothing retyped here); the scenario's own parameters default to the scenario's declarations.
struct MissionInput {
  std::string algorithm = MissionSpec{}.algorithm;
  std::string hull = "default";
  std::string scenario = "perfect";
  int uavs = world::MissionParams{}.uavs;
  int s1 = world::MissionParams{}.s1;
  int s2 = world::MissionParams{}.s2;
  double theta = world::MissionParams{}.theta_deg;
  int start_z = world::MissionParams{}.start_z;
  std::vector<std::string> starts;  ///< X,Y per UAV
  std::uint64_t seed = MissionSpec{}.seed;
  std::optional<std::string> p_c, p_tp, p_fp, front_p_c, l_c, front_l_c;
  int time_limit = world::MissionParams{}.time_limit;
  int separation = world::MissionParams{}.separation;
  bool strict_separation = world::MissionParams{}.strict_separation;
  bool no_deconfliction = !world::MissionParams{}.deconflict;
  std::optional<std::string> partitioner, partition_seed, tsp_solver, r1, r2, alpha, beta;
  std::vector<std::string> planner_options;  ///< KEY=VALUE
  std::string no_fly;                        ///< mask file of no-fly positions ("" = none)
  std::vector<std::string> no_fly_boxes;     ///< X0,Y0,X1,Y1 (cells, inclusive)
  std::vector<std::string> fail;             ///< UAV@STEP
  double fail_rate = 0;
  int fail_one_within = 0;
  MeshInput mesh;
  std::string prior, truth;                  ///< the user's C′ and C (any hull-mask format)
  std::string prior_defects, truth_defects;  ///< the same from defects in ship coordinates
  std::optional<double> frame_spacing;       ///< metres between frames, for defects by frame
  std::vector<std::string> launch;           ///< X,Y launch sites (none = the paper's model)
  double launch_transfer = world::MissionParams{}.launch_transfer_s;
  std::optional<double> takeoff_time;  ///< seconds; default u_z
  std::optional<double> endurance;     ///< seconds of flight per battery; none = unlimited
  std::optional<double> reserve;       ///< seconds; default 10 % of the endurance
  double swap_time = world::MissionParams{}.swap_time_s;
  std::optional<double> speed;        ///< m/s; empty = one cell per second (the paper's)
  std::optional<double> climb_speed;  ///< m/s; empty = the paper's plane change
};

/// How an option takes its value.
enum class InputKind {
  kFlag,      ///< no value: given = "true"
  kValue,     ///< one value
  kRepeated,  ///< one value per occurrence (a list in Python)
};

/// One declared mission option.
struct MissionOptionDecl {
  std::string key;         ///< "uavs": --uavs on the command line; Python's keyword with '_'
  std::string alias;       ///< a one-letter command-line alias ("n" for -n), or ""
  std::string also;        ///< another long spelling ("sides" for --side), or ""
  std::string value_name;  ///< INT, UINT, FLOAT, X,Y, FILE, … (as --help shows it)
  InputKind kind = InputKind::kValue;
  std::string help;
  std::string group;     ///< the --help group, "" for the command's own options
  std::string excludes;  ///< the key of an option this one cannot be given with, or ""
  char delimiter = 0;    ///< a repeated option's value is also split at it ("transom,bottom")
  /// Reads one value into the input; throws ParameterError(key, …) with the shared parser's
  /// message ("must be an integer in [a, b] (got 'x')").
  std::function<void(MissionInput&, const std::string&)> set;
  /// The default as --help shows it, or "" for none.
  std::string shown_default;
  /// Its key in experiment configs ("start_z", "battery.endurance": a key of the `battery:` map),
  /// or "" when a config does not set it this way (docs/experiments.md).
  std::string config_key;
  /// In a config, a list of values: one axis of the experiment's grid (s2, uavs).
  bool config_axis = false;
};

/// Every mission option, in --help order. The mesh options (group "Mesh hulls …") are also those
/// of `hull import` (mesh_option_declarations()).
const std::vector<MissionOptionDecl>& mission_option_declarations();
/// The mesh-import options alone, reading into a MeshInput's fields of a MissionInput.
std::vector<const MissionOptionDecl*> mesh_option_declarations();
/// The declaration of `key` ("uavs", "start"), or null.
const MissionOptionDecl* find_mission_option(std::string_view key);
/// Reads `text` as the value of option `key`; throws ParameterError(key, …) (also for an unknown
/// key, naming the known ones).
void set_mission_option(MissionInput& input, std::string_view key, const std::string& text);

/// Parses "X,Y" (a --start value) exactly: two integers in the int range, nothing else.
/// Throws ParameterError(option, …).
grid::Cell parse_xy(const std::string& text, const std::string& option = "start");

/// `base` with the mesh options given; throws ParameterError naming the option.
world::MeshImportOptions mesh_import_options(const MeshInput& mesh,
                                             world::MeshImportOptions base = {});
/// Imports a mesh file or a named mesh hull with the options given; prints warnings to stderr.
world::MeshImport import_mesh_argument(const std::string& mesh, const MeshInput& options);
/// Loads a hull argument: a mesh or named mesh hull (import_mesh_argument), else anything
/// world::load_hull reads.
world::HullMask load_hull_argument(const std::string& hull, const MeshInput& mesh);
/// The mission's hull (load_hull_argument of input.hull).
world::HullMask load_mission_hull(const MissionInput& input);

/// The no-fly mask a file and boxes describe for `hull`, or null when they name none.
std::shared_ptr<const grid::Grid<std::uint8_t>> build_no_fly(const std::string& file,
                                                             const std::vector<std::string>& boxes,
                                                             const world::HullMask& hull);

/// The corrosion statistics of scenario `name` with its parameters overridden by `options`
/// ("p-c" → "0.01") on a hull `width` cells long; a refused parameter is ParameterError naming
/// the mission option ("p-c"), not the scenario's own key ("perfect.p-c").
world::CorrosionParams scenario_corrosion(const std::string& name, const OptionMap& options,
                                          int width);

/// Writes the parameters of `input` that need no hull — fleet, footprints, camera, start plane,
/// time limit, separation, launch times, battery and speeds — into `params` (build_spec's, and an
/// experiment's for each of its missions).
void set_mission_params(const MissionInput& input, world::MissionParams& params);

/// Turns the input into a spec for `hull`; throws ParameterError naming the option.
MissionSpec build_spec(const MissionInput& input, const world::HullMask& hull);

}  // namespace hullinspect::planners
