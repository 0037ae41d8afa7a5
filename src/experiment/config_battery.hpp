#pragma once
// The `battery` key of experiment configs (docs/model.md, "Batteries and sorties"):
//   battery: {endurance: S, reserve: S, swap-time: S}
// times in seconds; the same as --endurance, --reserve and --swap-time on the command line.

#include <yaml-cpp/yaml.h>

#include "hullinspect/experiment/config.hpp"
#include "yaml_fields.hpp"

namespace hullinspect::experiment::detail {

/// Reads `battery` into c (after its launch sites); the times are checked here, naming their
/// line; an endurance too short for the hull is refused when the cells are validated.
void read_battery(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c);

}  // namespace hullinspect::experiment::detail
