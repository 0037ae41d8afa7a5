// DARP on the default hull with the default start cells (model.md §1), n = 2, 4, 6, 8, 12, 16 UAVs:
// time per partition and, as counters, the iterations, whether it converged and the largest
// imbalance; the `transfer` partitioner on the same hull and starts beside it.
//
//   build/release/bench/darp_bench --benchmark_repetitions=10
//   --benchmark_report_aggregates_only=true
//
// Each repetition uses a fresh partition seed (seed = repetition number) so the median covers the
// spread of the random factors, not one lucky draw.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/partition/transfer_partitioner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace {

using namespace hullinspect;

template <typename PartitionerType>
void BM_DefaultHull(benchmark::State& state) {
  const auto& hull = world::default_hull();
  world::MissionParams params;
  params.uavs = static_cast<int>(state.range(0));
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = world::start_cells(params, hull);
  static std::uint64_t repetition = 0;  // advances once per repetition
  request.seed = repetition++;
  const PartitionerType partitioner;
  partition::Partition result;
  for (auto _ : state) {
    result = partitioner.partition(request);
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

void fleet_sizes(benchmark::internal::Benchmark* b) {
  for (int n : {2, 4, 6, 8, 12, 16}) b->Arg(n);
}

BENCHMARK(BM_DefaultHull<partition::DarpPartitioner>)
    ->Name("BM_DarpDefaultHull")
    ->Apply(fleet_sizes)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DefaultHull<partition::TransferPartitioner>)
    ->Name("BM_TransferDefaultHull")
    ->Apply(fleet_sizes)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
