// Sweep-Inspect's tours of the prior's cells at z = 1 (docs/sweep-inspect.md, "The prior" and
// "Failures"): the planned tour, its estimate, and the re-splits that end neighbours' tours
// together, also of a failed UAV's cells.

#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "hullinspect/planners/open_tour.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::planners {

bool SweepInspectPlanner::hand_over_prior(const sim::PlannerView& view) {
  bool handed = false;
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (!view.uavs[j].failed || prior_[j].empty()) continue;
    handed = true;
    for (int i : prior_[j]) {
      const grid::Cell c = view.map.cell(i);
      int best = -1;
      int best_d = std::numeric_limits<int>::max();
      for (std::size_t k = 0; k < uavs_.size(); ++k) {
        if (view.uavs[k].failed || !reachable(static_cast<int>(k), i, world::kReachZ1)) continue;
        const int d = uav_distances_[k]->distance(
            view.uavs[k].pos, reach_position(static_cast<int>(k), view.uavs[k].pos, c, h1_));
        if (d < best_d) {
          best_d = d;
          best = static_cast<int>(k);
        }
      }
      if (best < 0) continue;
      prior_[static_cast<std::size_t>(best)].push_back(i);
      forget_tour(best);
    }
    prior_[j].clear();
  }
  return handed;
}

int SweepInspectPlanner::next_of_tour(int k, grid::Cell from, std::span<const int> cells,
                                      const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (p.repaired) {
    // A long tour is repaired when its cells are seen, not planned again: they leave it (a prior
    // cell leaves `cells` exactly when it is no longer a detection to inspect) and the rest keep
    // their order. Planning it anew each time the cell flown to was seen made the planning time
    // grow with the cube of the hull.
    while (p.tour_next < p.tour.size() && view.map[p.tour[p.tour_next]] != sim::kCorrosionSeen)
      ++p.tour_next;
    if (p.tour_next < p.tour.size()) return p.tour[p.tour_next];
  }
  // The tour's end is free (not pulled towards the sweep after it): the sweep is planned from
  // wherever the tour ends.
  const OpenTourCost cost{.reach = h1_};
  if (!p.tour.empty() && repair_tour(p, cells.size(), view)) {
    // A short tour is repaired where it changed (the UAV moved on, cells left it): the rest may
    // be ordered better from where it is.
    repair_open_tour(from, tour_points_, tour_touched_, cost);
  } else {
    tour_points_.clear();
    for (const int i : cells) tour_points_.push_back(hull_cell(i));
    plan_open_tour(from, tour_points_, cost);
  }
  p.tour.clear();
  for (const grid::Cell c : tour_points_) p.tour.push_back(c.y * width_ + c.x);
  p.tour_next = 0;
  p.repaired = cells.size() > kReplannedTourCells;
  return p.tour.front();
}

bool SweepInspectPlanner::repair_tour(const Uav& p, std::size_t cells,
                                      const sim::PlannerView& view) {
  tour_points_.clear();
  tour_touched_.assign({0, 1});  // the start moved: its edge changed
  bool dropped = false;
  for (const int i : p.tour) {
    if (view.map[i] != sim::kCorrosionSeen) {
      dropped = true;
      continue;
    }
    if (dropped) {  // the nodes on either side of the gap (node i ≥ 1 is tour_points_[i − 1])
      tour_touched_.push_back(tour_points_.size());
      tour_touched_.push_back(tour_points_.size() + 1);
      dropped = false;
    }
    tour_points_.push_back(hull_cell(i));
  }
  // Its cells are the prior cells left (any re-assignment forgot the tour); else plan anew.
  return !tour_points_.empty() && tour_points_.size() == cells;
}

PriorTourSplitter::Split SweepInspectPlanner::split_tours(int a, grid::Cell pa, int b,
                                                          grid::Cell pb, std::vector<int>& cells) {
  // No-fly zones: cells only a can inspect go to a, cells only b can inspect to b.
  return tours_.split(pa, pb, cells, [&](int i) {
    const bool to_a = reachable(a, i, world::kReachZ1);
    const bool to_b = reachable(b, i, world::kReachZ1);
    return to_a == to_b ? 0 : to_a ? -1 : 1;
  });
}

