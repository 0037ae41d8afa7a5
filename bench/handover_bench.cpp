// Work handed over from UAVs away at their launch site (docs/results.md, "Work handed over"): whole
// missions with batteries on the default hull (the paper-quick scenarios, s2 = 7, one site at
// (115, 0), 300 s per battery at 1 m/s, seeds 1–3), counting the hull cells first observed by
// another UAV than the owner of their region (the planner's partition at the start) while that
// owner is away for a battery swap. A planner without regions (Coop-Frontier: each UAV takes the
// frontiers nearest it) is measured in its own terms: when a UAV leaves for a swap, the unknown
// hull cells nearer to it (Manhattan distance) than to any UAV left on the hull are its share,
// and the cells of that share first observed by another UAV before it is back are handed over.
// Counters per mission: handed (partition), foreign (cells first observed by a non-owner at any
// time), share (unknown cells nearest a UAV that leaves, summed over its departures), handed_near
// (those of them first observed by another UAV while it is away), cells (hull cells), steps.
//
//   build/release/bench/handover_bench --benchmark_filter=HandOver

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "hullinspect/grid/cell.hpp"

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"

namespace hullinspect::bench {
namespace {

class HandOverCount final : public planners::MissionObserver {
 public:
  void on_start(const sim::Simulator& sim, const planners::Planner& planner) override {
    partition_ = planner.partition();
    on_hull_.assign(sim.uavs().size(), 0);
    share_.assign(sim.uavs().size(), {});
    share_of_.assign(static_cast<std::size_t>(sim.map().size()), -1);
  }
  void on_step(const sim::Simulator& sim, const planners::Planner& /*planner*/) override {
    const auto uavs = sim.uavs();
    for (std::size_t k = 0; k < uavs.size(); ++k) {
      if (uavs[k].away_left == 0) {
        on_hull_[k] = 1;  // the flight out at the start is not a swap
        release(k);       // back from its swap (or never left)
      } else if (on_hull_[k] != 0 && share_[k].empty()) {
        leave(sim, k);
      }
    }
    const sim::PlannerView view = sim.view();
    for (int j = 0; j < view.sensed.uav_count(); ++j) {
      for (const sim::Reading& r : view.sensed.readings(j)) {
        if ((r.events & sim::kEventFirstSeen) == 0) continue;
        const int near = share_of_[static_cast<std::size_t>(r.index)];
        if (near >= 0 && near != j) ++handed_near;
        if (partition_ == nullptr) continue;
        const int owner = partition_->owner[r.index];
        if (owner < 0 || owner == j) continue;
        ++foreign;
        const auto o = static_cast<std::size_t>(owner);
        if (on_hull_[o] != 0 && uavs[o].away_left > 0) ++handed;
      }
    }
  }
  long long handed = 0;
  long long foreign = 0;
  long long share = 0;
  long long handed_near = 0;

 private:
  // UAV k has left the hull for a swap: its share is every unknown hull cell nearer to it than to
  // any UAV still on the hull (a tie is nobody's), as Coop-Frontier sends the nearest UAV to a
  // frontier.
  void leave(const sim::Simulator& sim, std::size_t k) {
    const auto uavs = sim.uavs();
    const auto& map = sim.map();
    for (const int i : sim.hull().cells()) {
      if (map[i] != sim::kUnknown || share_of_[static_cast<std::size_t>(i)] >= 0) continue;
      const grid::Cell c = map.cell(i);
      const int mine = grid::manhattan(c, uavs[k].pos);
      bool nearest = true;
      for (std::size_t j = 0; j < uavs.size() && nearest; ++j) {
        if (j == k || uavs[j].failed || uavs[j].away_left > 0) continue;
        nearest = mine < grid::manhattan(c, uavs[j].pos);
      }
      if (!nearest) continue;
      share_of_[static_cast<std::size_t>(i)] = static_cast<int>(k);
      share_[k].push_back(i);
    }
    share += std::ssize(share_[k]);
    if (share_[k].empty()) share_[k].push_back(-1);  // left with no share: nothing to hand over
  }
  void release(std::size_t k) {
    for (const int i : share_[k]) {
      if (i >= 0) share_of_[static_cast<std::size_t>(i)] = -1;
    }
    share_[k].clear();
  }

  const partition::Partition* partition_ = nullptr;
  std::vector<char> on_hull_;
  std::vector<std::vector<int>> share_;  // per UAV away for a swap: its share of the hull
  std::vector<int> share_of_;            // per cell: the UAV away whose share it is, or -1
};

void hand_over(benchmark::State& state, const std::string& algorithm, const OptionMap& options) {
  const auto& hull = world::default_hull();
  const std::vector<std::string> scenarios = {"perfect", "imperfect", "inhomogeneous", "combined"};
  long long handed = 0, foreign = 0, share = 0, handed_near = 0, t_m = 0, missions = 0;
  for (auto _ : state) {
    for (const auto& scenario : scenarios) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        planners::MissionSpec spec;
        spec.algorithm = algorithm;
        spec.planner_options = options;
        spec.seed = seed;
        spec.params.uavs = static_cast<int>(state.range(0));
        spec.params.s2 = 7;
        spec.params.speed_m_s = 1.0;
        spec.params.launch_sites = {{115, 0}};
        spec.params.endurance_s = 300;
        spec.corrosion = world::scenario(scenario).corrosion(hull.width());
        HandOverCount count;
        planners::MissionOptions mission;
        mission.observers = {&count};
        const auto r = planners::run_mission(spec, hull, mission);
        handed += count.handed;
        foreign += count.foreign;
        share += count.share;
        handed_near += count.handed_near;
        t_m += r.steps;
        ++missions;
      }
    }
  }
  const auto per_mission = [&](long long v) {
    return benchmark::Counter(static_cast<double>(v) / static_cast<double>(missions));
  };
  state.counters["handed"] = per_mission(handed);
  state.counters["foreign"] = per_mission(foreign);
  state.counters["share"] = per_mission(share);
  state.counters["handed_near"] = per_mission(handed_near);
  state.counters["cells"] = static_cast<double>(hull.cells().size());
  state.counters["steps"] = per_mission(t_m);
}

BENCHMARK_CAPTURE(hand_over, sweep_inspect, std::string("sweep-inspect"), OptionMap{})
    ->Name("HandOver/sweep-inspect")
    ->Arg(4)
    ->Arg(8)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(hand_over, part_tsp_share, std::string("part-tsp"),
                  OptionMap{{"r1", "2"}, {"r2", "0"}, {"share-work", "true"}})
    ->Name("HandOver/part-tsp-share")
    ->Arg(4)
    ->Arg(8)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(hand_over, part_tsp, std::string("part-tsp"), OptionMap{{"r1", "2"}, {"r2", "0"}})
    ->Name("HandOver/part-tsp")
    ->Arg(4)
    ->Arg(8)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(hand_over, coop_frontier, std::string("coop-frontier"), OptionMap{})
    ->Name("HandOver/coop-frontier")
    ->Arg(4)
    ->Arg(8)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace
}  // namespace hullinspect::bench

BENCHMARK_MAIN();
