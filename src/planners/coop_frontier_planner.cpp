#include "hullinspect/planners/coop_frontier_planner.hpp"

#include <algorithm>
#include <cmath>

#include "hullinspect/planners/coop_frontier_utilities.hpp"

namespace hullinspect::planners {

using sim::Action;

namespace {
/// Levels of the d_HP floor: farther than this, a frontier's prior term is below α / 64.
constexpr int kFloorLevels = 64;
}  // namespace

void CoopFrontierPlanner::start(const PlannerContext& context) {
  const auto& prior = context.prior;
  const int w = prior.width();
  const int h = prior.height();
  const int n = context.params.uavs;
  width_ = w;
  radius_ = static_cast<int>(
      std::floor(options_.radius_factor * context.params.delta_zeta_cells() + 1e-9));

  distances_ = &distances_of(context, own_distances_);
  // With the flight space cut into parts, each UAV flies by its own part's service and only takes
  // work its part can see (docs/model.md §8).
  flights_.build(context, *distances_);
  uav_distances_.clear();
  for (int k = 0; k < n; ++k) uav_distances_.push_back(&flights_.of(k));
  needing_distances_.clear();
  needing_distances_.reserve(static_cast<std::size_t>(n));
  reach_ = context.reach != nullptr && context.reach->any_no_fly ? &context.reach->reach : nullptr;
  half1_ = context.params.half_side(1);
  half2_ = context.params.half_side(2);

  // M before t = 0's sensing: −1 off the hull, 2 where the prior expects corrosion, 0 elsewhere;
  // cells written off by no-fly zones read 1 (see effective()).
  grid::Grid<std::int8_t>& map = map_;
  map = grid::Grid<std::int8_t>(w, h, sim::kUnknown);
  known_.assign(static_cast<std::size_t>(prior.size()), 0);
  absorbed_.assign(static_cast<std::size_t>(prior.size()), 0);
  prior_field_.reset(w, h, distances_);
  detected_field_.reset(w, h, distances_);
  prior_floor_.reset(prior.size(), kFloorLevels);
  corrosion_left_.reset(w, h);
  for (int i = 0; i < prior.size(); ++i) {
    if (prior[i] < 0) {
      map[i] = sim::kNotHull;
    } else {
      map[i] = effective(i, prior[i] == 1 ? sim::kCorrosionSeen : sim::kUnknown);
      if (prior[i] == 1 && (reach_ == nullptr || ((*reach_)[i] & world::kReachZ2) != 0)) {
        prior_field_.set(i, true);
      }
      if (map[i] == sim::kCorrosionSeen) corrosion_left_.insert(i);
    }
    known_[static_cast<std::size_t>(i)] = map[i] != sim::kUnknown ? 1 : 0;
  }
  frontiers_.reset(map);
  claims_.reset(n, w, h);

  const Mode first = context.params.start_z == 2 ? Mode::kExplore : Mode::kInspect;
  uavs_.assign(static_cast<std::size_t>(n), UavPlan{first, {-1, -1}, false});

  assigner_.configure(options_.beta, context.params.s2, w + h);
  assigner_.set_distances(distances_);
  assigner_.reserve(prior.size(), n);
  joined_.clear();
  joined_.reserve(static_cast<std::size_t>(prior.size()));
  held_.clear();
  held_.reserve(static_cast<std::size_t>(n));
  needing_pos_.clear();
  needing_pos_.reserve(static_cast<std::size_t>(n));
  needing_uav_.clear();
  needing_uav_.reserve(static_cast<std::size_t>(n));
  chosen_.assign(static_cast<std::size_t>(n), -1);
  assignments_ = 0;
}

std::optional<grid::Cell> CoopFrontierPlanner::target(int uav) const {
  const auto& p = uavs_[static_cast<std::size_t>(uav)];
  if (!p.has_target()) return std::nullopt;
  return p.target;
}

std::int8_t CoopFrontierPlanner::effective(int index, std::int8_t m) const {
  if (reach_ == nullptr || m == sim::kNotHull) return m;
  const std::uint8_t reach = (*reach_)[index];
  if ((reach & world::kReachZ2) == 0) return sim::kClean;  // never seen: nothing to explore
  if (m == sim::kCorrosionSeen && (reach & world::kReachZ1) == 0) return sim::kClean;
  return m;
}

grid::Cell CoopFrontierPlanner::step_to(int uav, grid::Cell pos, grid::Cell target, int z) {
  grid::DistanceService& distances = *uav_distances_[static_cast<std::size_t>(uav)];
  const grid::Cell at = distances.viewpoint(target, z == 1 ? half1_ : half2_);
  if (at == grid::kNoCell) return pos;
  return distances.next_step(pos, at);
}

bool CoopFrontierPlanner::sees(int uav, int index, int half) {
  return !flights_.split() || uav_distances_[static_cast<std::size_t>(uav)]->viewpoint(
                                  map_.cell(index), half) != grid::kNoCell;
}

const grid::Grid<int>* CoopFrontierPlanner::field_from(int uav, grid::Cell pos) {
  grid::DistanceService& distances = *uav_distances_[static_cast<std::size_t>(uav)];
  return distances.searched() ? &distances.field(pos) : nullptr;
}

void CoopFrontierPlanner::absorb_readings(const sim::PlannerView& view) {
  auto& map = map_;
  const int n = view.sensed.uav_count();
  for (int k = 0; k < n; ++k) {
    for (const sim::Reading& r : view.sensed.readings(k)) {
      const int i = r.index;
      const std::int8_t m = effective(i, view.map[i]);
      // A cell read before with the same value needs nothing: everything below depends only on
      // m once a reading has been taken in (most readings see cells already seen).
      auto& absorbed = absorbed_[static_cast<std::size_t>(i)];
      if (absorbed != 0 && map[i] == m) continue;
      absorbed = 1;
      map[i] = m;
      auto& known = known_[static_cast<std::size_t>(i)];
      if (!known && m != sim::kUnknown) {
        known = 1;
        frontiers_.on_known(i, map);
      }
      prior_field_.set(i, false);  // a reading means the cell has been seen
      detected_field_.set(i, m == sim::kCorrosionSeen);
      if (m == sim::kCorrosionSeen) {
        corrosion_left_.insert(i);
      } else {
        corrosion_left_.erase(i);
      }
    }
  }
}

bool CoopFrontierPlanner::claim_detections(int uav, const sim::PlannerView& view) {
  bool claimed = false;
  for (const sim::Reading& r : view.sensed.readings(uav)) {
    if ((r.events & sim::kEventDetection) && map_[r.index] == sim::kCorrosionSeen &&
        sees(uav, r.index, half1_)) {
      claimed = claims_.claim(uav, r.index) || claimed;
    }
  }
  return claimed;
}

std::optional<grid::Cell> CoopFrontierPlanner::claim_nearest_free(int uav, grid::Cell pos) {
  std::optional<grid::Cell> best;
  int best_d = 0;
  int best_index = -1;
  const auto indices = corrosion_left_.indices();
  const auto cells = corrosion_left_.cells();
  const grid::Grid<int>* field = field_from(uav, pos);
  for (std::size_t j = 0; j < cells.size(); ++j) {
    if (claims_.owner(indices[j]) >= 0 || !sees(uav, indices[j], half1_)) continue;
    const int d = field != nullptr ? (*field)[cells[j]] : grid::manhattan(pos, cells[j]);
    if (!best || d < best_d || (d == best_d && cells[j] < *best)) {
      best = cells[j];
      best_d = d;
      best_index = indices[j];
    }
  }
  if (best) claims_.claim(uav, best_index);
  return best;
}

int CoopFrontierPlanner::prior_floor() {
  frontiers_.take_joined(joined_);
  for (const int i : joined_) prior_floor_.add(i);
  if (prior_field_.empty()) return grid::kUnreachable;  // the term is 0 for every frontier
  return prior_floor_.lowest([&](int i) { return frontiers_.contains(i); },
                             [&](int i) { return prior_field_.distance(i); });
}

void CoopFrontierPlanner::assign_frontiers() {
  // A term with zero weight needs no field (α = 1, the tuned default, never reads d_C).
  const bool use_prior = options_.alpha > 0.0;
  const bool use_detected = options_.alpha < 1.0;
  if (use_prior) prior_field_.refresh();
  if (use_detected) detected_field_.refresh();
  const FieldUtilities utilities(
      options_.alpha, options_.base_utility, frontiers_.indices(), width_,
      use_prior ? &prior_field_ : nullptr, use_detected ? &detected_field_ : nullptr,
      use_prior ? prior_floor() : grid::kUnreachable, !distances_->searched());
  if (flights_.split()) assigner_.set_robot_distances(needing_distances_, half2_);
  assigner_.assign(frontiers_.members(), utilities, held_, needing_pos_,
                   std::span<int>(chosen_).first(needing_pos_.size()));
  const auto cells = frontiers_.cells();
  for (std::size_t r = 0; r < needing_uav_.size(); ++r) {
    if (chosen_[r] < 0) continue;  // its part of the flight space sees no frontier: it waits
    uavs_[static_cast<std::size_t>(needing_uav_[r])].target =
        cells[static_cast<std::size_t>(chosen_[r])];
  }
  assignments_ += static_cast<long long>(needing_uav_.size());
}

void CoopFrontierPlanner::start_end_game(const sim::PlannerView& view, std::span<Action> actions) {
  // F is empty: every EXPLORE UAV that needs a target takes the nearest M = 2 cell nobody has
  // claimed (in UAV id order), claims it and descends; with none left it hovers.
  for (const int k : needing_uav_) {
    auto& plan = uavs_[static_cast<std::size_t>(k)];
    if (const auto cell = claim_nearest_free(k, view.uavs[static_cast<std::size_t>(k)].pos)) {
      plan.mode = Mode::kInspect;
      plan.target = *cell;
      actions[static_cast<std::size_t>(k)] = Action::kChangePlane;
    }
  }
}

void CoopFrontierPlanner::decide(const sim::PlannerView& view, std::span<Action> actions) {
  absorb_readings(view);
  held_.clear();
  needing_pos_.clear();
  needing_uav_.clear();
  needing_distances_.clear();

  // Mode changes and INSPECT moves; collect the EXPLORE UAVs that keep or need a frontier.
  for (std::size_t k = 0; k < view.uavs.size(); ++k) {
    const sim::UavState& u = view.uavs[k];
    UavPlan& plan = uavs_[k];
    const int id = static_cast<int>(k);
    if (u.failed) {
      if (plan.mode != Mode::kFailed) claims_.release_all(id);
      plan = {Mode::kFailed, {-1, -1}, false};
      continue;
    }
    if (u.in_transit()) continue;
    if (u.z == 2) {
      if (plan.mode == Mode::kExplore && claim_detections(id, view)) plan.mode = Mode::kInspect;
      if (plan.mode == Mode::kInspect) {
        // Descend; the target is chosen on arrival at z = 1.
        plan.target = {-1, -1};
        actions[k] = Action::kChangePlane;
        continue;
      }
      const bool keeps =
          plan.has_target() && plan.target != u.pos && frontiers_.contains(map_.index(plan.target));
      if (keeps) {
        held_.push_back(plan.target);
      } else {
        plan.target = {-1, -1};
        needing_pos_.push_back(u.pos);
        needing_uav_.push_back(id);
        needing_distances_.push_back(uav_distances_[k]);
      }
      continue;
    }
    // z = 1.
    if (plan.mode == Mode::kInspect) {
      auto cell = claims_.inspect_target(id, u.pos, map_, radius_, field_from(id, u.pos));
      if (!cell && options_.endgame_stay_low && frontiers_.empty()) {
        cell = claim_nearest_free(id, u.pos);
      }
      if (cell) {
        plan.target = *cell;
        actions[k] = sim::move_to_neighbour(u.pos, step_to(id, u.pos, *cell, 1));
        continue;
      }
      plan.mode = Mode::kExplore;
    }
    // Nothing left to inspect close by: ascend and explore.
    plan.target = {-1, -1};
    actions[k] = Action::kChangePlane;
  }

  if (!needing_uav_.empty()) {
    if (frontiers_.empty()) {
      start_end_game(view, actions);
    } else {
      assign_frontiers();
    }
  }

  for (std::size_t k = 0; k < view.uavs.size(); ++k) {
    const sim::UavState& u = view.uavs[k];
    const UavPlan& plan = uavs_[k];
    if (plan.mode == Mode::kExplore && plan.has_target() && !u.failed && !u.in_transit() &&
        u.z == 2) {
      actions[k] =
          sim::move_to_neighbour(u.pos, step_to(static_cast<int>(k), u.pos, plan.target, 2));
    }
    uavs_[k].changing_plane = u.in_transit() || actions[k] == Action::kChangePlane;
  }
}

sim::PlannerStats CoopFrontierPlanner::stats() const {
  sim::PlannerStats s;
  s.assignments = assignments_;
  return s;
}

void CoopFrontierPlanner::annotate(AnnotationSink& sink) const {
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    const UavPlan& plan = uavs_[k];
    std::string_view mode = "idle";
    if (plan.mode == Mode::kFailed) {
      mode = "idle";
    } else if (plan.changing_plane) {
      mode = "transit";
    } else if (plan.mode == Mode::kInspect) {
      mode = "inspect";
    } else if (plan.has_target()) {
      mode = "explore";
    }
    const std::span<const grid::Cell> plan_cells =
        plan.has_target() ? std::span<const grid::Cell>(&plan.target, 1)
                          : std::span<const grid::Cell>();
    sink.uav(static_cast<int>(k), mode, plan.target, plan_cells);
  }
  sink.cells("frontiers", frontiers_.indices());
}

}  // namespace hullinspect::planners
