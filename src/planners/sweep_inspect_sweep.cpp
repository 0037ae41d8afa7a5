// Sweep-Inspect's sweeps (docs/sweep-inspect.md, "The sweep" to "Help"): planning a UAV's bands,
// following them (skipping what is seen), rejoining after an inspection, and taking over the tail
// of another UAV's sweep.

#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>

#include "hullinspect/planners/band_rejoin.hpp"
#include "hullinspect/planners/sweep_approach.hpp"
#include "hullinspect/planners/sweep_chooser.hpp"
#include "hullinspect/planners/sweep_tail.hpp"
#include "hullinspect/world/no_fly.hpp"

#include "sweep_inspect_detail.hpp"

namespace hullinspect::planners {

using sweep_inspect_detail::leg_along_x;
using sweep_inspect_detail::sweep_work;
using sweep_inspect_detail::unobserved;

std::vector<grid::Cell> SweepInspectPlanner::strips_from(const grid::Grid<std::int16_t>& owner,
                                                         int k, grid::Cell from, bool approach) {
  auto waypoints = boustrophedon_from(owner, k, from, approach);
  low_blocks(owner, k, from, waypoints);
  return waypoints;
}

std::vector<grid::Cell> SweepInspectPlanner::boustrophedon_from(
    const grid::Grid<std::int16_t>& owner, int k, grid::Cell from, bool approach) {
  grid::DistanceService& distances = *uav_distances_[static_cast<std::size_t>(k)];
  BandAxis& axis = uavs_[static_cast<std::size_t>(k)].axis;
  const bool low = uavs_[static_cast<std::size_t>(k)].low;
  // On the band partition's grid a z = 2 sweep flies the grid's columns: the pieces are cut for
  // them, and rows across a piece's part-bands fly more; its z = 1 sweeps of dense columns
  // still choose.
  const bool auto_axis = options_.strips == "auto" && (band_start_.empty() || low);
  axis = options_.strips == "rows" || auto_axis ? BandAxis::kRows : BandAxis::kColumns;
  const int band = low ? s1_ : s2_;
  std::vector<grid::Cell> waypoints;
  if (auto_axis) {
    // Rows (listed first) or columns, whichever the chooser takes.
    auto candidates = axis_candidates(owner, k, band, from, band_start_);
    const std::size_t chosen = choose_plan(candidates);
    axis = chosen == 0 ? BandAxis::kRows : BandAxis::kColumns;
    waypoints = std::move(candidates[chosen].plan.waypoints);
  }
  uavs_[static_cast<std::size_t>(k)].approach_rest = 0;
  if (approach && reach_ == nullptr) {
    // The plain sweep, the sweep approached along the region's edge where that sees the bands'
    // ends, or begun with the bands on one side of the UAV's: the chooser takes one.
    SweepRequest request{k, band, axis, true, band_start_, true};
    request.edge_approach = true;
    request.own_band_first = true;
    request.x_lo = piece_columns_.first;
    request.x_hi = piece_columns_.second;
    SweepPlan plan = approach_and_sweep(owner, request, from, sweep_scratch_);
    if (plan.approach > 0)
      uavs_[static_cast<std::size_t>(k)].approach_rest = plan.waypoints.size() - plan.approach;
    return std::move(plan.waypoints);
  }
  if (!auto_axis) waypoints = band_sweep(owner, k, band, axis, true, from, band_start_);
  if (reach_ != nullptr) {
    // A strip end on a no-fly position is replaced by its nearest flyable viewpoint (or dropped);
    // the flight between waypoints goes around no-fly positions, and whatever the strips then
    // miss is found as unknown cells by the help phase.
    std::vector<grid::Cell> flyable;
    for (const grid::Cell w : waypoints) {
      const grid::Cell v =
          distances.allowed(w) ? w : distances.viewpoint(w, world::footprint_half(band));
      if (v != grid::kNoCell && (flyable.empty() || flyable.back() != v)) flyable.push_back(v);
    }
    waypoints = std::move(flyable);
  }
  // The same strips top to bottom when their far end is nearer (after the prior's inspections).
  if (waypoints.size() > 1 &&
      distances.distance(from, waypoints.back()) < distances.distance(from, waypoints.front())) {
    std::reverse(waypoints.begin(), waypoints.end());
  }
  return waypoints;
}

std::vector<grid::Cell> SweepInspectPlanner::part_strips(int k, bool low, grid::Cell from,
                                                         bool approach) {
  part_owner_ = owner_;
  for (int i : hull_cells_) {
    if (part_owner_[i] == k && (dense_column_[static_cast<std::size_t>(i % width_)] != 0) != low)
      part_owner_[i] = -1;
  }
  uavs_[static_cast<std::size_t>(k)].low = low;
  return strips_from(part_owner_, k, from, approach);
}

void SweepInspectPlanner::low_blocks(const grid::Grid<std::int16_t>& owner, int k, grid::Cell from,
                                     std::vector<grid::Cell>& waypoints) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (!p.low || !resplit_ || reach_ != nullptr) return;
  // A share after a failure's re-split holds cells other UAVs left part-swept, and one
  // boustrophedon over its ragged bands can leave a band for last on its far side, to be
  // reached by flying back across the share: two blocks of columns, one after the other, are
  // candidates too. Only at z = 1 (shares with both planes, shares wholly in dense columns),
  // where a band is a pass of the hull's height: at z = 2 the Manhattan estimate's gain is
  // small and the flown mission can be longer. Without a failure there is no re-split, and no
  // mission changes.
  const SweepRequest request{k, s1_, p.axis, true, band_start_, true};
  auto candidates = two_block_candidates(owner, request, from, std::move(waypoints));
  const std::size_t chosen = choose_plan(candidates);
  waypoints = std::move(candidates[chosen].plan.waypoints);
  if (chosen != 0) p.approach_rest = 0;  // the blocks have no approach
}