bool SweepInspectPlanner::take_prior_share(int k, grid::Cell pos) {
  // The working UAV of k's flight part with the longest tour of the prior's cells left.
  const std::size_t ku = static_cast<std::size_t>(k);
  int giver = -1;
  int giver_steps = 0;
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (j == ku || uavs_[j].mode != Mode::kPrior || prior_[j].empty() ||
        uav_distances_[j] != uav_distances_[ku]) {
      continue;
    }
    const int steps = tours_.tour_steps(positions_[j], prior_[j]);
    if (steps > giver_steps) {
      giver_steps = steps;
      giver = static_cast<int>(j);
    }
  }
  if (giver < 0) return false;
  auto& cells = prior_[static_cast<std::size_t>(giver)];
  const auto [t, later] =
      split_tours(k, pos, giver, positions_[static_cast<std::size_t>(giver)], cells);
  // Only when it saves the giver at least a strip's width of steps.
  if (t == 0 || later + s2_ > giver_steps) return false;
  prior_[ku].assign(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(t));
  cells.erase(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(t));
  forget_tour(k);
  forget_tour(giver);
  return true;
}

void SweepInspectPlanner::balance_prior_tours(std::span<const grid::Cell> starts,
                                              const sim::PlannerView* view) {
  // Neighbours (in the order of their starts along x) of one flight part re-split the union of
  // their prior cells so that the later of their two tours ends earliest; a few passes spread a
  // long tour over more than one neighbour.
  const std::size_t n = uavs_.size();
  split_helpers_.clear();
  for (std::size_t k = 0; k < n; ++k) {
    if (view == nullptr || !view->uavs[k].failed)
      split_helpers_.push_back({static_cast<int>(k), starts[k]});
  }
  std::stable_sort(split_helpers_.begin(), split_helpers_.end(),
                   [](const auto& a, const auto& b) { return a.second.x < b.second.x; });
  for (int pass = 0; pass < kBalancePasses; ++pass) {
    for (std::size_t r = 0; r + 1 < split_helpers_.size(); ++r) {
      const auto [a, pa] = split_helpers_[r];
      const auto [b, pb] = split_helpers_[r + 1];
      auto& cells_a = prior_[static_cast<std::size_t>(a)];
      auto& cells_b = prior_[static_cast<std::size_t>(b)];
      if (uav_distances_[static_cast<std::size_t>(a)] !=
              uav_distances_[static_cast<std::size_t>(b)] ||
          cells_a.size() + cells_b.size() == 0)
        continue;
      const int now = std::max(tours_.tour_steps(pa, cells_a), tours_.tour_steps(pb, cells_b));
      split_cells_.assign(cells_a.begin(), cells_a.end());
      split_cells_.insert(split_cells_.end(), cells_b.begin(), cells_b.end());
      const auto [t, later] = split_tours(a, pa, b, pb, split_cells_);
      if (later >= now) continue;
      cells_a.assign(split_cells_.begin(), split_cells_.begin() + static_cast<std::ptrdiff_t>(t));
      cells_b.assign(split_cells_.begin() + static_cast<std::ptrdiff_t>(t), split_cells_.end());
      forget_tour(a);
      forget_tour(b);
    }
  }
}

std::optional<sim::Action> SweepInspectPlanner::prior_tour_step(int k, const sim::UavState& u,
                                                                const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  // Inspect the prior's cells of the region first, nearest first, then sweep.
  auto& cells = prior_[static_cast<std::size_t>(k)];
  if (prior_distrusted()) cells.clear();  // a prior this wrong is not worth a tour: sweep
  if (cells.empty() && u.z == 1 && !prior_distrusted()) {
    take_prior_share(k, u.pos);  // the longest tour left gives it the part it ends sooner
  }
  if (cells.empty()) {
    if (u.z == 1 && !p.low) return sim::Action::kChangePlane;
    if (p.sweep_planned) {
      p.mode = p.after_prior;
    } else {
      p.mode = Mode::kSweep;
      p.sweep_planned = true;
      // Plan the sweep from where the prior's inspections ended, over the region's cells they
      // did not see (a strip band's ends that the tour saw are not flown again).
      drop_observed(k, view);
      p.sweep.assign(sweep_from(k, u.pos));
      p.replan = false;
    }
  } else {
    if (u.z == 2) return sim::Action::kChangePlane;
    // On when the cell it flew to was seen (on the way, or by another UAV) or went to another
    // UAV (the tours' re-split); a long tour also when its cells were re-assigned (forget_tour).
    const bool seen = p.target_cell < 0 || view.map[p.target_cell] != sim::kCorrosionSeen;
    const bool mine = p.repaired
                          ? p.tour_next < p.tour.size() && p.tour[p.tour_next] == p.target_cell
                          : std::find(cells.begin(), cells.end(), p.target_cell) != cells.end();
    if (seen || !mine) p.target_cell = next_of_tour(k, u.pos, cells, view);
    p.target = reach_position(k, u.pos, view.map.cell(p.target_cell), h1_);
    return step(k, u.pos, p.target);
  }
  return std::nullopt;  // its tour is done: on to the mode it now has
}

}  // namespace hullinspect::planners
