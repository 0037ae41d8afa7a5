#include "hullinspect/experiment/presets.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/build_data.hpp"

namespace hullinspect::experiment {

std::vector<std::string> preset_names() {
  std::vector<std::string> names;
  for (const auto& p : embedded_presets()) names.emplace_back(p.name);
  std::sort(names.begin(), names.end());
  return names;
}

std::string_view preset_text(std::string_view name) {
  for (const auto& p : embedded_presets()) {
    if (p.name == name) return p.text;
  }
  throw ParameterError("preset", fmt::format("unknown preset '{}' (known: {})", name,
                                             fmt::join(preset_names(), ", ")));
}

ExperimentConfig load_preset(std::string_view name) {
  const std::string_view text = preset_text(name);
  return parse_config(text, fmt::format("presets/{}.yaml", name), ".");
}

}  // namespace hullinspect::experiment
