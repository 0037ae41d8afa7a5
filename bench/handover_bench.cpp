// Work handed over from UAVs away at their launch site (docs/results.md, "Work handed over"): whole
// missions with batteries on the default hull (the paper-quick scenarios, s2 = 7, one site at
// (115, 0), 300 s per battery at 1 m/s, seeds 1–3), counting the hull cells first observed by
// another UAV than the owner of their region (the planner's partition at the start) while that
// owner is away for a battery swap. Counters per mission: handed (those cells), foreign (cells
// first observed by a non-owner at any time), cells (hull cells), T_m.
//
//   build/release/bench/handover_bench --benchmark_filter=HandOver

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

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
  }
  void on_step(const sim::Simulator& sim, const planners::Planner& /*planner*/) override {
    const auto uavs = sim.uavs();
    for (std::size_t k = 0; k < uavs.size(); ++k) {
      if (uavs[k].away_left == 0) on_hull_[k] = 1;  // the flight out at the start is not a swap
    }
    if (partition_ == nullptr) return;
    const sim::PlannerView view = sim.view();
    for (int j = 0; j < view.sensed.uav_count(); ++j) {
      for (const sim::Reading& r : view.sensed.readings(j)) {
        if ((r.events & sim::kEventFirstSeen) == 0) continue;
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

 private:
  const partition::Partition* partition_ = nullptr;
  std::vector<char> on_hull_;
};

void hand_over(benchmark::State& state, const std::string& algorithm, const OptionMap& options) {
  const auto& hull = world::default_hull();
  const std::vector<std::string> scenarios = {"perfect", "imperfect", "inhomogeneous", "combined"};
  long long handed = 0, foreign = 0, t_m = 0, missions = 0;
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

}  // namespace
}  // namespace hullinspect::bench

BENCHMARK_MAIN();