std::vector<grid::Cell> SweepInspectPlanner::sweep_from(int k, grid::Cell from) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  const bool was_low = p.low;
  p.other_part = false;
  p.low = false;
  std::vector<grid::Cell> waypoints;
  int dense = 0;
  int sparse = 0;
  int dense_lo = width_;
  int dense_hi = -1;
  if (!dense_column_.empty()) {
    for (int i : hull_cells_) {
      if (owner_[i] == k) {
        const bool d = dense_column_[static_cast<std::size_t>(i % width_)] != 0;
        ++(d ? dense : sparse);
        if (d) {
          dense_lo = std::min(dense_lo, i % width_);
          dense_hi = std::max(dense_hi, i % width_);
        }
      }
    }
  }
  // A dense part that a few z = 1 bands would cover is swept at z = 2 with the rest: each z = 1
  // band is a whole pass of the hull's height (and a plane change), for a few columns.
  if (sparse > 0 && dense > 0 && dense_hi - dense_lo + 1 <= kLowSweepMinBands * s1_) dense = 0;
  if (dense == 0) {
    waypoints = strips_from(owner_, k, from);
  } else if (sparse == 0) {
    p.low = true;
    waypoints = strips_from(owner_, k, from);
  } else {
    // Both planes: first the part whose sweep starts nearer, then the other from where it ends.
    grid::DistanceService& distances = *uav_distances_[static_cast<std::size_t>(k)];
    const auto start = [&](const std::vector<grid::Cell>& w) {
      return w.empty() ? std::numeric_limits<int>::max() : distances.distance(from, w.front());
    };
    // The plain sweeps' first waypoints decide (an approach would start both beside `from`);
    // the chosen part is then planned with its approach, which sets the UAV's axis and plane.
    const bool low_first =
        start(part_strips(k, true, from, false)) < start(part_strips(k, false, from, false));
    waypoints = part_strips(k, low_first, from);
    p.other_part = true;
  }
  // Leaving a z = 1 sweep: what is pending around here is inspected before it climbs.
  if (was_low && !p.low) p.resume = from;
  return waypoints;
}

