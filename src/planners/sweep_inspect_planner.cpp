// Sweep-Inspect (docs/sweep-inspect.md): the mission's start, the fleet-wide events of each step
// (detections, the prior's precision, failures) and the trace annotations. Each UAV's mode and
// its transitions are in sweep_inspect_modes.cpp; the other stages in
// sweep_inspect_{partition,sweep,targets,prior,failure}.cpp.

#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/prior_weights.hpp"
#include "hullinspect/world/no_fly.hpp"

#include "sweep_inspect_detail.hpp"

namespace hullinspect::planners {

using sweep_inspect_detail::leg_along_x;

grid::Cell SweepInspectPlanner::reach_position(int k, grid::Cell pos, grid::Cell c, int h) const {
  grid::DistanceService& distances = *uav_distances_[static_cast<std::size_t>(k)];
  const grid::Cell clamped{std::clamp(pos.x, c.x - h, c.x + h),
                           std::clamp(pos.y, c.y - h, c.y + h)};
  if (reach_ == nullptr || distances.allowed(clamped)) return clamped;
  return distances.viewpoint(c, h);
}

bool SweepInspectPlanner::reachable(int k, int i, std::uint8_t bit) const {
  if (reach_ == nullptr) return true;
  if (((*reach_)[i] & bit) == 0) return false;
  if (!flights_.split()) return true;
  const int h = bit == world::kReachZ1 ? h1_ : h2_;
  return uav_distances_[static_cast<std::size_t>(k)]->viewpoint(hull_cell(i), h) != grid::kNoCell;
}

sim::Action SweepInspectPlanner::step(int k, grid::Cell pos, grid::Cell to) const {
  return sim::move_to_neighbour(pos,
                                uav_distances_[static_cast<std::size_t>(k)]->next_step(pos, to));
}

void SweepInspectPlanner::start(const PlannerContext& context) {
  // Every distance and move comes from the mission's distance service (docs/model.md, "No-fly
  // zones"); without no-fly positions it answers Manhattan distances and the x-then-y rule.
  distances_ = &distances_of(context, own_distances_);
  // With the flight space cut into parts, each UAV flies by its own part's service.
  flights_.build(context, *distances_);
  uav_distances_.clear();
  for (int k = 0; k < context.params.uavs; ++k) uav_distances_.push_back(&flights_.of(k));
  width_ = context.hull.width();
  reach_ = context.reach != nullptr && context.reach->any_no_fly ? &context.reach->reach : nullptr;
  const auto& p = context.params;
  s1_ = p.footprint(1);
  s2_ = p.footprint(2);
  h1_ = p.half_side(1);
  h2_ = p.half_side(2);
  // An inspection takes the detections within s2 of the descent point (at least h2: a descent
  // is for a detected cell abreast, within h2 across, which must then lie within the radius, or
  // the UAV would climb at once and descend again for the same cell for ever).
  radius_ = std::max(h2_, p.s2);
  const partition::PartitionRequest request = partition_request(context, options_);
  // The plane a cell is swept on is known before the partition: the zones' statistics decide it.
  const double precision = expected_prior_precision(context);
  prior_dropped_ = options_.prior_trust > 0 && precision >= 0 && precision < options_.prior_trust;
  hull_cells_ = context.hull.cells();
  find_dense_columns(context);
  partition_ = nullptr;
  band_start_.clear();
  if (!flights_.split()) partition_ = band_partition(request, context);
  if (partition_ == nullptr) {
    // Column slabs (the stripes partitioner, weighted alike) suit column bands: a region with a
    // ragged edge costs part-column bands and turns. Where the hull has no connected slabs (a
    // column that is not one run of cells), the partitioner option's partition instead; a bad
    // request fails there as well.
    try {
      partition_ = context.partitions.get("stripes", {}, request);
    } catch (const Error&) {
      partition_ = nullptr;
    }
  }
  if (partition_ == nullptr)
    partition_ =
        context.partitions.get(options_.partitioner, options_.partitioner_options, request);
  owner_ = partition_->owner;
  const int n = p.uavs;
  uavs_.assign(static_cast<std::size_t>(n), Uav{});
  for (int k = 0; k < n; ++k) {
    Uav& uav = uavs_[static_cast<std::size_t>(k)];
    uav.sweep.assign(sweep_from(k, context.starts[static_cast<std::size_t>(k)]));
    uav.sweep.set_distances(uav_distances_[static_cast<std::size_t>(k)]);
  }
  prior_.assign(static_cast<std::size_t>(n), {});
  if (options_.prior_first && !prior_dropped_) {
    for (int i : context.hull.cells()) {
      const int owner = partition_->owner[i];
      if (context.prior[i] == 1 && reachable(owner, i, world::kReachZ1))
        prior_[static_cast<std::size_t>(owner)].push_back(i);
    }
  }
  positions_.assign(context.starts.begin(), context.starts.end());
  width_ = context.hull.width();
  tours_ = PriorTourSplitter(width_, h1_, static_cast<std::size_t>(context.hull.cell_count()));
  tour_points_.clear();
  tour_points_.reserve(static_cast<std::size_t>(context.hull.cell_count()));
  if (options_.prior_first) balance_prior_tours(context.starts);
  prior_true_ = 0;
  prior_false_ = 0;
  pending_.clear();
  pending_.reserve(static_cast<std::size_t>(context.hull.cell_count()));
  handed_over_.assign(static_cast<std::size_t>(n), 0);
  resplit_ = false;
  resplit_detection_ = grid::Grid<std::uint8_t>(width_, context.hull.height(), 0);
  split_cells_.clear();
  split_cells_.reserve(static_cast<std::size_t>(context.hull.cell_count()));
}

void SweepInspectPlanner::decide(const sim::PlannerView& view, std::span<sim::Action> actions) {
  // New detections join the pending list; inspected cells leave it.
  for (int k = 0; k < view.sensed.uav_count(); ++k) {
    for (const sim::Reading& r : view.sensed.readings(k)) {
      if ((r.events & sim::kEventDetection) != 0 && view.map[r.index] == sim::kCorrosionSeen) {
        pending_.push_back(r.index);
      }
    }
  }
  std::erase_if(pending_, [&](int i) { return view.map[i] != sim::kCorrosionSeen; });
  // The prior's precision so far, fleet-wide from the shared map: its cells found corroded
  // (inspected) against those found clean.
  for (auto& cells : prior_) {
    std::erase_if(cells, [&](int i) {
      if (view.map[i] == sim::kCorrosionSeen) return false;
      (view.map[i] == sim::kClean ? prior_false_ : prior_true_) += 1;
      return true;
    });
  }
  for (std::size_t k = 0; k < uavs_.size(); ++k) positions_[k] = view.uavs[k].pos;
  if (hand_over_prior(view) && !prior_distrusted()) {
    balance_prior_tours(positions_, &view);  // the failed UAV's cells among the neighbours
  }
  bool failure = false;
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (!view.uavs[j].failed || handed_over_[j] != 0) continue;
    handed_over_[j] = 1;
    failure = true;
  }
  if (failure) resplit(view);
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    actions[k] = decide_uav(static_cast<int>(k), view.uavs[k], view);
  }
}

bool SweepInspectPlanner::idle(const sim::PlannerView& view) const {
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    if (!view.uavs[k].failed && uavs_[k].mode != Mode::kDone) return false;
  }
  return true;
}

void SweepInspectPlanner::annotate(AnnotationSink& sink) const {
  static constexpr const char* kNames[] = {"prior", "sweep", "inspect", "return",
                                           "help",  "done",  "failed"};
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    const Uav& p = uavs_[k];
    const bool sweeping = p.mode == Mode::kSweep;
    // A dense zone's sweep at z = 1 (low-sweep-above) is told apart in the replay.
    sink.uav(static_cast<int>(k),
             sweeping && p.low ? "low sweep" : kNames[static_cast<int>(p.mode)],
             sweeping ? p.sweep.target() : p.target,
             sweeping ? p.sweep.remaining() : std::span<const grid::Cell>());
  }
}

}  // namespace hullinspect::planners
