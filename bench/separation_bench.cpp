// What separation costs the computer (docs/results.md, "Separation between UAVs"): one whole
// mission on the default hull (perfect scenario, s2 = 7, the partition shared as the experiment
// runner shares it) with separation D = 0 (nothing runs), and D = 1, 3 (the simulator's check and
// the deconfliction layer every step). The mission's wall time is the reference.
//   build/release/bench/separation_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include "mission_loop.hpp"

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/scenario.hpp"

namespace {

using namespace hullinspect;

// Args: planner (0 lawnmower, 1 sweep-inspect), n, D.
void BM_MissionWithSeparation(benchmark::State& state) {
  const auto& hull = world::default_hull();
  planners::MissionSpec spec;
  spec.algorithm = state.range(0) == 0 ? "lawnmower" : "sweep-inspect";
  spec.params.uavs = static_cast<int>(state.range(1));
  spec.params.separation = static_cast<int>(state.range(2));
  spec.params.s2 = 7;
  spec.corrosion = world::scenario("perfect").corrosion(hull.width());
  bench::time_missions(state, spec, 10);
}
BENCHMARK(BM_MissionWithSeparation)
    ->ArgsProduct({{0, 1}, {8, 32}, {0, 1, 3}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
