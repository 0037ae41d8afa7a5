#pragma once
// Experiment presets by name (presets/*.yaml, compiled into the binary).

#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/experiment/config.hpp"

namespace hullinspect::experiment {

/// Names of the built-in presets, sorted ("fig8", "paper", "paper-quick").
std::vector<std::string> preset_names();

/// The YAML text of a preset; ParameterError("preset", …) listing the known names otherwise.
std::string_view preset_text(std::string_view name);

/// Parses a preset; errors name it as "presets/<name>.yaml".
ExperimentConfig load_preset(std::string_view name);

}  // namespace hullinspect::experiment
