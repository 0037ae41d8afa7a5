#pragma once
// Runs one mission: a simulator and a planner stepped together until completion or the time limit.

#include <span>
#include <vector>

#include "hullinspect/planners/planner.hpp"
#include "hullinspect/sim/mission_result.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/world/failures.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::planners {

/// Watches a mission step by step (trace recorders, invariant checkers).
class MissionObserver {
 public:
  virtual ~MissionObserver() = default;
  /// After t = 0's sensing and planner start.
  virtual void on_start(const sim::Simulator& sim, const Planner& planner) = 0;
  /// After every step (the simulator is at the new t).
  virtual void on_step(const sim::Simulator& sim, const Planner& planner) = 0;
};

using world::UavFailure;

struct MissionOptions {
  std::vector<MissionObserver*> observers;
  /// UAV failures; random ones are drawn from the instance seed (the same for every planner).
  world::FailurePlan failures;
  PartitionSource* partitions = nullptr;  ///< nullptr: compute partitions directly
  /// The statistics the instance was drawn with, handed to the planner (PlannerContext::corrosion);
  /// nullptr: unknown. run_mission(MissionSpec) sets it unless a user map replaced C' or C.
  const world::CorrosionParams* corrosion = nullptr;
  /// When set, the CPU seconds the sortie layer and the deconfliction layer take in the mission
  /// are added to it (bench/layer_cost_bench.cpp); unset, they are not timed, which saves two
  /// clock reads a step.
  double* layer_seconds = nullptr;
};

/// Validates the parameters and failures, runs the mission and returns its result.
sim::MissionResult run_mission(const world::HullMask& hull, const world::Instance& instance,
                               const world::MissionParams& params, Planner& planner,
                               const MissionOptions& options = {});

/// run_mission for parameters and failures already validated (run_mission(MissionSpec) validates
/// the whole spec once, before it builds anything), from `starts`, the start cells that validation
/// returned: the simulator places the UAVs on them, the planner is told them and the lower bound
/// measures from them.
sim::MissionResult run_validated_mission(const world::HullMask& hull,
                                         const world::Instance& instance,
                                         const world::MissionParams& params,
                                         std::span<const grid::Cell> starts, Planner& planner,
                                         const MissionOptions& options = {});

}  // namespace hullinspect::planners
