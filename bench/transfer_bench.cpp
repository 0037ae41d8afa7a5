// The `transfer` partitioner at scale (docs/results.md, "Partition at scale"): n = 1 … 32 UAVs on
// the default hull (230 × 30) and on the same profile scaled to 700 × 70
// (tools/make_default_hull.py --size 700x70, generated at build time), with the model's default
// start cells; and the random-start sweep (10 start sets per n, drawn from a seeded stream)
// reported as counters.
//
//   build/release/bench/transfer_bench --benchmark_filter=Default --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true   (one command line)
//   build/release/bench/transfer_bench --benchmark_filter=RandomStarts
//   build/release/bench/transfer_bench --benchmark_filter=FreshStarts
//
// Counters: rounds (transfer rounds), converged (1/0, or how many of 10 start sets), infeasible
// (how many of them were reported provably infeasible: a start walled in by other starts' cells),
// imbalance (largest |cells − desired| of the last partition, or the worst over the start sets),
// slowest_s (the largest Partition::seconds, wall time, of the ten), slowest_cpu_s (the largest
// CPU time of one of the ten).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <string_view>

#include "hullinspect/partition/transfer_partitioner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/random.hpp"

namespace {

using namespace hullinspect;

const world::HullMask& hull_by_index(int which) {
  if (which == 0) return world::default_hull();
  static const world::HullMask large = world::load_hull(HULLINSPECT_HULL_700X70);
  return large;
}

double imbalance(const partition::Partition& p) {
  double worst = 0;
  for (std::size_t k = 0; k < p.region_weight.size(); ++k) {
    worst = std::max(worst, std::abs(p.region_weight[k] - p.desired_weight[k]));
  }
  return worst;
}

// The warning of a provably infeasible start set (a start walled in by other starts' cells).
constexpr std::string_view kInfeasible = "transfer: no balanced partition exists";

// CPU time of this thread (the machine is shared: wall time measures the others' load too).
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// n distinct hull cells drawn uniformly from a seeded stream.
std::vector<grid::Cell> random_starts(const world::HullMask& hull, int n, std::uint64_t seed) {
  world::RandomStream rs(seed, 102);
  std::vector<grid::Cell> starts;
  while (static_cast<int>(starts.size()) < n) {
    const grid::Cell c = hull.mask().cell(hull.cells()[rs.below(hull.cells().size())]);
    if (std::find(starts.begin(), starts.end(), c) == starts.end()) starts.push_back(c);
  }
  return starts;
}

// Args: hull (0 = default 230 × 30, 1 = 700 × 70), n.
void BM_TransferDefaultStarts(benchmark::State& state) {
  const auto& hull = hull_by_index(static_cast<int>(state.range(0)));
  world::MissionParams params;
  params.uavs = static_cast<int>(state.range(1));
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = world::start_cells(params, hull);
  const partition::TransferPartitioner transfer;
  partition::Partition result;
  for (auto _ : state) {
    result = transfer.partition(request);
    benchmark::DoNotOptimize(result.owner.values().data());
  }
  state.counters["rounds"] = result.iterations;
  state.counters["converged"] = result.converged ? 1 : 0;
  state.counters["imbalance"] = imbalance(result);
}

// Args: hull, n. One iteration partitions all 10 start sets; the time is for the ten. Seeds
// 1000 n + draw (RandomStarts) or, for start sets nothing was tuned on, 7919 n + 777777 + draw
// (FreshStarts).
void random_start_sets(benchmark::State& state, std::uint64_t multiplier, std::uint64_t offset) {
  const auto& hull = hull_by_index(static_cast<int>(state.range(0)));
  const int n = static_cast<int>(state.range(1));
  std::vector<partition::PartitionRequest> requests(10);
  for (std::size_t draw = 0; draw < requests.size(); ++draw) {
    requests[draw].hull = &hull;
    requests[draw].starts =
        random_starts(hull, n, multiplier * static_cast<std::uint64_t>(n) + offset + draw);
  }
  const partition::TransferPartitioner transfer;
  int converged = 0;
  int infeasible = 0;
  double slowest_cpu = 0;
  double worst = 0;
  double slowest = 0;
  for (auto _ : state) {
    converged = 0;
    infeasible = 0;
    slowest_cpu = 0;
    worst = 0;
    slowest = 0;
    for (const auto& request : requests) {
      const double cpu0 = thread_cpu_seconds();
      const auto p = transfer.partition(request);
      slowest_cpu = std::max(slowest_cpu, thread_cpu_seconds() - cpu0);
      converged += p.converged;
      infeasible += !p.warnings.empty() && p.warnings[0].starts_with(kInfeasible);
      worst = std::max(worst, imbalance(p));
      slowest = std::max(slowest, p.seconds);
    }
  }
  state.counters["converged"] = converged;
  state.counters["infeasible"] = infeasible;
  state.counters["imbalance"] = worst;
  state.counters["slowest_s"] = slowest;
  state.counters["slowest_cpu_s"] = slowest_cpu;
}
void BM_TransferRandomStarts(benchmark::State& state) {
  random_start_sets(state, 1000, 0);
}
void BM_TransferFreshStarts(benchmark::State& state) {
  random_start_sets(state, 7919, 777777);
}

void all_sizes(benchmark::internal::Benchmark* b) {
  for (int hull = 0; hull <= 1; ++hull) {
    for (int n = 1; n <= 32; ++n) b->Args({hull, n});
  }
}

BENCHMARK(BM_TransferDefaultStarts)->Apply(all_sizes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TransferRandomStarts)->Apply(all_sizes)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_TransferFreshStarts)->Apply(all_sizes)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
