#include "hullinspect/planners/lawnmower_planner.hpp"

#include <algorithm>

#include "hullinspect/planners/band_sweep.hpp"
#include "hullinspect/planners/lawnmower_no_fly.hpp"
#include "hullinspect/planners/prior_weights.hpp"

namespace hullinspect::planners {

std::vector<grid::Cell> LawnmowerPlanner::sweep(const grid::Grid<std::int16_t>& owner, int uav,
                                                int s1, grid::Cell from) {
  // The paper's strips are row bands from the bottom, flown from end cell to end cell.
  return band_sweep(owner, uav, s1, BandAxis::kRows, false, from);
}

void LawnmowerPlanner::start(const PlannerContext& context) {
  const partition::PartitionRequest request = partition_request(context, options_);
  partition_ = context.partitions.get(options_.partitioner, options_.partitioner_options, request);
  const int n = context.params.uavs;
  flights_.build(context, distances_of(context, own_distances_));
  followers_.assign(static_cast<std::size_t>(n), WaypointFollower{});
  climb_.assign(static_cast<std::size_t>(n), {});
  climbed_.assign(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < n; ++k) {
    auto& follower = followers_[static_cast<std::size_t>(k)];
    const grid::Cell from = context.starts[static_cast<std::size_t>(k)];
    grid::DistanceService& distances = flights_.of(k);
    // Lanes are flown straight, through any long neighbour flight (a shorter way around it would
    // leave the lane's cells unseen); only routes around no-fly zones follow the service.
    follower.set_distances(distances.has_no_fly() ? &distances : nullptr);
    if (!distances.has_no_fly() || context.reach == nullptr) {
      follower.assign(sweep(partition_->owner, k, context.params.s1, from));
      continue;
    }
    LawnmowerRoute route =
        lawnmower_route_around_no_fly(partition_->owner, k, context.params.s1, context.params.s2,
                                      from, distances, context.reach->reach);
    follower.assign(std::move(route.z1));
    climb_[static_cast<std::size_t>(k)] = std::move(route.z2);
  }
}

void LawnmowerPlanner::decide(const sim::PlannerView& view, std::span<sim::Action> actions) {
  last_.assign(view.uavs.begin(), view.uavs.end());
  for (std::size_t k = 0; k < view.uavs.size(); ++k) {
    const sim::UavState& u = view.uavs[k];
    if (u.failed || u.in_transit()) continue;
    if (climbed_[k] != 0) {  // the z = 2 leg of a route around no-fly zones
      actions[k] = u.z == 1 ? sim::Action::kHover : followers_[k].next_action(u.pos);
      continue;
    }
    if (u.z == 2) {
      actions[k] = sim::Action::kChangePlane;
      continue;
    }
    actions[k] = followers_[k].next_action(u.pos);
    if (actions[k] == sim::Action::kHover && !climb_[k].empty()) {
      climbed_[k] = 1;
      followers_[k].assign(std::move(climb_[k]));
      climb_[k].clear();
      actions[k] = sim::Action::kChangePlane;
    }
  }
}

bool LawnmowerPlanner::idle(const sim::PlannerView& view) const {
  for (std::size_t k = 0; k < view.uavs.size(); ++k) {
    const sim::UavState& u = view.uavs[k];
    if (u.failed) continue;
    if (u.in_transit() || !followers_[k].finished(u.pos)) return false;
    // Done on its plane: at z = 1 with no z = 2 leg still to fly, or at the end of that leg.
    if (climbed_[k] != 0 ? u.z != 2 : (u.z != 1 || !climb_[k].empty())) return false;
  }
  return true;
}

void LawnmowerPlanner::annotate(AnnotationSink& sink) const {
  for (std::size_t k = 0; k < followers_.size(); ++k) {
    const auto& f = followers_[k];
    const bool descending =
        k < last_.size() && climbed_[k] == 0 && (last_[k].z == 2 || last_[k].in_transit());
    const auto plan = f.remaining();
    sink.uav(static_cast<int>(k), descending ? "descend" : (plan.empty() ? "done" : "cover"),
             f.target(), plan);
  }
}

}  // namespace hullinspect::planners
