#include "hullinspect/planners/mission.hpp"

#include "hullinspect/partition/fallback.hpp"
#include "hullinspect/planners/mission_stepper.hpp"
#include "hullinspect/sim/lower_bound.hpp"

namespace hullinspect::planners {

std::shared_ptr<const partition::Partition> DirectPartitionSource::get(
    std::string_view partitioner, const OptionMap& options,
    const partition::PartitionRequest& request) {
  return std::make_shared<const partition::Partition>(
      partition::partition_with_fallback(partitioner, options, request));
}

void add_no_fly(partition::PartitionRequest& request, const PlannerContext& context) {
  if (context.reach != nullptr && context.reach->any_no_fly) {
    request.allowed = context.reach->flyable;
    request.seen_from = context.reach->seen_from;
  }
  if (context.distances != nullptr && context.distances->has_long_flights()) {
    request.flights = context.distances->flight_table();
  }
}

grid::DistanceService& distances_of(const PlannerContext& context,
                                    grid::DistanceService& fallback) {
  if (context.distances != nullptr) return *context.distances;
  fallback = grid::DistanceService(context.hull.width(), context.hull.height());
  return fallback;
}

sim::MissionResult run_mission(const world::HullMask& hull, const world::Instance& instance,
                               const world::MissionParams& params, Planner& planner,
                               const MissionOptions& options) {
  const auto starts = world::validate(params, hull);
  world::validate(options.failures, params.uavs);
  return run_validated_mission(hull, instance, params, starts, planner, options);
}

sim::MissionResult run_validated_mission(const world::HullMask& hull,
                                         const world::Instance& instance,
                                         const world::MissionParams& params,
                                         std::span<const grid::Cell> starts, Planner& planner,
                                         const MissionOptions& options) {
  MissionStepper mission(hull, instance, params, starts, planner, options);
  while (!mission.finished()) {
    mission.decide();
    mission.apply();
  }
  sim::MissionResult result = mission.result();
  const sim::LowerBound bound = sim::lower_bound(hull, instance.truth, params, starts);
  result.bound_t_c = bound.t_c;
  result.bound_t_m = bound.t_m;
  return result;
}

}  // namespace hullinspect::planners
