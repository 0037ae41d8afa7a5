#include "hullinspect/planners/part_tsp_planner.hpp"

#include <algorithm>
#include <chrono>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/part_tsp_share.hpp"
#include "hullinspect/planners/prior_weights.hpp"

namespace hullinspect::planners {

using part_tsp::divide_into_segments;
using part_tsp::evaluate_fsm;
using part_tsp::flight_field;
using part_tsp::FsmDecision;
using part_tsp::FsmInput;
using part_tsp::has_targets;
using part_tsp::helper_piece;
using part_tsp::kModeAscending;
using part_tsp::kModeCoverZ1;
using part_tsp::kModeCoverZ2;
using part_tsp::kModeDescending;
using part_tsp::kModeDone;
using part_tsp::kModeFailed;
using part_tsp::kModeInspectZ1;
using part_tsp::LocalEvents;
using part_tsp::LocalMaps;
using part_tsp::PlannedVisit;
using part_tsp::region_cells;
using part_tsp::remaining_work;
using part_tsp::segment_ends;
using part_tsp::StripSegment;
using part_tsp::target_value;

PartTspPlanner::PartTspPlanner(PartTspOptions options, std::unique_ptr<tsp::TspSolver> solver)
    : options_(std::move(options)), solver_(std::move(solver)) {
  if (!solver_) solver_ = tsp::make_tsp_solver(options_.tsp_solver, options_.tsp_solver_options);
  // The exact solver's own first tour: 10 kicks, seed 1.
  large_solver_ = tsp::make_tsp_solver("heuristic", {{"kicks", "10"}, {"seed", "1"}});
}

void PartTspPlanner::start(const PlannerContext& context) {
  const partition::PartitionRequest request = partition_request(context, options_);
  partition_ = context.partitions.get(options_.partitioner, options_.partitioner_options, request);
  const int n = context.params.uavs;
  if (options_.oracle && !context.truth)
    throw LogicError("oracle-part-tsp started without the truth");
  const auto& prior = options_.oracle ? *context.truth : context.prior;
  maps_ =
      std::make_unique<LocalMaps>(partition_->owner, prior, options_.use_prior || options_.oracle,
                                  n, context.params.s1, context.params.s2);
  distances_ = &distances_of(context, own_distances_);
  if (context.reach != nullptr && context.reach->any_no_fly) maps_->write_off(context.reach->reach);
  flights_.build(context, *distances_);
  problem_.distances = distances_;
  uavs_.assign(static_cast<std::size_t>(n), UavState{});
  for (int k = 0; k < n; ++k)
    uavs_[static_cast<std::size_t>(k)].path.set_distances(&flights_.of(k));
  stats_ = {};
  failed_regions_taken_ = 0;
  pieces_taken_ = 0;
  if (options_.share_work) {
    part_of_.assign(static_cast<std::size_t>(n), 0);
    if (flights_.split()) {
      for (int k = 0; k < n; ++k) {
        part_of_[static_cast<std::size_t>(k)] =
            context.reach->flight_component[context.starts[static_cast<std::size_t>(k)]];
      }
    }
    declined_.assign(static_cast<std::size_t>(n * n), -1);
    const auto cells = static_cast<std::size_t>(context.hull.cell_count());
    share_cells_.reserve(cells);
    share_piece_.reserve(cells);
    share_order_.reserve(cells);
    helper_field_ = grid::Grid<int>(context.hull.width(), context.hull.height(), 0);
    owner_field_ = helper_field_;
  }
}

void PartTspPlanner::decide(const sim::PlannerView& view, std::span<sim::Action> actions) {
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    const int uav_id = static_cast<int>(k);
    UavState& p = uavs_[k];
    // The local map takes this UAV's own readings only (empty in transit or after a failure).
    const LocalEvents events = maps_->ingest(uav_id, view.sensed.readings(uav_id));
    if (events.detection) p.last_detection = view.time;
    if (events.inspection) p.last_inspection = view.time;
    actions[k] = decide_uav(uav_id, view.uavs[k], view.time);
    if (options_.share_work && p.mode == kModeDone && take_over(uav_id, view)) {
      actions[k] = decide_uav(uav_id, view.uavs[k], view.time);
    }
  }
}

