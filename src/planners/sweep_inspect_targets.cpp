// Sweep-Inspect's single targets (docs/sweep-inspect.md, "Help"): the help phase of a UAV
// whose sweep is done, the nearest detection, unobserved cell or cluster edge a UAV may take, and
// the claims that keep two UAVs off one target.

#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include <algorithm>
#include <limits>

#include "hullinspect/planners/nearer_claims.hpp"
#include "hullinspect/world/no_fly.hpp"

#include "sweep_inspect_detail.hpp"

namespace hullinspect::planners {

using sweep_inspect_detail::beside_inspected;
using sweep_inspect_detail::chebyshev;
using sweep_inspect_detail::unobserved;

bool SweepInspectPlanner::claimed_by_other(int k, int cell) const {
  if (cell < 0) return false;
  const grid::Cell c = hull_cell(cell);
  return claim_held_against(
      static_cast<int>(uavs_.size()), k, cell,
      [&](int j) { return uavs_[static_cast<std::size_t>(j)].target_cell; },
      [&](int j) {
        const auto u = static_cast<std::size_t>(j);
        return uav_distances_[u]->distance(positions_[u], c);
      });
}

bool SweepInspectPlanner::left_to_low_sweep(int k, int i) const {
  // After a re-split a survivor may fly far across the others' shares to its own (the failed
  // UAV's cells at one end of the hull shift every share along it), and at z = 2 it detects
  // corrosion in their dense columns on the way. It leaves those detections to the owner's z = 1
  // sweep, which inspects them on its way anyway (drop_observed keeps them in its share):
  // descending for each would hold the survivor back from its own share, possibly for a long
  // stretch of the hull.
  if (!resplit_) return false;
  const int j = owner_[i];
  if (j < 0 || j == k || dense_column_.empty() ||
      dense_column_[static_cast<std::size_t>(i % width_)] == 0)
    return false;
  const Uav& owner = uavs_[static_cast<std::size_t>(j)];
  const bool sweeping =
      owner.mode == Mode::kSweep || owner.mode == Mode::kInspect || owner.mode == Mode::kReturn;
  return sweeping && owner.low;
}

bool SweepInspectPlanner::may_inspect(int k, int i) const {
  if (left_to_low_sweep(k, i)) return false;
  return reachable(k, i, world::kReachZ1) && !claimed_by_other(k, i);
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
  // Flight distances are symmetric (4-neighbour, each flight as long both ways), so one search from
  // here gives every candidate's; copied, because claimed_by_other's searches may reuse the
  // service's cache slot.
  const bool searched = distances.searched();
  if (searched) from_here_ = distances.field(pos);
  for (int i : hull_cells_) {
    if (!unobserved(view, i)) continue;
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

bool SweepInspectPlanner::cluster_edge(int k, int x, int y, const sim::PlannerView& view) const {
  const int i = view.map.index(x, y);
  return unobserved(view, i) && beside_inspected(view.map, x, y) &&
         reachable(k, i, world::kReachZ1) && !claimed_by_other(k, i);
}

grid::Cell SweepInspectPlanner::inspection_viewpoint(int k, grid::Cell pos, grid::Cell around,
                                                     int radius, grid::Cell held, int& cell,
                                                     const sim::PlannerView& view) {
  // The z = 1 footprint takes in every cell within h1 of the UAV, a rectangle's cells several at
  // a time, so the viewpoint is chosen by the work it takes in, not by the nearest cell: flying
  // to the nearest cell's nearest viewpoint, chosen anew each step, sees a cluster one edge at a
  // time and turns back and forth over it. Work: the detections it may inspect
  // within `radius` of `around` and the unobserved cells beside inspected
  // ones; every cell counts one. A position is worth the work its footprint takes in per step of
  // the flight there (plus one, so that a far position taking in much beats a near one taking in
  // little only by enough).
  const auto& map = view.map;
  const int x0 = std::max(0, around.x - radius - h1_);
  const int x1 = std::min(map.width() - 1, around.x + radius + h1_);
  const int y0 = std::max(0, around.y - radius - h1_);
  const int y1 = std::min(map.height() - 1, around.y + radius + h1_);
  const int w = x1 - x0 + 1;
  const int h = y1 - y0 + 1;
  const auto at = [&](int x, int y) { return static_cast<std::size_t>((y - y0) * w + (x - x0)); };
  view_work_.assign(static_cast<std::size_t>(w * h), 0);
  cell = -1;
  bool any = false;
  for (int i : pending_) {
    const grid::Cell c = map.cell(i);
    if (chebyshev(c, around) > radius || !may_inspect(k, i)) continue;
    view_work_[at(c.x, c.y)] += 1;
    any = true;
  }
  for (int y = std::max(0, around.y - radius); y <= std::min(y1, around.y + radius); ++y) {
    for (int x = std::max(0, around.x - radius); x <= std::min(x1, around.x + radius); ++x) {
      if (!cluster_edge(k, x, y, view)) continue;
      view_work_[at(x, y)] += 1;
      any = true;
    }
  }
  if (!any) return grid::kNoCell;
  // sums(x, y): the work at window positions below and left of (x, y), exclusive.
  view_work_sums_.assign(static_cast<std::size_t>((w + 1) * (h + 1)), 0);
  const auto sums = [&](int x, int y) -> int& {
    return view_work_sums_[static_cast<std::size_t>(y * (w + 1) + x)];
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      sums(x + 1, y + 1) = view_work_[static_cast<std::size_t>(y * w + x)] + sums(x, y + 1) +
                           sums(x + 1, y) - sums(x, y);
    }
  }
  const auto taken_in = [&](grid::Cell v) {
    const int xa = std::max(x0, v.x - h1_) - x0;
    const int xb = std::min(x1, v.x + h1_) - x0 + 1;
    const int ya = std::max(y0, v.y - h1_) - y0;
    const int yb = std::min(y1, v.y + h1_) - y0 + 1;
    return sums(xb, yb) - sums(xa, yb) - sums(xb, ya) + sums(xa, ya);
  };
  const auto inside = [&](grid::Cell v) {
    return v.x >= x0 && v.x <= x1 && v.y >= y0 && v.y <= y1;
  };
  grid::DistanceService& distances = *uav_distances_[static_cast<std::size_t>(k)];
  grid::Cell best = grid::kNoCell;
  if (held != pos && inside(held) && taken_in(held) > 0) {
    best = held;  // held until reached: choosing anew each step turned back and forth
  } else {
    double best_worth = 0.0;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const grid::Cell v{x, y};
        const int work = taken_in(v);
        if (work == 0 || v == pos) continue;
        if (reach_ != nullptr && !distances.allowed(v)) continue;
        // distance(a, b) searches from b: one search from here for every position.
        const int d = reach_ == nullptr ? grid::manhattan(pos, v) : distances.distance(v, pos);
        if (d == grid::kUnreachable) continue;
        const double worth = static_cast<double>(work) / (d + 1);
        if (worth > best_worth) {
          best_worth = worth;
          best = v;
        }
      }
    }
  }
  if (best == grid::kNoCell) return best;
  for (int y = std::max(y0, best.y - h1_); y <= std::min(y1, best.y + h1_) && cell < 0; ++y) {
    for (int x = std::max(x0, best.x - h1_); x <= std::min(x1, best.x + h1_); ++x) {
      if (view_work_[at(x, y)] > 0) {
        cell = map.index(x, y);
        break;
      }
    }
  }
  return best;
}

std::optional<sim::Action> SweepInspectPlanner::help_step(int k, const sim::UavState& u,
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
    // that would end last, then unknown cells.
    p.target_cell = nearest_pending(k, u.pos, u.pos, -1, view);
    if (p.target_cell < 0 && take_sweep_tail(k, u, view)) return std::nullopt;  // now sweeping
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