void SweepInspectPlanner::drop_observed(int k, const sim::PlannerView& view) {
  // A detection in a column swept at z = 1 stays: the sweep planned anew inspects it on its way
  // (left out, it would wait for the helpers at the mission's end).
  for (int i : hull_cells_) {
    const bool low =
        !dense_column_.empty() && dense_column_[static_cast<std::size_t>(i % width_)] != 0;
    if (owner_[i] == k && !sweep_work_left(view, i, low)) owner_[i] = -1;
  }
}

bool SweepInspectPlanner::sweep_work_left(const sim::PlannerView& view, int i, bool low) const {
  // A detection whose finder failed before inspecting it is pending with nobody on the way to
  // it: dropped from the share at z = 2, the share's bands would be trimmed short of it, and it
  // would wait for the helpers at the mission's end, one of them flying back from far away.
  if (sweep_work(view, i, low)) return true;
  // Only a re-split marks resplit_detection_.
  return resplit_detection_[i] != 0 && view.map[i] == sim::kCorrosionSeen;
}

std::optional<sim::Action> SweepInspectPlanner::follow_sweep(int k, const sim::UavState& u,
                                                             const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (p.approach_rest > 0 && p.sweep.remaining().size() <= p.approach_rest) {
    // The approach is flown: its bands are planned again over what is unobserved now, in case
    // the flight left the approach's line (a re-plan from elsewhere, an inspection).
    drop_observed(k, view);
    // As sweep_from planned it: one part of two planes, or all its cells.
    p.sweep.assign(p.other_part ? part_strips(k, p.low, u.pos, false)
                                : strips_from(owner_, k, u.pos, false));
  }
  // An approach's legs are not bands: none is skipped (its line leg may see nothing new).
  if (p.approach_rest == 0) skip_seen_bands(p, u.pos, view);
  const sim::Action a = p.sweep.next_action(u.pos);
  if (a != sim::Action::kHover) return a;
  if (p.other_part) {
    next_part(k, u);
  } else {
    p.mode = Mode::kHelp;
  }
  return std::nullopt;
}

void SweepInspectPlanner::next_part(int k, const sim::UavState& u) {
  // One part of its cells swept: the other, planned from here, on its plane.
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  p.other_part = false;
  const bool low = !p.low;
  p.sweep.assign(part_strips(k, low, u.pos));
  if (!low) p.resume = u.pos;  // from z = 1: inspect what is pending here, climb, sweep
}

