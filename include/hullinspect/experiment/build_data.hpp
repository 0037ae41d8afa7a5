#pragma once
// Data compiled into the library by cmake/EmbedExperiment.cmake, so that the CLI finds its presets
// and plotting script from any directory.

#include <span>
#include <string_view>

namespace hullinspect::experiment {

struct EmbeddedFile {
  std::string_view name;  ///< file stem ("paper" for presets/paper.yaml)
  std::string_view text;
};

/// presets/*.yaml.
std::span<const EmbeddedFile> embedded_presets();

/// tools/plot_report.py.
std::string_view embedded_plot_script();

/// The git revision of the source tree when the build was configured, or "unknown".
std::string_view git_revision();

}  // namespace hullinspect::experiment
