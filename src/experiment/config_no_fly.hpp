#pragma once
// The `no-fly` key of experiment configs (docs/model.md, "No-fly zones"):
//   no-fly: {file: MASK, boxes-m: [[x0, y0, x1, y1], …]}
// boxes in metres along the grid (x from the stern end, y from the bottom), converted to the cells
// they touch with the config's cell size.

#include <yaml-cpp/yaml.h>

#include <filesystem>

#include "hullinspect/experiment/config.hpp"
#include "yaml_fields.hpp"

namespace hullinspect::experiment::detail {

/// A `no-fly` map read: the mask and the spec written to the manifest (file, boxes, mask hash).
struct NoFlyZones {
  std::shared_ptr<const grid::Grid<std::uint8_t>> mask;
  nlohmann::json spec;
};

/// Reads the `no-fly` map `node`, named `key` in messages, on c's hull and cell size.
NoFlyZones read_no_fly_zones(const YamlFields& f, const YAML::Node& node, const std::string& key,
                             const std::filesystem::path& base_dir, const ExperimentConfig& c);

/// Reads root["no-fly"] (if present) into c.no_fly and c.no_fly_spec; the hull must be read.
void read_no_fly(const YamlFields& f, const YAML::Node& root, const std::filesystem::path& base_dir,
                 ExperimentConfig& c);

/// Reads the `no-fly` key of each plain scenario in `scenarios` (the config's list, already
/// parsed into c.scenarios, one spec per item in order) into that scenario. A scenario's zones
/// cannot be combined with top-level ones.
void read_scenario_no_fly(const YamlFields& f, const YAML::Node& scenarios,
                          const std::filesystem::path& base_dir, ExperimentConfig& c);

}  // namespace hullinspect::experiment::detail
