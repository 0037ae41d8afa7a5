#include "hullinspect/planners/scenario.hpp"

#include <fmt/format.h>

#include <vector>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::planners {

world::CorrosionParams Scenario::corrosion(int grid_width) const {
  if (back_p_c == front_p_c && back_l_c == front_l_c) {
    return world::CorrosionParams::homogeneous(grid_width, back_p_c, back_l_c, p_tp, p_fp);
  }
  return world::CorrosionParams::front_back(grid_width, back_p_c, back_l_c, front_p_c, front_l_c,
                                            p_tp, p_fp);
}

std::span<const Scenario> scenarios() {
  static const std::vector<Scenario> all = {
      {"perfect", "homogeneous corrosion, perfect prior (C' = C)", 0.005, 0.005, 5, 5, 1.0, 0.0},
      {"imperfect", "homogeneous corrosion, prior with false negatives and positives", 0.005, 0.005,
       5, 5, 0.6, 0.003},
      {"inhomogeneous", "more and larger clusters in the front half, perfect prior", 0.0025, 0.01, 3,
       7, 1.0, 0.0},
      {"combined", "inhomogeneous corrosion and a poor prior (Fig. 8 c2)", 0.0025, 0.01, 3, 7, 0.4,
       0.005},
  };
  return all;
}

const Scenario& scenario(std::string_view name) {
  std::string names;
  for (const auto& s : scenarios()) {
    if (s.name == name) return s;
    names += (names.empty() ? "" : ", ") + s.name;
  }
  throw ParameterError("scenario", fmt::format("unknown scenario '{}' (known: {})", name, names));
}

}  // namespace hullinspect::planners
