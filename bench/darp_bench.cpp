// DARP on the default hull with the default start cells (model.md §1), n = 2, 4, 6, 8 UAVs: time per
// partition and, as counters, the iterations, whether it converged and the largest imbalance.
//
//   build/release/darp_bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
//
// Each repetition uses a fresh partition seed (seed = repetition number) so the median covers the
// spread of the random factors, not one lucky draw.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace {

using namespace hullinspect;

void BM_DarpDefaultHull(benchmark::State& state) {
  const auto& hull = world::default_hull();
  world::MissionParams params;
  params.uavs = static_cast<int>(state.range(0));
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = world::start_cells(params, hull);
  static std::uint64_t repetition = 0;  // advances once per repetition
  request.seed = repetition++;
  const partition::DarpPartitioner darp;
  partition::Partition result;
  for (auto _ : state) {
    result = darp.partition(request);
    benchmark::DoNotOptimize(result.owner.values().data());
  }
  double imbalance = 0;
  for (std::size_t k = 0; k < result.region_weight.size(); ++k) {
    imbalance = std::max(imbalance, std::abs(result.region_weight[k] - result.desired_weight[k]));
  }
  state.counters["iterations"] = result.iterations;
  state.counters["converged"] = result.converged ? 1 : 0;
  state.counters["imbalance"] = imbalance;
}

BENCHMARK(BM_DarpDefaultHull)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
