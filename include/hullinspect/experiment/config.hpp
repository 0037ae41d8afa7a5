#pragma once
// Experiment configs (docs/experiments.md): a YAML file naming the hull, the corrosion scenarios
// and sweeps, the parameter lists (s2, fleet sizes), the algorithms with their options, the
// instances and the curve time grid. Every list is one axis of a cartesian product.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/core/options.hpp"
#include "hullinspect/planners/mission_input.hpp"
#include "hullinspect/world/failures.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/user_maps.hpp"

namespace hullinspect::experiment {

/// One corrosion scenario: a built-in one (model.md §6), a custom one, or one point of a sweep.
struct ScenarioSpec {
  std::string name;
  std::string sweep;        ///< the sweep it belongs to; empty for plain scenarios
  std::string sweep_value;  ///< the swept value as text ("0.8", "0.01/0.0025" for front/back)
  world::CorrosionParams corrosion;
  world::FailurePlan failures;  ///< UAV failures of every mission of the scenario (paired by seed)
  int line = 0;                 ///< config line that declared it (for error messages)
  /// The scenario's own no-fly zones (its `no-fly:` key; null = the config's, if any) and their
  /// spec as written to the manifest.
  std::shared_ptr<const grid::Grid<std::uint8_t>> no_fly;
  nlohmann::json no_fly_spec;
};

/// One entry of the algorithm list.
struct AlgorithmSpec {
  std::string label;    ///< its name in result tables (default: the planner name)
  std::string planner;  ///< planner registry name
  OptionMap options;    ///< planner options, validated by the planner registry
  int line = 0;
};

/// The times at which c(t) and m(t) are sampled for curves: 0, step, 2·step, … ≤ end.
struct CurveGrid {
  int step = 5;
  int end = 1500;
  std::vector<int> times() const;
};

struct ExperimentConfig {
  std::string source;  ///< names the config in messages: a path or "presets/<name>.yaml"
  std::string name;
  std::string description;
  /// As written: "default", "rectangle", "dtc", a mask/hull JSON/mesh path, or for a `hull: {mesh:
  /// …}` map "mesh:FILE" followed by its options.
  std::string hull_spec = "default";
  std::shared_ptr<const world::HullMask> hull;  ///< null in a config read back from a manifest
  std::string hull_hash;                        ///< stable id of the mask's contents
  int hull_width = 0;
  int hull_height = 0;
  int hull_cells = 0;
  double cell_size = world::MissionParams{}.cell_size_m;
  /// No-fly positions (null = none) and how the config stated them ({file, boxes-m, hash}).
  std::shared_ptr<const grid::Grid<std::uint8_t>> no_fly;
  nlohmann::json no_fly_spec;
  /// The user's C′ and C ("prior:", "truth:") as the config names them (relative to its
  /// directory).
  std::string prior_path, truth_path;
  /// The same as defects in ship coordinates ("prior-defects:", "truth-defects:"), as the config
  /// names them, and the frame spacing for defects placed by frame ("frame-spacing:").
  std::string prior_defects_path, truth_defects_path;
  /// Stable ids of the loaded C′ and C (from a mask or defects; empty without), so that the
  /// fingerprint follows the files' contents.
  std::string prior_hash, truth_hash;
  world::UserMaps maps;                 ///< loaded from them; empty in a config read back
  std::vector<ScenarioSpec> scenarios;  ///< plain scenarios, then every sweep's points
  /// The mission options the config sets (s1, theta, start_z, time_limit, separation, the launch
  /// times, the battery, the speeds, the frame spacing), read through their declarations
  /// (planners/mission_input.hpp), with the same defaults as on the command line. Its uavs and s2
  /// are unused: those are the axes below.
  planners::MissionInput mission;
  std::vector<int> s2 = {world::MissionParams{}.s2};
  std::vector<int> uavs = {world::MissionParams{}.uavs};
  std::vector<AlgorithmSpec> algorithms;
  std::vector<std::uint64_t> seeds;
  /// Launch sites ("launch:", docs/model.md); empty = the paper's model.
  std::vector<grid::Cell> launch_sites;
  CurveGrid curve;
  /// Config line of each key and list item ("s1", "s2[1]", "uavs[0]", "battery.endurance"), so
  /// that an error found later (when cells are validated) can still name its line. 0 = not in the
  /// file.
  std::map<std::string, int> lines;

  int line_of(const std::string& key) const;
  /// The parameters that convert this experiment's steps to seconds (cell size and speeds).
  world::MissionParams timing() const;
};

/// Parses a config. `source` names it in errors ("FILE:LINE: key: problem"); a relative hull path
/// is resolved against `base_dir`. Throws InputError for syntax errors, unknown keys, wrong types
/// and out-of-range values.
ExperimentConfig parse_config(std::string_view yaml, const std::string& source,
                              const std::filesystem::path& base_dir);

/// Reads and parses a config file.
ExperimentConfig load_config(const std::filesystem::path& path);

/// Keeps only the algorithms whose labels are listed (in config order). Throws ParameterError
/// ("algorithms") for a label the config does not have.
void restrict_algorithms(ExperimentConfig& config, const std::vector<std::string>& labels);

/// Replaces the seeds by 1..count (ParameterError "instances" unless count >= 1).
void set_instance_count(ExperimentConfig& config, int count);

/// Replaces the seeds by as many consecutive ones from `first` (first, first + 1, ...): seeds
/// held out from the ones a config was tuned on, with the same count. ParameterError
/// ("first-seed") when the last would pass 2^64 - 1.
void set_first_seed(ExperimentConfig& config, std::uint64_t first);

/// The fully resolved config (defaults filled in, scenarios as zones, every seed), as recorded in
/// manifest.json.
nlohmann::json config_json(const ExperimentConfig& config);

/// Reads back what config_json wrote (for merging shards). The hull mask itself is not stored:
/// `hull` is null, so such a config can be expanded into runs but not run. Throws InputError
/// naming `source` when the JSON does not have the expected shape.
ExperimentConfig config_from_json(const nlohmann::json& json, const std::string& source);

/// Stable id of the resolved config: equal ids mean the same experiment (resume, merge).
std::string config_fingerprint(const ExperimentConfig& config);

}  // namespace hullinspect::experiment
