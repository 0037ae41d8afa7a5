#pragma once
// The `scenarios` and `sweeps` sections of a config, resolved into corrosion parameters.

#include <yaml-cpp/yaml.h>

#include <vector>

#include "hullinspect/experiment/config.hpp"
#include "yaml_fields.hpp"

namespace hullinspect::experiment::detail {

/// Plain scenarios in order, then each sweep's points in order. Either node may be undefined; with
/// neither, the result is the built-in "perfect" scenario. `grid_width` places the front/back split.
std::vector<ScenarioSpec> parse_scenarios(const YamlFields& fields, const YAML::Node& scenarios,
                                          const YAML::Node& sweeps, int grid_width);

}  // namespace hullinspect::experiment::detail
