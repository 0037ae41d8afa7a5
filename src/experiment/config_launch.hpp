#pragma once
// The `launch` key of experiment configs (docs/model.md, "Launch sites"):
//   launch: {sites: [[x, y], …], transfer: S, takeoff-time: S}
// sites in cells of the grid, times in seconds; the same as --launch, --launch-transfer and
// --takeoff-time on the command line.

#include <yaml-cpp/yaml.h>

#include "hullinspect/experiment/config.hpp"
#include "yaml_fields.hpp"

namespace hullinspect::experiment::detail {

/// Reads `launch` into c (after its hull, no-fly zones and time limit); every site and time is
/// checked here, naming its line.
void read_launch(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c);

}  // namespace hullinspect::experiment::detail