bool PartTspPlanner::take_over(int j, const sim::PlannerView& view) {
  const auto n = uavs_.size();
  const int part = part_of_[static_cast<std::size_t>(j)];
  // A failed UAV's region first (no one else will ever do it), the one with the most work left,
  // ties to the lowest id. Its map failed with it: the region comes back as it was at the start.
  int donor = -1;
  double most = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!view.uavs[k].failed || part_of_[k] != part) continue;
    const double work = remaining_work(*maps_, static_cast<int>(k));
    if (work > most) {
      most = work;
      donor = static_cast<int>(k);
    }
  }
  if (donor >= 0) {
    region_cells(*maps_, donor, true, share_cells_);
    maps_->hand_over(share_cells_, j, true);
    ++failed_regions_taken_;
    return true;
  }
  // Else a piece of the working UAV with the most work left (ties: lowest id), unless j declined
  // it already at no less work.
  for (std::size_t k = 0; k < n; ++k) {
    if (static_cast<int>(k) == j || view.uavs[k].failed || part_of_[k] != part) continue;
    const int left = maps_->unknown_cells(static_cast<int>(k)) +
                     maps_->corrosion_to_inspect(static_cast<int>(k));
    const int declined_at = declined_[static_cast<std::size_t>(j) * n + k];
    if (declined_at >= 0 && left <= declined_at) continue;
    const double work = remaining_work(*maps_, static_cast<int>(k));
    if (work > most) {
      most = work;
      donor = static_cast<int>(k);
    }
  }
  if (donor < 0) return false;
  const auto k = static_cast<std::size_t>(donor);
  const double s2 = maps_->layout(2).s;
  // The tail of k's plan, when handing it over ends both sooner by s2 steps or more: whole
  // segments, in the order k would have flown them.
  if (!uavs_[k].path.finished()) {
    const part_tsp::SegmentPath& path = uavs_[k].path;
    const auto waypoints = path.remaining();
    const auto visits = path.visits().subspan(path.visits().size() - (waypoints.size() + 1) / 2);
    const int m = part_tsp::plan_tail(visits, waypoints, view.uavs[k].pos,
                                      view.uavs[static_cast<std::size_t>(j)].pos, s2);
    share_piece_.clear();
    for (std::size_t i = m > 0 ? static_cast<std::size_t>(m) : visits.size(); i < visits.size();
         ++i) {
      part_tsp::visit_cells(*maps_, donor, uavs_[k].plan_z, uavs_[k].plan_value, visits[i],
                            share_piece_);
    }
    std::sort(share_piece_.begin(), share_piece_.end());
    share_piece_.erase(std::unique(share_piece_.begin(), share_piece_.end()), share_piece_.end());
    if (!share_piece_.empty()) {
      maps_->hand_over(share_piece_, j, false);
      uavs_[k].path.clear();
      ++pieces_taken_;
      return true;
    }
  }
  region_cells(*maps_, donor, false, share_cells_);
  grid::DistanceService& distances = flights_.of(j);
  flight_field(distances, view.uavs[static_cast<std::size_t>(j)].pos, helper_field_);
  flight_field(distances, view.uavs[k].pos, owner_field_);
  // Else the cells relatively nearer to j. The owner's steps left: its plan, or its work at a
  // z = 2 sweep's rate if that is more (the plan covers one plane). A piece that saves it less
  // than s2 steps is not worth two replans.
  const double owner_steps = std::max(
      static_cast<double>(part_tsp::plan_length(view.uavs[k].pos, uavs_[k].path.remaining())),
      most / s2);
  const bool got = helper_piece(*maps_, share_cells_, helper_field_, owner_field_, owner_steps, s2,
                                share_order_, share_piece_);
  if (!got) {
    declined_[static_cast<std::size_t>(j) * n + k] = static_cast<int>(share_cells_.size());
    return false;
  }
  maps_->hand_over(share_piece_, j, false);
  uavs_[k].path.clear();  // the owner replans without the piece at its next decision
  ++pieces_taken_;
  return true;
}

sim::Action PartTspPlanner::decide_uav(int k, const sim::UavState& u, int time) {
  UavState& p = uavs_[static_cast<std::size_t>(k)];
  if (u.failed) {
    p.mode = kModeFailed;
    p.path.clear();
    return sim::Action::kHover;
  }
  if (u.in_transit()) {  // the FSM waits until the UAV is on a plane again
    p.mode = u.z == 2 ? kModeDescending : kModeAscending;
    return sim::Action::kHover;
  }
  const bool arrived = u.z != p.plane;  // also true at t = 0: the UAV "arrives" at its start plane
  if (arrived) {
    p.plane = u.z;
    if (u.z == 1) p.last_arrival_z1 = time;
  }
  const FsmInput in{u.z, maps_->corrosion_to_inspect(k), maps_->unknown_cells(k),
                    time - p.last_detection, time - std::max(p.last_inspection, p.last_arrival_z1)};
  switch (evaluate_fsm(in, options_.r1, options_.r2)) {
    case FsmDecision::kDone:
      p.mode = kModeDone;
      p.path.clear();
      return sim::Action::kHover;
    case FsmDecision::kChangePlane:  // the plan for the new plane is made on arrival
      p.mode = u.z == 2 ? kModeDescending : kModeAscending;
      p.path.clear();
      return sim::Action::kChangePlane;
    case FsmDecision::kStay:
      break;
  }
  p.path.advance(u.pos);
  if (options_.skip_resolved && !arrived) skip_resolved(k, u.pos);
  if (arrived || p.path.finished()) make_plan(k, u.pos, u.z);
  p.mode = u.z == 2 ? kModeCoverZ2
                    : (p.plan_value == sim::kCorrosionSeen ? kModeInspectZ1 : kModeCoverZ1);
  return p.path.next_action(u.pos);
}

