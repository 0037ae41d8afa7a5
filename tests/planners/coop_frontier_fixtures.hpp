#pragma once
// Hand-made worlds and a lock-step driver for Coop-Frontier behaviour tests.

#include <string>
#include <vector>

#include "hullinspect/planners/coop_frontier_planner.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::testing {

/// An all-hull text mask of `width` × `height` cells.
inline std::string full_mask(int width, int height) {
  std::string text;
  for (int y = 0; y < height; ++y) text += std::string(static_cast<std::size_t>(width), 'X') + "\n";
  return text;
}

/// An instance whose C and C' are 1 exactly on the given cells (0 elsewhere on the hull).
inline world::Instance hand_instance(const world::HullMask& hull,
                                     const std::vector<grid::Cell>& truth,
                                     const std::vector<grid::Cell>& prior) {
  world::Instance in;
  in.truth = grid::Grid<std::int8_t>(hull.width(), hull.height(), -1);
  for (int i : hull.cells()) in.truth[i] = 0;
  in.prior = in.truth;
  for (const auto c : truth) in.truth[c] = 1;
  for (const auto c : prior) in.prior[c] = 1;
  return in;
}

/// Drives a simulator and a planner one decision at a time (what run_mission does, opened up).
class LockStep {
 public:
  LockStep(const world::HullMask& hull, const world::Instance& instance,
           const world::MissionParams& params, planners::Planner& planner)
      : sim_(hull, instance, params),
        starts_(world::start_cells(params, hull)),
        planner_(planner),
        actions_(static_cast<std::size_t>(params.uavs), sim::Action::kHover) {
    planners::PlannerContext context{hull, params, instance.prior, starts_, partitions_};
    planner_.start(context);
  }
  /// The planner's actions for the current t (not applied yet).
  const std::vector<sim::Action>& decide() {
    std::fill(actions_.begin(), actions_.end(), sim::Action::kHover);
    planner_.decide(sim_.view(), actions_);
    return actions_;
  }
  /// Applies the last decided actions.
  void step() { sim_.step(actions_); }
  const sim::Simulator& sim() const { return sim_; }
  sim::Simulator& sim() { return sim_; }
  const std::vector<sim::Action>& actions() const { return actions_; }

 private:
  sim::Simulator sim_;
  std::vector<grid::Cell> starts_;
  planners::DirectPartitionSource partitions_;
  planners::Planner& planner_;
  std::vector<sim::Action> actions_;
};

}  // namespace hullinspect::testing
