// Whole missions at scale (docs/results.md, "Missions at scale"): every paper planner (lawnmower,
// part-tsp, part-tsp0, coop-frontier) on the default hull profile at 1×, 2×, 4× and 8× its area and
// on the 700 × 70 hull, for n = 4 … 32. The partitioned planners use the `transfer` partitioner
// (DARP does not converge at these sizes; docs/results.md), so every mission is one partition plus
// one simulated mission, measured as CPU time of one thread. Scenario "imperfect" (noisy prior),
// s1 = 5, s2 = 7, instance seed 1, time limit 200 000 steps.
//
//   build/release/bench/mission_scale_bench --benchmark_format=json > scale.json
//   /usr/bin/python3 tools/plot_mission_scale.py scale.json docs/img/mission_scale.png
//   build/release/bench/mission_scale_bench --benchmark_filter='Hull700x70/16/'
//
// Counters: T_m (the mission's T_m in steps; 0 if incomplete),
// complete (1/0), hull_cells, area (hull cells ÷ the default hull's), tsp_solves.

#include <benchmark/benchmark.h>

#include <array>
#include <string>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"

namespace {

using namespace hullinspect;

// The default profile at 1×, 2×, 4×, 8× its area (both sides scaled by √k), then 700 × 70.
const world::HullMask& hull_by_index(int which) {
  static const std::array<world::HullMask, 5> hulls = {
      world::default_hull(), world::load_hull(HULLINSPECT_HULL_325X42),
      world::load_hull(HULLINSPECT_HULL_460X60), world::load_hull(HULLINSPECT_HULL_650X85),
      world::load_hull(HULLINSPECT_HULL_700X70)};
  return hulls[static_cast<std::size_t>(which)];
}

constexpr std::array<const char*, 4> kAlgorithms = {"lawnmower", "part-tsp", "part-tsp0",
                                                    "coop-frontier"};

// Args: hull index, n, algorithm index. One mission per iteration (the same one each time).
void BM_Mission(benchmark::State& state) {
  const auto& hull = hull_by_index(static_cast<int>(state.range(0)));
  const std::string algorithm = kAlgorithms[static_cast<std::size_t>(state.range(2))];
  planners::MissionSpec spec;
  spec.algorithm = algorithm;
  if (algorithm != "coop-frontier") spec.planner_options = {{"partitioner", "transfer"}};
  if (algorithm == "part-tsp" || algorithm == "part-tsp0") {
    spec.planner_options["r1"] = "2";  // the paper preset's Part-TSP settings
    spec.planner_options["r2"] = "0";
  }
  spec.params.uavs = static_cast<int>(state.range(1));
  spec.params.s2 = 7;
  spec.params.time_limit = 200'000;
  spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
  spec.seed = 1;
  sim::MissionResult r;
  for (auto _ : state) {
    r = planners::run_mission(spec, hull);
    // Not DoNotOptimize(r.t_m): Google Benchmark 1.7.1's non-const DoNotOptimize lets GCC pass a
    // small object through a register ("+m,r") and corrupted the std::optional (t_m came back
    // empty or garbage on complete missions: google/benchmark#1340, #1424). An int is safe.
    benchmark::DoNotOptimize(r.steps);
  }
  if (r.complete != r.t_m.has_value()) state.SkipWithError("complete and T_m disagree");
  state.SetLabel(algorithm);
  state.counters["T_m"] = r.t_m.value_or(0);
  state.counters["complete"] = r.complete ? 1 : 0;
  state.counters["hull_cells"] = r.hull_cells;
  state.counters["area"] =
      static_cast<double>(hull.cell_count()) / world::default_hull().cell_count();
  state.counters["tsp_solves"] = static_cast<double>(r.planner.tsp_solves);
}

void growth(benchmark::internal::Benchmark* b) {
  for (int hull = 0; hull <= 3; ++hull) {
    for (int n : {4, 8, 16, 32}) {
      for (int a = 0; a < static_cast<int>(kAlgorithms.size()); ++a) b->Args({hull, n, a});
    }
  }
}
void target(benchmark::internal::Benchmark* b) {
  for (int a = 0; a < static_cast<int>(kAlgorithms.size()); ++a) b->Args({4, 16, a});
}

BENCHMARK(BM_Mission)->Name("Growth")->Apply(growth)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Mission)
    ->Name("Hull700x70")
    ->Apply(target)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);

}  // namespace

BENCHMARK_MAIN();