void PartTspPlanner::skip_resolved(int k, grid::Cell pos) {
  UavState& p = uavs_[static_cast<std::size_t>(k)];
  while (!p.path.finished()) {
    const PlannedVisit& v = p.path.current_visit();
    const StripSegment& s = v.segment;
    // On the segment, only the columns still ahead count (the footprint swept those behind).
    const int from = p.path.on_segment() ? pos.x : s.x_left;
    const int to = p.path.on_segment() ? (v.exit.x >= v.entry.x ? s.x_right : s.x_left) : s.x_right;
    if (has_targets(*maps_, k, p.plan_z, p.plan_value, s, from, to)) return;
    p.path.skip_current_visit();
    p.path.advance(pos);
  }
}

void PartTspPlanner::make_plan(int k, grid::Cell pos, int z) {
  UavState& p = uavs_[static_cast<std::size_t>(k)];
  p.plan_z = z;
  p.plan_value = target_value(z, maps_->corrosion_to_inspect(k));
  if (p.plans++ > 0) ++stats_.replans;
  const int trim = options_.trim_ends ? world::footprint_half(maps_->layout(z).s) : 0;
  grid::DistanceService& distances = flights_.of(k);
  problem_.distances = &distances;
  if (distances.has_no_fly()) {
    part_tsp::divide_around_no_fly(*maps_, k, z, p.plan_value, trim, distances, segments_, ends_);
  } else {
    divide_into_segments(*maps_, k, z, p.plan_value, segments_);
    ends_.clear();
    for (const StripSegment& s : segments_) ends_.push_back(segment_ends(s, trim));
  }

  order_.clear();
  if (segments_.size() == 1) {
    // One segment: the optimal open path enters at the nearer end (the left one on a tie).
    const auto& [left, right] = ends_.front();
    // Distances are symmetric: a search from `pos` that stops at the two ends answers.
    const grid::Cell both[2] = {left, right};
    int to_end[2];
    distances.distances_to(pos, both, to_end);
    order_.push_back(tsp::Visit{0, to_end[1] < to_end[0]});
  } else if (segments_.size() > 1) {
    problem_.start = pos;
    problem_.segments.clear();
    for (const auto& [left, right] : ends_) problem_.segments.push_back(tsp::Segment{left, right});
    const auto t0 = std::chrono::steady_clock::now();
    const bool large = options_.tsp_max_segments > 0 &&
                       segments_.size() > static_cast<std::size_t>(options_.tsp_max_segments);
    const tsp::TspSolution solution = (large ? large_solver_ : solver_)->solve(problem_);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++stats_.tsp_solves;
    stats_.tsp_seconds += seconds;
    stats_.tsp_max_seconds = std::max(stats_.tsp_max_seconds, seconds);
    if (!solution.optimal) ++stats_.tsp_unproven;
    if (solution.fallback) ++stats_.tsp_fallbacks;
    order_.assign(solution.order.begin(), solution.order.end());
  }
  p.path.assign(segments_, ends_, order_);
  p.path.advance(pos);
}

bool PartTspPlanner::idle(const sim::PlannerView& view) const {
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    if (!view.uavs[k].failed && uavs_[k].mode != part_tsp::kModeDone) return false;
  }
  return !(options_.share_work && failed_work_reachable(view));
}

bool PartTspPlanner::failed_work_reachable(const sim::PlannerView& view) const {
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    if (!view.uavs[k].failed || remaining_work(*maps_, static_cast<int>(k)) == 0) continue;
    for (std::size_t j = 0; j < uavs_.size(); ++j) {
      if (!view.uavs[j].failed && part_of_[j] == part_of_[k]) return true;
    }
  }
  return false;
}

void PartTspPlanner::annotate(AnnotationSink& sink) const {
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    const UavState& p = uavs_[k];
    sink.uav(static_cast<int>(k), p.mode, p.path.target(), p.path.remaining());
  }
}

}  // namespace hullinspect::planners
