#pragma once
// The `speed` and `climb-speed` keys of experiment configs (docs/model.md, "Speed and time"):
//   speed: M/S          horizontal; a step lasts cell / speed seconds
//   climb-speed: M/S    plane changes and take-off
// the same as --speed and --climb-speed on the command line.

#include <yaml-cpp/yaml.h>

#include "hullinspect/experiment/config.hpp"
#include "yaml_fields.hpp"

namespace hullinspect::experiment::detail {

/// Reads both keys into c (after its grid, before `launch`, whose times depend on the step).
void read_speed(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c);

}  // namespace hullinspect::experiment::detail
