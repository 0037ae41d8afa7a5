// What batteries cost the computer (docs/results.md, "Batteries and sorties"): one whole mission
// on the default hull (perfect scenario, s2 = 7, one launch site at (115, 0), the partition shared
// as the experiment runner shares it) with unlimited flight and with 360 s per battery (the
// simulator's battery count and the sortie layer every step). Missions with batteries are longer,
// so the comparison is per simulated step: the counter us/step.
//   build/release/bench/battery_bench --benchmark_repetitions=3
//   --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include "mission_loop.hpp"

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/scenario.hpp"

namespace {

using namespace hullinspect;

// Args: planner (0 lawnmower, 1 sweep-inspect), n, endurance in seconds (0 = unlimited).
void BM_MissionWithBattery(benchmark::State& state) {
  const auto& hull = world::default_hull();
  planners::MissionSpec spec;
  spec.algorithm = state.range(0) == 0 ? "lawnmower" : "sweep-inspect";
  spec.params.uavs = static_cast<int>(state.range(1));
  spec.params.launch_sites = {{115, 0}};
  if (state.range(2) > 0) spec.params.endurance_s = static_cast<double>(state.range(2));
  spec.params.s2 = 7;
  spec.corrosion = world::scenario("perfect").corrosion(hull.width());
  const long long steps = bench::time_missions(state, spec, 10);
  state.counters["us/step"] = benchmark::Counter(
      static_cast<double>(steps) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_MissionWithBattery)
    ->ArgsProduct({{0, 1}, {8}, {0, 360}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
