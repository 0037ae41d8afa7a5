#pragma once
// The paper's corrosion scenarios (model.md §6) by name.

#include <span>
#include <string>
#include <string_view>

#include "hullinspect/world/instance.hpp"

namespace hullinspect::planners {

struct Scenario {
  std::string name;
  std::string description;
  double back_p_c, front_p_c;
  int back_l_c, front_l_c;
  double p_tp, p_fp;
  world::CorrosionParams corrosion(int grid_width) const;
};

/// perfect, imperfect, inhomogeneous, combined.
std::span<const Scenario> scenarios();
/// Throws ParameterError("scenario", …) for an unknown name.
const Scenario& scenario(std::string_view name);

}  // namespace hullinspect::planners
