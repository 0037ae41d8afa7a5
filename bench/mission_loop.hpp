#pragma once
// The mission loop the mission benchmarks share: whole missions on the default hull, one seed after
// another, the partition computed once and shared as the experiment runner shares it.

#include <benchmark/benchmark.h>

#include <cstdint>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/partition_cache.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::bench {

/// Runs `spec` once per benchmark iteration with seeds 1 … `seeds` in turn, sets the counter
/// steps/mission and returns the steps simulated in all.
inline long long time_missions(benchmark::State& state, planners::MissionSpec spec, int seeds) {
  const auto& hull = world::default_hull();
  planners::PartitionCache partitions;
  planners::MissionOptions options;
  options.partitions = &partitions;
  std::uint64_t seed = 1;
  long long steps = 0;
  for (auto _ : state) {
    spec.seed = seed++ % static_cast<std::uint64_t>(seeds) + 1;
    const auto r = planners::run_mission(spec, hull, options);
    steps += r.steps;
    benchmark::DoNotOptimize(r.t_m);
  }
  state.counters["steps/mission"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kAvgIterations);
  return steps;
}

}  // namespace hullinspect::bench