bool SweepInspectPlanner::take_sweep_tail(int j, const sim::UavState& u,
                                          const sim::PlannerView& view) {
  // The UAVs' sweeps end tens of steps apart (their shares' inspections differ): the one that
  // is done takes the far end of the sweep that would end last (split_sweep_tail), among the
  // working UAVs of its flight part whose sweep is one part in one plane.
  grid::DistanceService& mine = *uav_distances_[static_cast<std::size_t>(j)];
  int donor = -1;
  double donor_alone = 0.0;
  TailSplit chosen;
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    const Uav& q = uavs_[k];
    if (static_cast<int>(k) == j || view.uavs[k].failed || uav_distances_[k] != &mine) continue;
    if (!q.sweep_planned || q.other_part || q.replan) continue;
    if (q.mode != Mode::kSweep && q.mode != Mode::kReturn && q.mode != Mode::kInspect) continue;
    const auto rest = q.sweep.remaining();
    if (rest.empty()) continue;
    const bool sweeping = q.mode == Mode::kSweep;
    const SweepLeft left{rest, sweeping ? view.uavs[k].pos : q.resume,
                         sweeping ? 0 : grid::manhattan(view.uavs[k].pos, q.resume), q.axis};
    const double alone = sweep_left_end(left);
    if (donor >= 0 && alone <= donor_alone) continue;
    // A split must save at least s2 steps.
    const TailSplit split = split_sweep_tail(left, u.pos, mine, s2_, tail_walk_);
    if (split.leg < 0) continue;
    donor = static_cast<int>(k);
    donor_alone = alone;
    chosen = split;
  }
  if (donor < 0) return false;
  Uav& q = uavs_[static_cast<std::size_t>(donor)];
  const auto rest = q.sweep.remaining();
  const auto leg = static_cast<std::size_t>(chosen.leg);
  std::vector<grid::Cell> tail;
  if (!chosen.skip_leg) tail.push_back(chosen.at);
  tail.insert(tail.end(), rest.begin() + static_cast<std::ptrdiff_t>(leg), rest.end());
  if (chosen.backward) std::reverse(tail.begin(), tail.end());
  // The tail's cells become the taker's in owner_, so that a sweep planned again from owner_
  // (after an inspection) neither drops the tail nor gives it back to the donor.
  const int half = q.low ? h1_ : h2_;
  const auto& map = view.map;
  for (std::size_t i = 0; i + 1 < tail.size(); ++i) {
    const grid::Cell a = tail[i];
    const grid::Cell b = tail[i + 1];
    const bool band_leg = q.axis == BandAxis::kRows ? a.y == b.y : a.x == b.x;
    if (!band_leg) continue;  // a flight between two bands
    const LegBox box = leg_footprints(a, b, half, map.width(), map.height());
    for (int y = box.y_lo; y <= box.y_hi; ++y) {
      for (int x = box.x_lo; x <= box.x_hi; ++x) {
        const int c = map.index(x, y);
        if (owner_[c] == donor) owner_[c] = static_cast<std::int16_t>(j);
      }
    }
  }
  if (chosen.skip_leg) {
    q.sweep.keep(leg);  // up to rest[leg - 1], the start of the leg between two bands
  } else {
    q.sweep.keep(leg, chosen.at);
  }
  Uav& p = uavs_[static_cast<std::size_t>(j)];
  p.sweep.assign(std::move(tail));
  p.approach_rest = 0;  // whatever approach is left is the donor's
  q.approach_rest = 0;
  p.axis = q.axis;
  p.low = q.low;
  p.other_part = false;
  p.sweep_planned = true;
  p.mode = Mode::kSweep;
  p.target_cell = -1;
  p.resume = u.pos;  // from z = 1 onto a z = 2 tail: what is pending here first, then climb
  return true;
}

bool SweepInspectPlanner::replan_after_inspection(int k, grid::Cell pos,
                                                  const sim::PlannerView& view) {
  // An inspection can take a UAV up to the inspection radius away from its band (a rectangle at
  // the footprint's edge, a cluster followed), and flying back to where it left the band can
  // cost more than the sweep planned anew from here over what is still unobserved. Both flights are
  // estimated as the sweep will be planned (both parts, with the approach; among no-fly zones the
  // service's flights, where the way back around a zone is longer still); the state that planning
  // sets is the UAV's again unless the plan from here is taken.
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (p.resume == pos) return false;
  drop_observed(k, view);
  const auto restore = [&p, low = p.low, other_part = p.other_part, axis = p.axis,
                        approach_rest = p.approach_rest, resume = p.resume] {
    p.low = low;
    p.other_part = other_part;
    p.axis = axis;
    p.approach_rest = approach_rest;
    p.resume = resume;
  };
  // Two candidates for the chooser, costs only: back to the band (listed first, so a tie keeps
  // it), or planned anew from here (planned again if chosen, as planning sets the UAV's state).
  std::array<SweepCandidate, 2> candidates;
  candidates[0].cost.reach = flight(k, pos, p.resume);
  candidates[0].cost.bands = planned_sweep_steps(k, p.resume);
  restore();
  candidates[1].cost.bands = planned_sweep_steps(k, pos);
  restore();
  if (choose_plan(candidates) == 0) return false;
  p.sweep.assign(sweep_from(k, pos));
  p.resume = pos;
  return true;
}

