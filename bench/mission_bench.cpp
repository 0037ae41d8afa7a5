// One whole lawnmower mission (default hull, perfect scenario, s2 = 7): the foundation's speed.
// The partition is computed once and shared, as the experiment runner does. Also one whole
// Sweep-Inspect mission (docs/sweep-inspect.md, "Planner time") in the combined scenario (z = 1
// sweeps of the dense half) and the imperfect one (the band partition's cuts balanced on planned
// flights, which plans every UAV's sweep for each cut it tries).
//   build/release/bench/mission_bench --benchmark_repetitions=10
//   --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include "mission_loop.hpp"

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/scenario.hpp"

namespace {

using namespace hullinspect;

void run_missions(benchmark::State& state, const std::string& algorithm,
                  const char* scenario = "perfect", OptionMap planner_options = {}) {
  const auto& hull = world::default_hull();
  planners::MissionSpec spec;
  spec.algorithm = algorithm;
  spec.planner_options = std::move(planner_options);
  spec.params.uavs = static_cast<int>(state.range(0));
  spec.params.s2 = 7;
  spec.corrosion = world::scenario(scenario).corrosion(hull.width());
  bench::time_missions(state, spec, 50);
  state.counters["missions/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_LawnmowerMission(benchmark::State& state) {
  run_missions(state, "lawnmower");
}
BENCHMARK(BM_LawnmowerMission)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);

// Args: n, scenario (0 combined, 1 imperfect).
void BM_SweepInspectMission(benchmark::State& state) {
  run_missions(state, "sweep-inspect", state.range(1) == 0 ? "combined" : "imperfect");
}
BENCHMARK(BM_SweepInspectMission)->ArgsProduct({{4, 8}, {0, 1}})->Unit(benchmark::kMillisecond);

// The simulator alone: instance generation + step loop with a trivial hovering planner is not
// meaningful (it never completes), so time the instance draw separately.
void BM_GenerateInstance(benchmark::State& state) {
  const auto& hull = world::default_hull();
  const auto corrosion = world::scenario("imperfect").corrosion(hull.width());
  std::uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(world::generate_instance(hull, corrosion, seed++));
}
BENCHMARK(BM_GenerateInstance)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
