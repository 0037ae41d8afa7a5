#pragma once
// Records a mission step by step for behavioural tests: actions, UAV states, readings, M, and the
// planner's annotations (modes, targets, plans).

#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/sim/simulator.hpp"

namespace hullinspect::testing {

class MissionRecorder final : public planners::MissionObserver, public planners::AnnotationSink {
 public:
  struct Frame {
    int time = 0;
    std::vector<sim::UavState> uavs;   ///< at `time`
    std::vector<sim::Action> actions;  ///< applied at time − 1 (empty at t = 0)
    std::vector<std::string> modes;    ///< annotations after the decision of time − 1
    std::vector<grid::Cell> targets;
    std::vector<std::vector<grid::Cell>> plans;
    std::vector<std::vector<sim::Reading>> readings;  ///< per UAV, sensed at `time`
    grid::Grid<std::int8_t> map;                      ///< M at `time`
  };

  void on_start(const sim::Simulator& sim, const planners::Planner& planner) override {
    record(sim, planner, false);
  }
  void on_step(const sim::Simulator& sim, const planners::Planner& planner) override {
    record(sim, planner, true);
  }
  void uav(int k, std::string_view mode, grid::Cell target,
           std::span<const grid::Cell> plan) override {
    auto& f = frames.back();
    const auto uk = static_cast<std::size_t>(k);
    if (f.modes.size() <= uk) {
      f.modes.resize(uk + 1);
      f.targets.resize(uk + 1);
      f.plans.resize(uk + 1);
    }
    f.modes[uk] = std::string(mode);
    f.targets[uk] = target;
    f.plans[uk].assign(plan.begin(), plan.end());
  }
  void cells(std::string_view, std::span<const int>) override {}

  /// Action applied by UAV k at time t (i.e. during the step t → t + 1).
  sim::Action action(int k, int t) const {
    return frames.at(static_cast<std::size_t>(t + 1)).actions.at(static_cast<std::size_t>(k));
  }
  /// Mode of UAV k decided at time t.
  const std::string& mode(int k, int t) const {
    return frames.at(static_cast<std::size_t>(t + 1)).modes.at(static_cast<std::size_t>(k));
  }
  /// Last decision time.
  int last_time() const { return static_cast<int>(frames.size()) - 2; }

  std::vector<Frame> frames;

 private:
  void record(const sim::Simulator& sim, const planners::Planner& planner, bool stepped) {
    Frame f;
    f.time = sim.time();
    f.uavs.assign(sim.uavs().begin(), sim.uavs().end());
    if (stepped) f.actions.assign(sim.applied_actions().begin(), sim.applied_actions().end());
    const auto view = sim.view();
    for (int k = 0; k < view.sensed.uav_count(); ++k) {
      const auto r = view.sensed.readings(k);
      f.readings.emplace_back(r.begin(), r.end());
    }
    f.map = sim.map();
    frames.push_back(std::move(f));
    planner.annotate(*this);
  }
};

}  // namespace hullinspect::testing