bool SweepInspectPlanner::leg_sees_unobserved(grid::Cell a, grid::Cell b, bool low,
                                              const sim::PlannerView& view) const {
  // At z = 1 (a low sweep) the footprint is s1 wide, and it also inspects the detected cells.
  const auto& map = view.map;
  const LegBox box = leg_footprints(a, b, low ? h1_ : h2_, map.width(), map.height());
  for (int y = box.y_lo; y <= box.y_hi; ++y) {
    for (int x = box.x_lo; x <= box.x_hi; ++x) {
      const int i = map.index(x, y);
      if (sweep_work_left(view, i, low)) return true;
    }
  }
  return false;
}

void SweepInspectPlanner::skip_seen_bands(Uav& p, grid::Cell pos,
                                          const sim::PlannerView& view) const {
  // The waypoints come in pairs, the two ends of a band, on one line. The leg being flown (from
  // here, on the band's line, to its end) and each following band are dropped while their
  // footprints would see nothing new: a helper or an inspection saw those cells already.
  for (;;) {
    const auto left = p.sweep.remaining();
    if (left.empty()) return;
    const grid::Cell end = left.front();
    const bool on_line = (p.axis == BandAxis::kRows) ? pos.y == end.y : pos.x == end.x;
    if (on_line && pos != end) {
      if (leg_sees_unobserved(pos, end, p.low, view)) return;
      p.sweep.skip(1);
      continue;
    }
    // Flying to a band's first end: skip the whole band when it would see nothing.
    if (left.size() < 2) return;
    const grid::Cell other = left[1];
    const bool band = (p.axis == BandAxis::kRows) ? end.y == other.y : end.x == other.x;
    if (!band || leg_sees_unobserved(end, other, p.low, view)) return;
    p.sweep.skip(2);
  }
}

bool SweepInspectPlanner::detection_abreast(int k, grid::Cell pos,
                                            const sim::PlannerView& view) const {
  const Uav& p = uavs_[static_cast<std::size_t>(k)];
  // Descend when a detected cell is abreast: its position along the band within reach of
  // the z = 1 footprint (across it, within the band's width), and no
  // longer ahead on the leg. Also, with
  // when this leg of the flight comes no nearer to it along the band:
  // a cell beyond the trimmed end of a band (within h2 of its last position, never within
  // h1) or behind its start would otherwise wait for the helpers at the mission's end.
  grid::Cell next = pos;
  for (const grid::Cell w : p.sweep.remaining()) {
    if (w != pos) {
      next = w;
      break;
    }
  }
  const bool rows = leg_along_x(p.axis, pos, next);
  const auto along_of = [rows](grid::Cell c) { return rows ? c.x : c.y; };
  const bool leg_along = rows ? next.y == pos.y : next.x == pos.x;
  const int leg_lo = std::min(along_of(pos), leg_along ? along_of(next) : along_of(pos));
  const int leg_hi = std::max(along_of(pos), leg_along ? along_of(next) : along_of(pos));
  // The direction the leg is flown along (0: not flying along a leg), so
  // that a cell still ahead on it waits; once it is level, the footprint has seen h2 rows beyond
  // it, a rectangle's last rows among them.
  const int leg_dir = !leg_along || next == pos ? 0 : along_of(next) > along_of(pos) ? 1 : -1;
  for (int i : pending_) {
    const grid::Cell c = view.map.cell(i);
    const int along = std::abs(along_of(c) - along_of(pos));
    const int across = rows ? std::abs(c.y - pos.y) : std::abs(c.x - pos.x);
    const int nearest_on_leg = along_of(c) < leg_lo   ? leg_lo - along_of(c)
                               : along_of(c) > leg_hi ? along_of(c) - leg_hi
                                                      : 0;
    const bool ahead = leg_dir * (along_of(c) - along_of(pos)) > 0;
    const bool here_or_never =
        (along <= h1_ && !ahead) || (along <= h2_ && nearest_on_leg >= along);
    // The cells nearest_pending may take, so that a UAV never descends for one it then leaves
    // (a detection it may not inspect: it would climb and descend for ever).
    if (here_or_never && across <= h2_ && may_inspect(k, i)) return true;
  }
  return false;
}

}  // namespace hullinspect::planners
