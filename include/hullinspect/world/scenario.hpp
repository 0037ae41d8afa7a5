#pragma once
// The paper's corrosion scenarios (docs/model.md, "Instances") by name, as a registry whose entries
// declare their parameters (p-c, l-c, front-p-c, front-l-c, p-tp, p-fp) with per-scenario defaults.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/core/registry.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::world {

/// One scenario's corrosion settings: homogeneous when the front half equals the back half.
struct CorrosionScenario {
  double p_c = 0.005;        ///< centre probability, back half (whole hull when homogeneous)
  int l_c = 5;               ///< largest rectangle side, back half
  double front_p_c = 0.005;  ///< centre probability of the front half (x >= a/2)
  int front_l_c = 5;         ///< largest rectangle side of the front half
  double p_tp = 1.0;         ///< a true centre is in the prior
  double p_fp = 0.0;         ///< another hull cell is a false prior centre
  CorrosionParams corrosion(int grid_width) const;
};

using ScenarioInfo = RegistryEntry<CorrosionScenario>;
using ScenarioRegistry = Registry<CorrosionScenario>;

/// perfect, imperfect, inhomogeneous, combined.
ScenarioRegistry& scenarios();
/// The named scenario with `options` over its defaults. "p-c" ("l-c") sets both halves unless
/// "front-p-c" ("front-l-c") is given too. Throws ParameterError("scenario", …) for an unknown
/// name and ParameterError("<scenario>.<key>", …) for a bad option.
CorrosionScenario scenario(std::string_view name, const OptionMap& options = {});
/// The effective options of a scenario (same rules as scenario()).
OptionMap resolve_scenario_options(std::string_view name, const OptionMap& options = {});

}  // namespace hullinspect::world
