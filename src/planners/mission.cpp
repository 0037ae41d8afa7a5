#include "hullinspect/planners/mission.hpp"

#include <chrono>
#include <ctime>
#include <optional>

#include "hullinspect/partition/fallback.hpp"
#include "hullinspect/sim/deconfliction.hpp"
#include "hullinspect/sim/lower_bound.hpp"
#include "hullinspect/sim/sortie_layer.hpp"

namespace hullinspect::planners {

namespace {
/// CPU time of the calling thread (MissionResult::planner_seconds is the planner's CPU time: on a
/// shared machine wall time measures the other jobs as well).
struct Clock {
  using time_point = double;
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
  }
};
double seconds_since(Clock::time_point t0) {
  return Clock::now() - t0;
}
}  // namespace

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
  sim::Simulator sim(hull, instance, params, starts);
  if (!options.failures.empty()) {
    const auto times =
        world::failure_times(options.failures, params.uavs, instance.seed, params.time_limit);
    for (int k = 0; k < params.uavs; ++k) {
      if (times[static_cast<std::size_t>(k)] >= 0)
        sim.fail_uav_at(k, times[static_cast<std::size_t>(k)]);
    }
  }

  DirectPartitionSource direct;
  grid::DistanceService distances =
      world::make_distance_service(sim.reachability(), sim.flight_steps());
  PlannerContext context{hull,
                         params,
                         instance.prior,
                         starts,
                         options.partitions ? *options.partitions : direct,
                         &distances,
                         &sim.reachability()};
  if (planner.sees_truth()) context.truth = &instance.truth;
  context.corrosion = options.corrosion;
  double planner_seconds = 0;
  auto t0 = Clock::now();
  planner.start(context);
  planner_seconds += seconds_since(t0);
  for (auto* o : options.observers) o->on_start(sim, planner);

  bool stopped_idle = false;
  std::vector<sim::Action> actions(static_cast<std::size_t>(params.uavs), sim::Action::kHover);
  std::optional<sim::Deconfliction> deconfliction;
  if (params.separation > 0 && params.deconflict) {
    deconfliction.emplace(params.separation, params.uavs, hull.width(), hull.height(),
                          params.no_fly.get(), &sim.flight_steps().plane[0]);
  }
  std::optional<sim::SortieLayer> sorties;
  if (sim.battery().limited) sorties.emplace();
  std::vector<int> planned_returns;
  planned_returns.reserve(
      static_cast<std::size_t>(params.uavs));  // the step loop allocates nothing
  double layer_seconds = 0;
  const auto layer = [&](const auto& call) {
    if (options.layer_seconds == nullptr) return call();
    const auto start = Clock::now();
    call();
    layer_seconds += seconds_since(start);
  };
  while (!sim.finished()) {
    std::fill(actions.begin(), actions.end(), sim::Action::kHover);
    if (sorties) {
      planned_returns.clear();
      t0 = Clock::now();
      planner.returns(sim.view(), planned_returns);
      planner_seconds += seconds_since(t0);
      layer([&] { sorties->before_step(sim, planned_returns); });
    }
    t0 = Clock::now();
    planner.decide(sim.view(), actions);
    planner_seconds += seconds_since(t0);
    if (deconfliction) {
      layer([&] { deconfliction->adjust(sim, actions); });
      sim.step(actions, deconfliction->away_orders());
    } else {
      sim.step(actions);
    }
    for (auto* o : options.observers) o->on_step(sim, planner);
    // A planner whose working UAVs have nothing left to do will only hover: when the hull is not
    // complete (e.g. a failed UAV's region under Part-TSP), the mission cannot complete.
    // UAVs flying home to their launch sites after the hull is complete leave the planner idle.
    if (!sim.finished() && !sim.complete() && planner.idle(sim.view())) {
      stopped_idle = true;
      break;
    }
  }
  sim::MissionResult result = sim.result();
  result.stopped_idle = stopped_idle;
  const sim::LowerBound bound = sim::lower_bound(hull, instance.truth, params, starts);
  result.bound_t_c = bound.t_c;
  result.bound_t_m = bound.t_m;
  result.planner_seconds = planner_seconds;
  if (options.layer_seconds != nullptr) *options.layer_seconds += layer_seconds;
  result.planner = planner.stats();
  if (const partition::Partition* p = planner.partition(); p != nullptr && !p->fallback.empty()) {
    result.planner.partition_fallbacks = 1;
  }
  return result;
}

}  // namespace hullinspect::planners
