// Sweep-Inspect's choice of single targets: the nearest detection, unobserved cell or cluster edge
// a UAV may take, and the claims that keep two UAVs off one target (yield-claims).

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

int SweepInspectPlanner::nearest_pending(int k, grid::Cell pos, grid::Cell around, int radius,
                                         const sim::PlannerView& view) const {
  int best = -1;
  int best_d = std::numeric_limits<int>::max();
  for (int i : pending_) {
    const grid::Cell c = view.map.cell(i);
    if (radius >= 0 && chebyshev(c, around) > radius) continue;
    if (!options_.help && partition_->owner[i] != k) continue;
    if (!reachable(k, i, world::kReachZ1) || claimed_by_other(k, i)) continue;
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

}  // namespace hullinspect::planners
