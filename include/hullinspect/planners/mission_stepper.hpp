#pragma once
// One mission, one step at a time: the simulator, the planner's context (the distance service and
// reachability of the mission), the flight layers (sorties, deconfliction) and the planner's CPU
// time. run_validated_mission() steps it to the end; a live session (python/session.hpp) steps it
// as the cameras' readings arrive. The one place a simulator and a planner are put together.

#include <optional>
#include <span>
#include <vector>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/sim/deconfliction.hpp"
#include "hullinspect/sim/mission_result.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/sim/sortie_layer.hpp"

namespace hullinspect::planners {

class MissionStepper {
 public:
  /// Places the UAVs on `starts` and senses t = 0 from `instance.truth` (read again at every step,
  /// so a caller may write cells into it before apply()), schedules `options.failures`, starts
  /// `planner` on the mission's context and tells the observers. `params`, `starts` and the
  /// failures must be valid; `instance`, `planner` and the observers must outlive the stepper.
  MissionStepper(const world::HullMask& hull, const world::Instance& instance,
                 const world::MissionParams& params, std::span<const grid::Cell> starts,
                 Planner& planner, const MissionOptions& options);
  MissionStepper(const MissionStepper&) = delete;
  MissionStepper& operator=(const MissionStepper&) = delete;
  /// Adds the layers' CPU seconds to MissionOptions::layer_seconds when it was set.
  ~MissionStepper();

  /// The actions of the next step, one per UAV: the sortie layer sends UAVs home, the planner
  /// decides, the deconfliction layer adjusts. Call once before each apply().
  std::span<const sim::Action> decide();
  /// Flies the actions decide() returned, tells the observers, and stops the mission when the
  /// planner is idle while the hull is not complete (it would only hover until the time limit).
  void apply();

  /// At the time limit, complete (and landed), no UAV left, or stopped idle.
  bool finished() const { return stopped_idle_ || sim_.finished(); }
  const sim::Simulator& simulator() const { return sim_; }
  /// For a caller that reports failures as they happen (Simulator::fail_uav_at before apply()).
  sim::Simulator& simulator() { return sim_; }

  /// The mission so far: the simulator's result with the planner's CPU time and statistics and
  /// whether it stopped idle (no lower bound: the truth may still be unknown).
  sim::MissionResult result() const;

 private:
  sim::Simulator sim_;
  Planner& planner_;
  std::vector<MissionObserver*> observers_;
  DirectPartitionSource direct_partitions_;
  grid::DistanceService distances_;
  std::optional<sim::Deconfliction> deconfliction_;
  std::optional<sim::SortieLayer> sorties_;
  std::vector<sim::Action> actions_;
  std::vector<int> planned_returns_;  // reserved once: the step loop allocates nothing
  /// Runs one layer's call, timed only when the caller asked for the layers' CPU (two clock
  /// reads a step otherwise saved).
  template <typename Call>
  void time_layer(const Call& call) {
    if (layer_seconds_out_ == nullptr) return call();
    const double start = thread_seconds();
    call();
    layer_seconds_ += thread_seconds() - start;
  }
  static double thread_seconds();

  double planner_seconds_ = 0;
  double* layer_seconds_out_ = nullptr;
  double layer_seconds_ = 0;
  bool stopped_idle_ = false;
};

}  // namespace hullinspect::planners
