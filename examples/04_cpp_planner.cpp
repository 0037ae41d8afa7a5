// Tutorial 04: a planner of your own in C++ (docs/user-planners.md).
//   build/release/examples/04_cpp_planner
//
// examples/planners/nearest_first_planner.cpp defines and registers "nearest-first" in one line;
// every file of examples/planners/ is linked into this program, the CLI and the Python module, so
// the planner is found by name like the built-in ones. This program lists its declared options and
// runs it against Part-TSP on a few seeds.

#include <cstdio>
#include <string>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/scenario.hpp"

int main() {
  using namespace hullinspect;
  const auto& entry = planners::planners().get("nearest-first");
  std::printf("%s: %s\n%s", entry.name.c_str(), entry.description.c_str(),
              describe_params(entry.options, "  ").c_str());

  const world::HullMask& hull = world::default_hull();
  for (const std::string algorithm : {"nearest-first", "part-tsp"}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      planners::MissionSpec spec;
      spec.algorithm = algorithm;
      spec.seed = seed;
      spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
      const auto result = planners::run_mission(spec, hull);
      std::printf("%-14s seed %llu: T_c = %d s, T_m = %d s\n", algorithm.c_str(),
                  static_cast<unsigned long long>(seed), result.t_c.value_or(-1),
                  result.t_m.value_or(-1));
      if (!result.complete) return 1;
    }
  }
  return 0;
}
