// Example 1: run one mission from C++ and print c(t) every 50 s.
//   build/release/examples/01_run_mission [algorithm]
//
// The library's whole flow in a few lines: a hull, an instance drawn from a scenario and a seed,
// a planner by name, and run_mission.

#include <cstdio>
#include <string>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/world/scenario.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"

int main(int argc, char** argv) {
  using namespace hullinspect;
  const std::string algorithm = argc > 1 ? argv[1] : "lawnmower";

  const world::HullMask& hull = world::default_hull();
  const auto corrosion = world::scenario("imperfect").corrosion(hull.width());
  const world::Instance instance = world::generate_instance(hull, corrosion, /*seed=*/7);

  world::MissionParams params;  // n = 4, s1 = 5, s2 = 7, θ = 90°
  auto planner = planners::make_planner(algorithm);
  const sim::MissionResult result = planners::run_mission(hull, instance, params, *planner);

  std::printf("%s: T_c = %d s, T_m = %d s\n", algorithm.c_str(), result.t_c.value_or(-1),
              result.t_m.value_or(-1));
  for (int t = 0; t <= result.steps; t += 50) {
    std::printf("t = %4d s   c = %5.1f %%   m = %5.1f %%\n", t, result.c_percent(t), result.m_percent(t));
  }
  return result.complete ? 0 : 1;
}
