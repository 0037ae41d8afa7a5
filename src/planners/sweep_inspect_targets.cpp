// Sweep-Inspect's single targets (docs/beyond.md, Sweep-Inspect item 6): the help phase of a UAV
// whose sweep is done, the nearest detection, unobserved cell or cluster edge a UAV may take, and
// the claims that keep two UAVs off one target (yield-claims).

#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include <algorithm>
#include <limits>

#include "hullinspect/world/no_fly.hpp"

#include "sweep_inspect_detail.hpp"

namespace hullinspect::planners {

using sweep_inspect_detail::chebyshev;
using sweep_inspect_detail::unobserved;

bool SweepInspectPlanner::claimed_by_other(int k, int cell) const {
  // A claim holds against UAVs no nearer to the cell than the claimer: a UAV that is done takes
  // over a far claimer's target instead of hovering while the claimer crosses the hull.
  if (cell < 0) return false;
  int mine = -1;
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (static_cast<int>(j) == k || uavs_[j].target_cell != cell) continue;
    if (!options_.yield_claims) return true;
    const grid::Cell c = hull_cell(cell);
    if (mine < 0) {
      mine = uav_distances_[static_cast<std::size_t>(k)]->distance(
          positions_[static_cast<std::size_t>(k)], c);
    }
    if (uav_distances_[j]->distance(positions_[j], c) <= mine) return true;
  }
  return false;
}

bool SweepInspectPlanner::may_inspect(int k, int i) const {
  return (options_.help || partition_->owner[i] == k) && reachable(k, i, world::kReachZ1) &&
         !claimed_by_other(k, i);
}

int SweepInspectPlanner::nearest_pending(int k, grid::Cell pos, grid::Cell around, int radius,
                                         const sim::PlannerView& view) const {
  int best = -1;
  int best_d = std::numeric_limits<int>::max();
  for (int i : pending_) {
    const grid::Cell c = view.map.cell(i);
    if (radius >= 0 && chebyshev(c, around) > radius) continue;
    if (!may_inspect(k, i)) continue;
    const int d =
        uav_distances_[static_cast<std::size_t>(k)]->distance(pos, reach_position(k, pos, c, h1_));
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  return best;
}

int SweepInspectPlanner::nearest_unknown(int k, grid::Cell pos,
                                         const sim::PlannerView& view) const {
  int best = -1;
  int best_d = std::numeric_limits<int>::max();
  grid::DistanceService& distances = *uav_distances_[static_cast<std::size_t>(k)];
  // Flight distances are symmetric (4-neighbour, unit steps), so one search from here gives every
  // candidate's; copied, because claimed_by_other's searches may reuse the service's cache slot.
  const bool searched = distances.has_no_fly();
  if (searched) from_here_ = distances.field(pos);
  for (int i : hull_cells_) {
    if (!unobserved(view, i)) continue;
    if (!options_.help && partition_->owner[i] != k) continue;
    if (!reachable(k, i, world::kReachZ2) || claimed_by_other(k, i)) continue;
    const grid::Cell c = view.map.cell(i);
    const grid::Cell there = reach_position(k, pos, c, h2_);
    const int d = searched ? from_here_[there] : grid::manhattan(pos, there);
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  return best;
}

int SweepInspectPlanner::nearest_cluster_edge(int k, grid::Cell pos, grid::Cell around, int radius,
                                              const sim::PlannerView& view) const {
  // Corrosion comes in rectangles: an unobserved cell beside an inspected one is likely corroded
  // too, and looking at it now from z = 1 costs a step or two, against a climb, a descent and a
  // flight back when the sweep detects it later.
  const auto& map = view.map;
  int best = -1;
  int best_d = std::numeric_limits<int>::max();
  const int x_lo = std::max(0, around.x - radius);
  const int x_hi = std::min(map.width() - 1, around.x + radius);
  const int y_lo = std::max(0, around.y - radius);
  const int y_hi = std::min(map.height() - 1, around.y + radius);
  for (int y = y_lo; y <= y_hi; ++y) {
    for (int x = x_lo; x <= x_hi; ++x) {
      const int i = map.index(x, y);
      if (!unobserved(view, i)) continue;
      const bool beside = (x > 0 && map(x - 1, y) == sim::kInspected) ||
                          (x + 1 < map.width() && map(x + 1, y) == sim::kInspected) ||
                          (y > 0 && map(x, y - 1) == sim::kInspected) ||
                          (y + 1 < map.height() && map(x, y + 1) == sim::kInspected);
      if (!beside || !reachable(k, i, world::kReachZ1) || claimed_by_other(k, i)) continue;
      const grid::Cell c{x, y};
      const int d = uav_distances_[static_cast<std::size_t>(k)]->distance(
          pos, reach_position(k, pos, c, h1_));
      if (d < best_d) {
        best_d = d;
        best = i;
      }
    }
  }
  return best;
}

sim::Action SweepInspectPlanner::help_step(int k, const sim::UavState& u,
                                           const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  // Keep a target while it is still work; else take the nearest unclaimed work anywhere:
  // detected cells first (inspected from z = 1), then unknown cells (covered from z = 2).
  // A cell taken as unknown that turned out corroded needs z = 1 now: drop it when no z = 1
  // footprint reaches it (no-fly zones).
  const bool target_done = p.target_cell < 0 ||
                           (view.map[p.target_cell] != sim::kUnknown &&
                            !(view.map[p.target_cell] == sim::kCorrosionSeen)) ||
                           (view.map[p.target_cell] == sim::kCorrosionSeen &&
                            (view.seen[p.target_cell] & sim::kSeenAtZ2) != 0 &&
                            !reachable(k, p.target_cell, world::kReachZ1));
  if (target_done || claimed_by_other(k, p.target_cell)) {
    // Detected cells first (a sweep passing abreast is not sure to), then the tail of the sweep
    // that would end last (share-sweep), then unknown cells.
    p.target_cell = nearest_pending(k, u.pos, u.pos, -1, view);
    if (p.target_cell < 0 && options_.share_sweep && take_sweep_tail(k, u, view))
      return decide_uav(k, u, view);
    if (p.target_cell < 0) p.target_cell = nearest_unknown(k, u.pos, view);
    if (p.target_cell < 0) {
      p.mode = Mode::kDone;
      return sim::Action::kHover;
    }
  }
  const grid::Cell c = view.map.cell(p.target_cell);
  // A detected cell (seen at z = 2, M = 2) needs z = 1; anything else is covered from z = 2.
  const bool inspect = view.map[p.target_cell] == sim::kCorrosionSeen &&
                       (view.seen[p.target_cell] & sim::kSeenAtZ2) != 0;
  const int want_z = inspect ? 1 : 2;
  p.target = reach_position(k, u.pos, c, inspect ? h1_ : h2_);
  if (u.z != want_z) {
    // Change plane where the work is: go there first at z = 2, climb at once from z = 1.
    if (u.z == 2 && u.pos != p.target) return step(k, u.pos, p.target);
    return sim::Action::kChangePlane;
  }
  return step(k, u.pos, p.target);
}

}  // namespace hullinspect::planners
