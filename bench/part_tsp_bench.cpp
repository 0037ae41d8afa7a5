// Time of one whole Part-TSP mission (default hull, perfect scenario, s2 = 7) for n = 4 and 8 with
// the exact and the dfj-iterative segment-TSP solvers; the partition is computed once per fleet
// size (PartitionCache) and timed separately. Target: under 20 ms per mission with `exact`.
//
//   build/release/bench/part_tsp_bench
//
// Each iteration runs one mission, cycling over the instances of seeds 1–20. Counters: median and
// mean wall time per mission (median_ms, mean_ms, max_ms), median and mean process CPU time per
// mission (median_cpu_ms, mean_cpu_ms; the figure to quote on a shared machine), the TSP solvers'
// share (tsp_ms, wall) and TSP solves per mission.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <string>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/planners/partition_cache.hpp"
#include "hullinspect/world/scenario.hpp"
#include "hullinspect/world/hull.hpp"

namespace {

using namespace hullinspect;

constexpr int kInstances = 20;

const std::vector<world::Instance>& instances() {
  static const std::vector<world::Instance> all = [] {
    const auto& hull = world::default_hull();
    const auto corrosion = world::scenario("perfect").corrosion(hull.width());
    std::vector<world::Instance> v;
    for (int seed = 1; seed <= kInstances; ++seed) {
      v.push_back(world::generate_instance(hull, corrosion, static_cast<std::uint64_t>(seed)));
    }
    return v;
  }();
  return all;
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double mean(const std::vector<double>& v) {
  double total = 0;
  for (double x : v) total += x;
  return v.empty() ? 0 : total / static_cast<double>(v.size());
}

world::MissionParams params_for(int uavs) {
  world::MissionParams p;
  p.uavs = uavs;
  p.s2 = 7;
  return p;
}

void BM_Partition(benchmark::State& state) {
  const auto& hull = world::default_hull();
  const auto params = params_for(static_cast<int>(state.range(0)));
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = world::start_cells(params, hull);
  const auto partitioner = partition::make_partitioner(planners::PartTspOptions{}.partitioner);
  for (auto _ : state) benchmark::DoNotOptimize(partitioner->partition(request));
  state.SetLabel(planners::PartTspOptions{}.partitioner);
}

void BM_Mission(benchmark::State& state, bool use_prior, const std::string& solver,
                OptionMap solver_options) {
  const auto& hull = world::default_hull();
  const auto params = params_for(static_cast<int>(state.range(0)));
  planners::PartitionCache partitions;
  planners::PartTspOptions options;
  options.use_prior = use_prior;
  options.tsp_solver = solver;
  options.tsp_solver_options = solver_options;
  try {
    const planners::PartTspPlanner probe(options);
  } catch (const Error& e) {
    state.SkipWithError(e.what());
    return;
  }
  planners::MissionOptions mission_options;
  mission_options.partitions = &partitions;
  {  // compute the partition outside the timed loop
    planners::PartTspPlanner warmup(options);
    planners::run_mission(hull, instances().front(), params, warmup, mission_options);
  }
  std::vector<double> seconds;
  std::vector<double> cpu_seconds;
  double tsp_seconds = 0;
  long long solves = 0;
  std::size_t next = 0;
  for (auto _ : state) {
    planners::PartTspPlanner planner(options);
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = process_cpu_seconds();
    const auto result =
        planners::run_mission(hull, instances()[next], params, planner, mission_options);
    cpu_seconds.push_back(process_cpu_seconds() - cpu0);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    benchmark::DoNotOptimize(result.t_m);
    if (!result.complete) state.SkipWithError("a mission did not complete");
    tsp_seconds += result.planner.tsp_seconds;
    solves += result.planner.tsp_solves;
    next = (next + 1) % instances().size();
  }
  if (seconds.empty()) return;
  const double runs = static_cast<double>(seconds.size());
  state.counters["median_ms"] = median(seconds) * 1e3;
  state.counters["mean_ms"] = mean(seconds) * 1e3;
  state.counters["max_ms"] = *std::max_element(seconds.begin(), seconds.end()) * 1e3;
  state.counters["median_cpu_ms"] = median(cpu_seconds) * 1e3;
  state.counters["mean_cpu_ms"] = mean(cpu_seconds) * 1e3;
  state.counters["tsp_ms"] = tsp_seconds / runs * 1e3;
  state.counters["tsp_solves"] = static_cast<double>(solves) / runs;
  std::string label = (use_prior ? "part-tsp " : "part-tsp0 ") + solver;
  for (const auto& [key, value] : solver_options) label += " " + key + "=" + value;
  state.SetLabel(label);
}

}  // namespace

BENCHMARK(BM_Partition)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Mission, part_tsp_exact, true, std::string("exact"), OptionMap{})
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Mission, part_tsp_exact_dp12, true, std::string("exact"),
                  OptionMap{{"dp-max-segments", "12"}})
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Mission, part_tsp_dfj, true, std::string("dfj-iterative"), OptionMap{})
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Mission, part_tsp0_exact, false, std::string("exact"), OptionMap{})
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Mission, part_tsp0_dfj, false, std::string("dfj-iterative"), OptionMap{})
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

BENCHMARK_MAIN();
