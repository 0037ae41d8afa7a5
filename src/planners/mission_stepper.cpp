#include "hullinspect/planners/mission_stepper.hpp"

#include <algorithm>
#include <ctime>

#include "hullinspect/world/failures.hpp"

namespace hullinspect::planners {

/// CPU time of the calling thread (MissionResult::planner_seconds is the planner's CPU time: on a
/// shared machine wall time measures the other jobs as well).
double MissionStepper::thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

MissionStepper::MissionStepper(const world::HullMask& hull, const world::Instance& instance,
                               const world::MissionParams& params,
                               std::span<const grid::Cell> starts, Planner& planner,
                               const MissionOptions& options)
    : sim_(hull, instance, params, starts),
      planner_(planner),
      observers_(options.observers),
      distances_(world::make_distance_service(sim_.reachability(), sim_.flight_steps())),
      actions_(static_cast<std::size_t>(params.uavs), sim::Action::kHover),
      layer_seconds_out_(options.layer_seconds) {
  if (!options.failures.empty()) {
    const auto times =
        world::failure_times(options.failures, params.uavs, instance.seed, params.time_limit);
    for (int k = 0; k < params.uavs; ++k) {
      if (times[static_cast<std::size_t>(k)] >= 0)
        sim_.fail_uav_at(k, times[static_cast<std::size_t>(k)]);
    }
  }
  PlannerContext context{hull,
                         params,
                         instance.prior,
                         starts,
                         options.partitions ? *options.partitions : direct_partitions_,
                         &distances_,
                         &sim_.reachability()};
  if (planner_.sees_truth()) context.truth = &instance.truth;
  context.corrosion = options.corrosion;
  const double t0 = thread_seconds();
  planner_.start(context);
  planner_seconds_ += thread_seconds() - t0;
  for (auto* o : observers_) o->on_start(sim_, planner_);

  if (params.separation > 0 && params.deconflict) {
    deconfliction_.emplace(params.separation, params.uavs, hull.width(), hull.height(),
                           params.no_fly.get(), &sim_.flight_steps().plane[0]);
  }
  if (sim_.battery().limited) sorties_.emplace();
  planned_returns_.reserve(static_cast<std::size_t>(params.uavs));
}

std::span<const sim::Action> MissionStepper::decide() {
  std::fill(actions_.begin(), actions_.end(), sim::Action::kHover);
  if (sorties_) {
    planned_returns_.clear();
    const double t0 = thread_seconds();
    planner_.returns(sim_.view(), planned_returns_);
    planner_seconds_ += thread_seconds() - t0;
    time_layer([&] { sorties_->before_step(sim_, planned_returns_); });
  }
  const double t0 = thread_seconds();
  planner_.decide(sim_.view(), actions_);
  planner_seconds_ += thread_seconds() - t0;
  if (deconfliction_) time_layer([&] { deconfliction_->adjust(sim_, actions_); });
  return actions_;
}

void MissionStepper::apply() {
  if (deconfliction_) {
    sim_.step(actions_, deconfliction_->away_orders());
  } else {
    sim_.step(actions_);
  }
  for (auto* o : observers_) o->on_step(sim_, planner_);
  // A planner whose working UAVs have nothing left to do will only hover: when the hull is not
  // complete (e.g. a failed UAV's region under Part-TSP), the mission cannot complete.
  // UAVs flying home to their launch sites after the hull is complete leave the planner idle.
  if (!sim_.finished() && !sim_.complete() && planner_.idle(sim_.view())) stopped_idle_ = true;
}

MissionStepper::~MissionStepper() {
  if (layer_seconds_out_ != nullptr) *layer_seconds_out_ += layer_seconds_;
}

sim::MissionResult MissionStepper::result() const {
  sim::MissionResult result = sim_.result();
  result.stopped_idle = stopped_idle_;
  result.planner_seconds = planner_seconds_;
  result.planner = planner_.stats();
  if (const partition::Partition* p = planner_.partition(); p != nullptr && !p->fallback.empty()) {
    result.planner.partition_fallbacks = 1;
  }
  return result;
}

}  // namespace hullinspect::planners
