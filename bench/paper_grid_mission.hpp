#pragma once
// One mission of the paper preset's grid, as the benchmarks that fly that grid build it.

#include <cstdint>
#include <string>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"

namespace hullinspect::bench {

/// `algorithm` on `hull` in `scenario` with footprint s2, n UAVs and `seed`; the partitioned
/// planners with the preset's r1 = 2, r2 = 0.
inline planners::MissionSpec paper_grid_mission(const std::string& algorithm, const char* scenario,
                                                int s2, int n, int seed,
                                                const world::HullMask& hull) {
  planners::MissionSpec spec;
  spec.algorithm = algorithm;
  if (algorithm == "part-tsp" || algorithm == "part-tsp0")
    spec.planner_options = {{"r1", "2"}, {"r2", "0"}};
  spec.params.uavs = n;
  spec.params.s2 = s2;
  spec.corrosion = world::scenario(scenario).corrosion(hull.width());
  spec.seed = static_cast<std::uint64_t>(seed);
  return spec;
}

}  // namespace hullinspect::bench
