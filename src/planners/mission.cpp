#include "hullinspect/planners/mission.hpp"

#include <chrono>

namespace hullinspect::planners {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
}  // namespace

std::shared_ptr<const partition::Partition> DirectPartitionSource::get(
    std::string_view partitioner, const OptionMap& options, const partition::PartitionRequest& request) {
  auto p = partition::make_partitioner(partitioner, options);
  return std::make_shared<const partition::Partition>(p->partition(request));
}

void add_no_fly(partition::PartitionRequest& request, const PlannerContext& context) {
  if (context.reach != nullptr && context.reach->any_no_fly) request.allowed = context.reach->flyable;
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
  world::validate(params, hull);
  sim::Simulator sim(hull, instance, params);
  for (const auto& f : options.failures) sim.fail_uav_at(f.uav, f.time);

  DirectPartitionSource direct;
  const auto starts = world::start_cells(params, hull);
  grid::DistanceService distances = world::make_distance_service(sim.reachability());
  PlannerContext context{hull,
                         params,
                         instance.prior,
                         starts,
                         options.partitions ? *options.partitions : direct,
                         &distances,
                         &sim.reachability()};
  double planner_seconds = 0;
  auto t0 = Clock::now();
  planner.start(context);
  planner_seconds += seconds_since(t0);
  for (auto* o : options.observers) o->on_start(sim, planner);

  std::vector<sim::Action> actions(static_cast<std::size_t>(params.uavs), sim::Action::kHover);
  while (!sim.finished()) {
    std::fill(actions.begin(), actions.end(), sim::Action::kHover);
    t0 = Clock::now();
    planner.decide(sim.view(), actions);
    planner_seconds += seconds_since(t0);
    sim.step(actions);
    for (auto* o : options.observers) o->on_step(sim, planner);
  }
  sim::MissionResult result = sim.result();
  result.planner_seconds = planner_seconds;
  result.planner = planner.stats();
  return result;
}

}  // namespace hullinspect::planners
