// Time of one whole Coop-Frontier mission (default hull, perfect scenario, s2 = 7): simulator and
// planner together, instances drawn beforehand. Each iteration runs the next of 20 fixed seeds, so
// the per-iteration time is the mean over a fixed instance mix; the median over repetitions is the
// number to quote.
//
//   build/release/coop_frontier_bench --benchmark_repetitions=9 --benchmark_report_aggregates_only

#include <benchmark/benchmark.h>

#include <vector>

#include "hullinspect/planners/coop_frontier_planner.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/world/scenario.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"

namespace {

using namespace hullinspect;

void BM_CoopFrontierMission(benchmark::State& state) {
  const auto& hull = world::default_hull();
  world::MissionParams params;
  params.uavs = static_cast<int>(state.range(0));
  params.s2 = 7;
  const auto corrosion = world::scenario("perfect").corrosion(hull.width());
  std::vector<world::Instance> instances;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    instances.push_back(world::generate_instance(hull, corrosion, seed));
  }
  std::size_t next = 0;
  long long steps = 0;
  long long missions = 0;
  for (auto _ : state) {
    planners::CoopFrontierPlanner planner;
    const auto result = planners::run_mission(hull, instances[next], params, planner);
    if (!result.complete) state.SkipWithError("mission incomplete");
    steps += result.steps;
    ++missions;
    next = (next + 1) % instances.size();
  }
  state.counters["steps_per_mission"] =
      benchmark::Counter(static_cast<double>(steps) / static_cast<double>(missions));
}
BENCHMARK(BM_CoopFrontierMission)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
