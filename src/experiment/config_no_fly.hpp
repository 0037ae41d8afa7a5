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

/// Reads root["no-fly"] (if present) into c.no_fly and c.no_fly_spec; the hull must be read.
void read_no_fly(const YamlFields& f, const YAML::Node& root, const std::filesystem::path& base_dir,
                 ExperimentConfig& c);

}  // namespace hullinspect::experiment::detail
