#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/band_partition.hpp"
#include "hullinspect/planners/open_tour.hpp"
#include "hullinspect/planners/prior_weights.hpp"
#include "hullinspect/planners/sweep_approach.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::planners {

namespace {
// Whether the leg from `a` to `b` runs along x (as a row band's). A band runs along its sweep's
// axis, but an approach leg (approach-edge) may run across it; a leg that is not straight (or
// empty) is taken as the sweep's.
bool leg_along_x(BandAxis axis, grid::Cell a, grid::Cell b) {
  if (a.y == b.y && a.x != b.x) return true;
  if (a.x == b.x && a.y != b.y) return false;
  return axis == BandAxis::kRows;
}

int chebyshev(grid::Cell a, grid::Cell b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y));
}
/// Splits `cells` (flat indices, sorted by column) into consecutive column slabs, left to right,
/// one per UAV of `uavs` (id and position, sorted by x): the earliest common end t for which each
/// UAV's load, its flight to the nearer end of its slab (per_column per column) and its slab
/// (1 per cell) fit in t, found by bisection. Calls assign(uav, cell) for every cell.
template <class Assign>
void split_in_slabs(const std::vector<int>& cells, int width,
                    const std::vector<std::pair<int, grid::Cell>>& uavs,
                    const std::vector<double>& load, double per_column, Assign assign) {
  if (cells.empty() || uavs.empty()) return;
  const auto split = [&](double t, bool give) {
    std::size_t c = 0;
    for (const auto& uav : uavs) {
      const int k = uav.first;
      const grid::Cell pos = uav.second;
      const std::size_t first = c;
      while (c < cells.size()) {
        const int x_lo = cells[first] % width;
        const int x_hi = cells[c] % width;
        const int flight = pos.x < x_lo   ? x_lo - pos.x
                           : pos.x > x_hi ? pos.x - x_hi
                                          : std::min(pos.x - x_lo, x_hi - pos.x);
        const double cost = load[static_cast<std::size_t>(k)] + per_column * flight +
                            static_cast<double>(c - first + 1);
        if (cost > t) break;
        if (give) assign(k, cells[c]);
        ++c;
      }
    }
    return c == cells.size();
  };
  split(earliest_common_end([&](double t) { return split(t, false); }), true);
}

/// Not yet observed: unknown, or expected corroded by the prior and not yet seen.
bool unobserved(const sim::PlannerView& view, int i) {
  return view.map[i] == sim::kUnknown || (view.map[i] == sim::kCorrosionSeen && view.seen[i] == 0);
}
}  // namespace

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
  return sim::step_towards(pos, uav_distances_[static_cast<std::size_t>(k)]->next_step(pos, to));
}

std::vector<grid::Cell> SweepInspectPlanner::strips_from(const grid::Grid<std::int16_t>& owner,
                                                         int k, grid::Cell from, bool approach) {
  grid::DistanceService& distances = *uav_distances_[static_cast<std::size_t>(k)];
  BandAxis& axis = uavs_[static_cast<std::size_t>(k)].axis;
  const bool low = uavs_[static_cast<std::size_t>(k)].low;
  // On the band partition's grid a z = 2 sweep flies the grid's columns: the pieces are cut for
  // them (rows across a piece's part-bands flew more: on the tuning seeds `auto` there cost T_m
  // 6-12 s with a right prior); its z = 1 sweeps of dense columns still choose.
  const bool auto_axis = options_.strips == "auto" && (band_start_.empty() || low);
  axis = options_.strips == "rows" || auto_axis ? BandAxis::kRows : BandAxis::kColumns;
  const int band = low ? h1_ * 2 + 1 : h2_ * 2 + 1;
  auto waypoints = band_sweep(owner, k, band, axis, options_.trim_strip_ends, from, band_start_);
  if (auto_axis) {
    // Whichever of the two patterns is the shorter flight from here (Manhattan estimate).
    auto columns =
        band_sweep(owner, k, band, BandAxis::kColumns, options_.trim_strip_ends, from, band_start_);
    if (flight_length(from, columns) < flight_length(from, waypoints)) {
      waypoints = std::move(columns);
      axis = BandAxis::kColumns;
    }
  }
  uavs_[static_cast<std::size_t>(k)].approach_rest = 0;
  if (approach && options_.approach_edge && reach_ == nullptr) {
    // approach-edge: fly to the sweep along the region's edge where that sees the bands' ends.
    const SweepRequest request{
        k, band, axis, options_.trim_strip_ends, band_start_, options_.nearer_sweep_end};
    SweepPlan plan = approach_and_sweep(owner, request, from, approach_owner_);
    if (plan.approach > 0)
      uavs_[static_cast<std::size_t>(k)].approach_rest = plan.waypoints.size() - plan.approach;
    return std::move(plan.waypoints);
  }
  if (reach_ != nullptr) {
    // A strip end on a no-fly position is replaced by its nearest flyable viewpoint (or dropped);
    // the flight between waypoints goes around no-fly positions, and whatever the strips then
    // miss is found as unknown cells by the help phase.
    std::vector<grid::Cell> flyable;
    for (const grid::Cell w : waypoints) {
      const grid::Cell v = distances.allowed(w) ? w : distances.viewpoint(w, band / 2);
      if (v != grid::kNoCell && (flyable.empty() || flyable.back() != v)) flyable.push_back(v);
    }
    waypoints = std::move(flyable);
  }
  // The same strips top to bottom when their far end is nearer (after the prior's inspections).
  if (options_.nearer_sweep_end && waypoints.size() > 1 &&
      distances.distance(from, waypoints.back()) < distances.distance(from, waypoints.front())) {
    std::reverse(waypoints.begin(), waypoints.end());
  }
  return waypoints;
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
  h1_ = (p.s1 - 1) / 2;
  h2_ = (p.s2 - 1) / 2;
  // At least h2: a descent is for a detected cell abreast (column within h1, row within h2 of the
  // UAV), which must then lie within the radius, or the UAV would climb at once and descend again
  // for the same cell for ever (radius-factor below about 0.45 did).
  radius_ = std::max(h2_, static_cast<int>(std::lround(options_.radius_factor * p.s2)));
  partition::PartitionRequest request;
  request.hull = &context.hull;
  request.starts.assign(context.starts.begin(), context.starts.end());
  request.seed = options_.partition_seed;
  add_no_fly(request, context);
  add_prior_weights(request, context, options_.prior_weights, options_.prior_statistics);
  // The plane a cell is swept on is known before the partition: the zones' statistics decide it.
  const double precision = expected_prior_precision(context);
  prior_dropped_ = options_.trust_statistics && options_.prior_trust > 0 && precision >= 0 &&
                   precision < options_.prior_trust;
  hull_cells_ = context.hull.cells();
  find_dense_columns(context);
  partition_ = nullptr;
  band_start_.clear();
  if (options_.band_partition && !flights_.split()) partition_ = band_partition(request, context);
  if (partition_ == nullptr && options_.slab_partition) {
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
  tour_left_.clear();
  tour_left_.reserve(static_cast<std::size_t>(context.hull.cell_count()));
  tour_points_.clear();
  tour_points_.reserve(static_cast<std::size_t>(context.hull.cell_count()));
  if (options_.prior_first && options_.share_prior) balance_prior_tours(context.starts);
  prior_true_ = 0;
  prior_false_ = 0;
  pending_.clear();
  pending_.reserve(static_cast<std::size_t>(context.hull.cell_count()));
  handed_over_.assign(static_cast<std::size_t>(n), 0);
  split_cells_.clear();
  split_cells_.reserve(static_cast<std::size_t>(context.hull.cell_count()));
}

std::shared_ptr<const partition::Partition> SweepInspectPlanner::band_partition(
    const partition::PartitionRequest& request, const PlannerContext& context) {
  // One boustrophedon over the hull's bands (s1 wide in dense columns, s2 elsewhere), cut into
  // pieces of equal work, in the weights' unit (a clean cell swept at z = 2; a step sweeps s2
  // of them): a band is one step a row and about one more to reach it (its width across, less
  // the rows its trimmed ends save); at z = 2 a cell adds the inspections the weights expect
  // there (their excess over 1), at z = 1 nothing (it is inspected when seen).
  std::vector<int> width_of_column(static_cast<std::size_t>(width_), 2 * h2_ + 1);
  for (std::size_t x = 0; x < dense_column_.size(); ++x) {
    if (dense_column_[x] != 0) width_of_column[x] = 2 * h1_ + 1;
  }
  std::vector<int> band_start = column_band_starts(width_of_column);
  // An inspection on detection (a descent, a flight across the band and back, a climb) costs
  // more than its weight says, which is a planned z = 1 tour's (the prior's cells when toured).
  // The tours, though, are re-split among neighbours after the partition (share-prior): a piece
  // shrunk for its whole tour lost sweep to pieces that then also took part of its tour, and
  // ended early (inhomogeneous, s2 = 7, n = 4, 20 tuning seeds: the two UAVs of the denser half
  // ended their sweeps 25-30 s before the other two with a weight of 1, within 12 s with 0.25).
  // Without share-prior each UAV tours its own cells, and the whole weight counts.
  const bool toured = options_.prior_first && !prior_dropped_;
  const double tour_factor = options_.share_prior ? options_.prior_tour_weight : 1.0;
  grid::Grid<double> extra = request.weights;
  for (int i = 0; i < extra.size(); ++i) {
    const bool dense =
        !dense_column_.empty() && dense_column_[static_cast<std::size_t>(i % width_)] != 0;
    const double factor =
        toured && context.prior[i] == 1 ? tour_factor : options_.inspection_weight;
    extra[i] = dense ? 0.0 : factor * std::max(0.0, extra[i] - 1.0);
  }
  const double step = context.params.s2;
  try {
    const BandPieces rows(context.hull, extra, band_start, context.starts, step, step);
    std::vector<std::size_t> cuts = rows.balanced_cuts();
    auto pieces = rows.cut(cuts);
    band_start_ = std::move(band_start);
    const auto& hull_cells = context.hull.cells();
    const bool tours = toured && std::any_of(hull_cells.begin(), hull_cells.end(),
                                             [&](int i) { return context.prior[i] == 1; });
    const bool one_plane =
        std::none_of(dense_column_.begin(), dense_column_.end(), [](char d) { return d != 0; });
    if (options_.balance_flights && !tours && one_plane && reach_ == nullptr)
      pieces = balance_flights(rows, std::move(cuts), std::move(pieces), context);
    return std::make_shared<const partition::Partition>(std::move(pieces));
  } catch (const Error&) {
    band_start_.clear();
    return nullptr;  // a piece not 4-connected: slabs or the partitioner instead
  }
}

partition::Partition SweepInspectPlanner::balance_flights(const BandPieces& rows,
                                                          std::vector<std::size_t> cuts,
                                                          partition::Partition pieces,
                                                          const PlannerContext& context) {
  // The pieces' work counts a row of a band one step and a band one more, wherever the UAV
  // starts; but a piece's flight depends on where in it the UAV starts and on how its ends cut
  // the bands. So the cuts are moved, one at a time, by a few rows either way, as long as that
  // makes the latest planned end (the flight as planned from the start, with the approach, plus
  // the expected inspections) earlier, or keeps it and spreads the ends less.
  const int n = rows.uavs();
  const double step = context.params.s2;
  owner_ = pieces.owner;
  uavs_.assign(static_cast<std::size_t>(n), Uav{});
  const auto first_row = [&](int piece) {
    return piece == 0 ? std::size_t{0} : cuts[static_cast<std::size_t>(piece - 1)];
  };
  const auto end_row = [&](int piece) {
    return piece == n - 1 ? rows.rows() : cuts[static_cast<std::size_t>(piece)];
  };
  const auto planned_end = [&](int piece) {
    const int k = rows.uav_of_piece(piece);
    return planned_sweep_steps(k, context.starts[static_cast<std::size_t>(k)]) +
           rows.extra(first_row(piece), end_row(piece)) / step;
  };
  std::vector<double> ends(static_cast<std::size_t>(n));
  for (int piece = 0; piece < n; ++piece)
    ends[static_cast<std::size_t>(piece)] = planned_end(piece);
  const auto score = [&] {
    double latest = 0;
    double squares = 0;
    for (double e : ends) {
      latest = std::max(latest, e);
      squares += e * e;
    }
    return std::pair{latest, squares};
  };
  auto best = score();
  for (int round = 0; round < options_.balance_rounds; ++round) {
    bool moved_any = false;
    for (int c = 0; c + 1 < n; ++c) {
      const auto cc = static_cast<std::size_t>(c);
      for (const int delta : {-60, -45, -30, -20, -10, -5, -3, -1, 1, 3, 5, 10, 20, 30, 45, 60}) {
        const std::size_t old = cuts[cc];
        const long moved = static_cast<long>(old) + delta;
        if (moved <= static_cast<long>(first_row(c)) || moved >= static_cast<long>(end_row(c + 1)))
          continue;  // every piece keeps a row
        const auto cut = static_cast<std::size_t>(moved);
        // Moving cut c from `a` to `b` gives the rows between to the piece before or after it.
        const auto move_cut = [&](std::size_t a, std::size_t b) {
          if (b > a) rows.assign_rows(owner_, a, b, rows.uav_of_piece(c));
          if (b < a) rows.assign_rows(owner_, b, a, rows.uav_of_piece(c + 1));
          cuts[cc] = b;
        };
        move_cut(old, cut);
        const double before_c = ends[cc];
        const double before_next = ends[cc + 1];
        ends[cc] = planned_end(c);
        ends[cc + 1] = planned_end(c + 1);
        const auto now = score();
        if (now < best) {
          best = now;
          moved_any = true;
          continue;
        }
        move_cut(cut, old);  // undo
        ends[cc] = before_c;
        ends[cc + 1] = before_next;
      }
    }
    if (!moved_any) break;
  }
  try {
    return rows.cut(cuts);
  } catch (const Error&) {
    return pieces;  // a moved cut left a piece in two: the equal-work pieces
  }
}

double SweepInspectPlanner::planned_sweep_steps(int k, grid::Cell from) {
  // As the sweep will be planned (sweep_from), both parts when its cells lie on both planes.
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  const auto first = sweep_from(k, from);
  double steps = flight_length(from, first);
  if (p.other_part && !first.empty()) {
    const auto second = part_strips(k, !p.low, first.back());
    steps += flight_length(first.back(), second);
  }
  return steps;
}

void SweepInspectPlanner::find_dense_columns(const PlannerContext& context) {
  // Where corrosion is dense, a z = 2 sweep spends more on descents, inspections and flights
  // back than it saves by its wider footprint: one z = 1 pass (bands of s1) sees and inspects
  // every cell. The expected corroded fraction is the zone's mean over what the sweep will find:
  // the prior's cells, when they are toured first, are inspected before it.
  dense_column_.clear();
  if (options_.low_sweep_above >= 1.0) return;
  const grid::Grid<double> corrosion = corrosion_probabilities(context, true);
  const bool toured = options_.prior_first && !prior_dropped_;
  const int width = context.hull.width();
  std::vector<world::CorrosionZone> zones;
  if (context.corrosion != nullptr) zones = context.corrosion->zones;
  if (zones.empty()) zones.push_back({0, width});
  dense_column_.assign(static_cast<std::size_t>(width), 0);
  for (const auto& zone : zones) {
    const int x_lo = std::max(0, zone.x_begin);
    const int x_hi = std::min(width, zone.x_end);
    double expected = 0.0;
    int cells = 0;
    for (int i : context.hull.cells()) {
      const int x = i % width;
      if (x < x_lo || x >= x_hi) continue;
      if (!(toured && context.prior[i] == 1)) expected += corrosion[i];
      ++cells;
    }
    if (cells == 0 || expected <= options_.low_sweep_above * cells) continue;
    for (int x = x_lo; x < x_hi; ++x) dense_column_[static_cast<std::size_t>(x)] = 1;
  }
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
  if (sparse > 0 && dense > 0 &&
      dense_hi - dense_lo + 1 <= options_.low_sweep_min_bands * (2 * h1_ + 1))
    dense = 0;
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
  if (options_.take_over_prior && hand_over_prior(view) && options_.share_prior &&
      !prior_distrusted()) {
    balance_prior_tours(positions_, &view);  // the failed UAV's cells among the neighbours
  }
  if (options_.take_over_sweep) {
    bool failure = false;
    for (std::size_t j = 0; j < uavs_.size(); ++j) {
      if (!view.uavs[j].failed || handed_over_[j] != 0) continue;
      handed_over_[j] = 1;
      failure = true;
    }
    if (failure) resplit(view);
  }
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    actions[k] = decide_uav(static_cast<int>(k), view.uavs[k], view);
  }
}

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
      if (best >= 0) prior_[static_cast<std::size_t>(best)].push_back(i);
    }
    prior_[j].clear();
  }
  return handed;
}

sim::Action SweepInspectPlanner::decide_uav(int k, const sim::UavState& u,
                                            const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (u.failed) {
    p = Uav{};
    p.mode = Mode::kFailed;
    return sim::Action::kHover;
  }
  if (u.in_transit()) return sim::Action::kHover;

  if (!prior_[static_cast<std::size_t>(k)].empty() && u.z == 2 &&
      (p.mode == Mode::kSweep || p.mode == Mode::kHelp || p.mode == Mode::kDone)) {
    // Prior cells handed over from a failed UAV: leave the sweep (or help) for them, come back.
    p.after_prior = p.mode == Mode::kSweep ? Mode::kReturn : Mode::kHelp;
    if (p.mode == Mode::kSweep) p.resume = u.pos;
    p.target_cell = -1;
    p.mode = Mode::kPrior;
  }
  if (p.mode == Mode::kPrior) {
    // Inspect the prior's cells of the region first, nearest first, then sweep.
    auto& cells = prior_[static_cast<std::size_t>(k)];
    if (prior_distrusted()) cells.clear();  // a prior this wrong is not worth a tour: sweep
    if (cells.empty() && options_.share_prior && u.z == 1 && !prior_distrusted()) {
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
        if (options_.nearer_sweep_end) {
          drop_observed(k, view);
          p.sweep.assign(sweep_from(k, u.pos));
          p.replan = false;
        }
      }
    } else {
      if (u.z == 2) return sim::Action::kChangePlane;
      if (options_.plan_prior_tour) {
        // Plan anew when the cell it flew to was seen (on the way, or by another UAV) or went to
        // another UAV (share-prior): the rest of the tour may be ordered better from here.
        if (p.target_cell < 0 || view.map[p.target_cell] != sim::kCorrosionSeen ||
            std::find(cells.begin(), cells.end(), p.target_cell) == cells.end())
          p.target_cell = first_of_planned_tour(u.pos, cells);
        p.target = reach_position(k, u.pos, view.map.cell(p.target_cell), h1_);
        return step(k, u.pos, p.target);
      }
      int best = -1;
      int best_d = std::numeric_limits<int>::max();
      for (int i : cells) {
        const int d = uav_distances_[static_cast<std::size_t>(k)]->distance(
            u.pos, reach_position(k, u.pos, view.map.cell(i), h1_));
        if (d < best_d) {
          best_d = d;
          best = i;
        }
      }
      p.target = reach_position(k, u.pos, view.map.cell(best), h1_);
      return step(k, u.pos, p.target);
    }
  }

  if (p.mode == Mode::kSweep && p.low) {
    // low-sweep-above: dense columns are swept at z = 1; every cell seen is inspected.
    if (p.replan) {
      p.replan = false;
      p.sweep.assign(sweep_from(k, u.pos));
      if (!p.low) return decide_uav(k, u, view);
    }
    if (u.z == 2) return sim::Action::kChangePlane;
    if (const auto a = follow_sweep(k, u, view)) return *a;
  }
  if (p.mode == Mode::kSweep || p.mode == Mode::kReturn) {
    if (u.z == 1) {  // arrived below for an inspection
      p.mode = Mode::kInspect;
    } else {
      if (p.replan) {
        // Its cells were re-split after a failure: strips over its new share from here.
        p.replan = false;
        p.mode = Mode::kSweep;
        p.sweep.assign(sweep_from(k, u.pos));
      }
      if (p.mode == Mode::kReturn && u.pos == p.resume) p.mode = Mode::kSweep;
      if (p.mode == Mode::kSweep && options_.inspect_on_the_way) {
        // Descend when a detected cell is abreast: its position along the band within reach of
        // the z = 1 footprint (across it, within the band's width). Also, with
        // `inspect-band-ends`, when this leg of the flight comes no nearer to it along the band:
        // a cell beyond the trimmed end of a band (within h2 of its last position, never within
        // h1) or behind its start would otherwise wait for the helpers at the mission's end.
        grid::Cell next = u.pos;
        for (const grid::Cell w : p.sweep.remaining()) {
          if (w != u.pos) {
            next = w;
            break;
          }
        }
        const bool rows = leg_along_x(p.axis, u.pos, next);
        const auto along_of = [rows](grid::Cell c) { return rows ? c.x : c.y; };
        const bool leg_along = rows ? next.y == u.pos.y : next.x == u.pos.x;
        const int leg_lo = std::min(along_of(u.pos), leg_along ? along_of(next) : along_of(u.pos));
        const int leg_hi = std::max(along_of(u.pos), leg_along ? along_of(next) : along_of(u.pos));
        for (int i : pending_) {
          const grid::Cell c = view.map.cell(i);
          const int along = std::abs(along_of(c) - along_of(u.pos));
          const int across = rows ? std::abs(c.y - u.pos.y) : std::abs(c.x - u.pos.x);
          const int nearest_on_leg = along_of(c) < leg_lo   ? leg_lo - along_of(c)
                                     : along_of(c) > leg_hi ? along_of(c) - leg_hi
                                                            : 0;
          const bool here_or_never = along <= h1_ || (options_.inspect_band_ends && along <= h2_ &&
                                                      nearest_on_leg >= along);
          if (here_or_never && across <= h2_ && reachable(k, i, world::kReachZ1) &&
              !claimed_by_other(k, i)) {
            p.resume = u.pos;
            return sim::Action::kChangePlane;
          }
        }
      }
      if (p.mode == Mode::kReturn) return step(k, u.pos, p.resume);
      if (const auto a = follow_sweep(k, u, view)) return *a;
    }
  }
  if (p.mode == Mode::kDone)
    p.mode = Mode::kHelp;  // work may have appeared (a failure, a claim freed)
  if (p.mode == Mode::kHelp && p.replan && (u.z == 2 || p.low)) {
    // Cells re-split after a failure while it was helping: sweep them.
    p.replan = false;
    p.sweep.assign(sweep_from(k, u.pos));
    p.sweep_planned = true;
    p.target_cell = -1;
    const sim::Action a = p.sweep.next_action(u.pos);
    if (a != sim::Action::kHover) {
      p.mode = Mode::kSweep;
      return a;
    }
  }

  if (p.mode == Mode::kInspect) {
    if (u.z == 2) {  // climbed back: resume the sweep
      p.mode = Mode::kReturn;
      p.target_cell = -1;
      return u.pos == p.resume ? decide_uav(k, u, view) : step(k, u.pos, p.resume);
    }
    int cell = nearest_pending(k, u.pos, p.resume, radius_, view);
    if (cell < 0 && options_.follow_clusters)
      cell = nearest_cluster_edge(k, u.pos, p.resume, radius_, view);
    p.target_cell = cell;
    if (cell < 0) {
      if (options_.resume_ahead) p.resume = rejoin_point(k, p, u.pos, view);
      return sim::Action::kChangePlane;
    }
    p.target = reach_position(k, u.pos, view.map.cell(cell), h1_);
    return step(k, u.pos, p.target);
  }

  if (p.mode == Mode::kHelp) {
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
  return sim::Action::kHover;  // kDone
}

void SweepInspectPlanner::drop_observed(int k, const sim::PlannerView& view) {
  for (int i : hull_cells_) {
    if (owner_[i] == k && !unobserved(view, i)) owner_[i] = -1;
  }
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
  if (options_.skip_seen_bands && p.approach_rest == 0) skip_seen_bands(p, u.pos, view);
  const sim::Action a = p.sweep.next_action(u.pos);
  if (a != sim::Action::kHover) return a;
  if (p.other_part) return next_part(k, u, view);
  p.mode = Mode::kHelp;
  return std::nullopt;
}

sim::Action SweepInspectPlanner::next_part(int k, const sim::UavState& u,
                                           const sim::PlannerView& view) {
  // One part of its cells swept: the other, planned from here, on its plane.
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  p.other_part = false;
  const bool low = !p.low;
  p.sweep.assign(part_strips(k, low, u.pos));
  if (!low) p.resume = u.pos;  // from z = 1: inspect what is pending here, climb, sweep
  return decide_uav(k, u, view);
}

bool SweepInspectPlanner::take_sweep_tail(int j, const sim::UavState& u,
                                          const sim::PlannerView& view) {
  // The UAVs' sweeps end tens of steps apart (on the tuning seeds of the combined scenario,
  // n = 8, the first 20-60 s before the last): the one that is done takes the far end of the
  // sweep that would end last — its last bands, or the far part of its last band — which keeps
  // the bands' structure where helping cell by cell flies to scattered cells. A sweep left is
  // estimated as the walk through its waypoints (Manhattan) times kTailWalkCost (inspections on
  // the way); the split is anywhere along a band, or at a leg between two bands (not flown).
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
    const grid::Cell from = sweeping ? view.uavs[k].pos : q.resume;
    const int back = sweeping ? 0 : grid::manhattan(view.uavs[k].pos, q.resume);
    // tail_walk_[i]: the walk from `from` to rest[i].
    tail_walk_.assign(rest.size(), grid::manhattan(from, rest[0]));
    for (std::size_t i = 1; i < rest.size(); ++i)
      tail_walk_[i] = tail_walk_[i - 1] + grid::manhattan(rest[i - 1], rest[i]);
    const double alone = back + kTailWalkCost * tail_walk_.back();
    if (donor >= 0 && alone <= donor_alone) continue;
    // distance(a, b) searches from b: from here once for every candidate (flights are symmetric).
    const int to_end = mine.distance(rest.back(), u.pos);
    const double total = tail_walk_.back();
    TailSplit split;
    split.end = alone - (2 * h2_ + 1);  // a split must save at least s2 steps
    const auto consider = [&](std::size_t leg, grid::Cell at, double kept, bool skip_leg) {
      // k flies to `at` (on leg `leg`, the leg into rest[leg]) and stops; the UAV j takes the
      // rest: from `at` (or, skipping a leg between bands, from rest[leg]) to the end.
      const grid::Cell first = skip_leg ? rest[leg] : at;
      const double taken = total - (skip_leg ? tail_walk_[leg] : kept);
      const int to_first = mine.distance(first, u.pos);
      if (to_first == grid::kUnreachable) return;
      const double keeps = back + kTailWalkCost * kept;
      const double takes = std::min(to_first, to_end) + kTailWalkCost * taken;
      const double end = std::max(keeps, takes);
      if (end >= split.end) return;
      split = {end, static_cast<int>(leg), at, skip_leg, to_end < to_first};
    };
    for (std::size_t leg = 0; leg < rest.size(); ++leg) {
      const grid::Cell a = leg == 0 ? from : rest[leg - 1];
      const grid::Cell b = rest[leg];
      const double before = leg == 0 ? 0.0 : tail_walk_[leg - 1];
      if (back + kTailWalkCost * before >= split.end) break;  // k's share only grows
      const bool band_leg = q.axis == BandAxis::kRows ? a.y == b.y : a.x == b.x;
      if (!band_leg) {
        if (leg > 0) consider(leg, a, before, true);
        continue;
      }
      const int length = grid::manhattan(a, b);
      const grid::Cell dir{(b.x > a.x) - (b.x < a.x), (b.y > a.y) - (b.y < a.y)};
      for (int d = 1; d < length; ++d) {
        const grid::Cell at{a.x + d * dir.x, a.y + d * dir.y};
        if (mine.allowed(at)) consider(leg, at, before + d, false);
      }
    }
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

void SweepInspectPlanner::resplit(const sim::PlannerView& view) {
  const std::size_t n = uavs_.size();
  for (int i : hull_cells_) owner_[i] = -1;
  // The working UAVs' loads: the prior's cells each still has to visit, in cells (a visit costs
  // about kPriorVisitSteps steps, a step of sweep sees about kSweepRate·s2 new cells); on the
  // band partition's grid in steps.
  const double cells_per_step = kSweepRate * (2 * h2_ + 1);
  const bool on_bands = !band_start_.empty();
  split_load_.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    if (view.uavs[k].failed) continue;
    split_load_[k] = kPriorVisitSteps * (on_bands ? 1.0 : cells_per_step) *
                     static_cast<double>(prior_[k].size());
    uavs_[k].replan = true;
  }
  // One split per flight part (docs/model.md §8; one part without a no-fly wall): the cells not
  // yet observed that the part sees, in column order (then row), among its working UAVs in the
  // order of their positions (x).
  for (std::size_t g = 0; g < n; ++g) {
    if (view.uavs[g].failed) continue;
    bool first_of_part = true;
    for (std::size_t k = 0; k < g; ++k) {
      if (!view.uavs[k].failed && uav_distances_[k] == uav_distances_[g]) first_of_part = false;
    }
    if (!first_of_part) continue;
    split_helpers_.clear();
    for (std::size_t k = g; k < n; ++k) {
      if (!view.uavs[k].failed && uav_distances_[k] == uav_distances_[g])
        split_helpers_.push_back({static_cast<int>(k), view.uavs[k].pos});
    }
    std::stable_sort(split_helpers_.begin(), split_helpers_.end(),
                     [](const auto& a, const auto& b) { return a.second.x < b.second.x; });
    split_cells_.clear();
    for (int i : hull_cells_) {
      // Detected cells not yet inspected are work too: a band passing abreast inspects them
      // (else they would wait, unowned, for the helpers at the end).
      const bool detected = view.map[i] == sim::kCorrosionSeen && view.seen[i] != 0;
      if ((unobserved(view, i) && reachable(static_cast<int>(g), i, world::kReachZ2)) ||
          (detected && reachable(static_cast<int>(g), i, world::kReachZ1)))
        split_cells_.push_back(i);
    }
    const auto assign = [&](int k, int i) { owner_[i] = static_cast<std::int16_t>(k); };
    if (on_bands) {
      // On the band partition's grid: runs of its boustrophedon, in steps (a row of a band at
      // the sweep rate with its inspections, a band begun about one more).
      split_in_band_order(split_cells_, width_, band_start_, split_helpers_, split_load_,
                          1.0 / kSweepRate, 1.0, assign);
      continue;
    }
    std::stable_sort(split_cells_.begin(), split_cells_.end(),
                     [&](int a, int b) { return a % width_ < b % width_; });
    split_in_slabs(split_cells_, width_, split_helpers_, split_load_, cells_per_step, assign);
  }
}

int SweepInspectPlanner::first_of_planned_tour(grid::Cell from, std::span<const int> cells) {
  tour_points_.clear();
  for (const int i : cells) tour_points_.push_back(hull_cell(i));
  // The tour's end is free: pulling it towards the nearer end of the sweep after it (half the
  // flight there added to its cost) lowered T_m by 1.2 s and raised T_c by 0.9 s on the tuning
  // seeds.
  plan_open_tour(from, tour_points_, {.reach = h1_});
  const grid::Cell first = tour_points_.front();
  return first.y * width_ + first.x;
}

int SweepInspectPlanner::tour_steps(grid::Cell from, std::span<const int> cells) {
  // A nearest-first tour at z = 1 (Manhattan, the project's x-then-y flights) in which the
  // footprint (Chebyshev half-width h1) sees every cell along each leg: a planning estimate.
  tour_left_.assign(cells.begin(), cells.end());
  int steps = 0;
  grid::Cell at = from;
  while (!tour_left_.empty()) {
    int best_d = std::numeric_limits<int>::max();
    grid::Cell best{};
    for (const int i : tour_left_) {
      const grid::Cell c = hull_cell(i);
      const grid::Cell q{std::clamp(at.x, c.x - h1_, c.x + h1_),
                         std::clamp(at.y, c.y - h1_, c.y + h1_)};
      const int d = grid::manhattan(at, q);
      if (d < best_d) {
        best_d = d;
        best = q;
      }
    }
    steps += best_d;
    // Seen on the way: within h1 of the leg along x (row at.y), then of the leg along y.
    const int x_lo = std::min(at.x, best.x) - h1_;
    const int x_hi = std::max(at.x, best.x) + h1_;
    const int y_lo = std::min(at.y, best.y) - h1_;
    const int y_hi = std::max(at.y, best.y) + h1_;
    std::erase_if(tour_left_, [&](int i) {
      const grid::Cell c = hull_cell(i);
      const bool along_x = std::abs(c.y - at.y) <= h1_ && c.x >= x_lo && c.x <= x_hi;
      const bool along_y = std::abs(c.x - best.x) <= h1_ && c.y >= y_lo && c.y <= y_hi;
      return along_x || along_y;
    });
    at = best;
  }
  return steps;
}

std::size_t SweepInspectPlanner::split_tours(int a, grid::Cell pa, int b, grid::Cell pb,
                                             std::vector<int>& cells, int* later) {
  // Cells only a can inspect first, then by how much nearer they are to a than to b, cells only
  // b can inspect last (no-fly zones); a takes a prefix.
  const auto key = [&](int i) {
    const bool to_a = reachable(a, i, world::kReachZ1);
    const bool to_b = reachable(b, i, world::kReachZ1);
    if (to_a != to_b)
      return to_a ? std::numeric_limits<int>::min() : std::numeric_limits<int>::max();
    const grid::Cell c = hull_cell(i);
    return grid::manhattan(pa, c) - grid::manhattan(pb, c);
  };
  std::stable_sort(cells.begin(), cells.end(), [&](int x, int y) { return key(x) < key(y); });
  std::size_t t_min = 0;
  std::size_t t_max = cells.size();
  while (t_min < cells.size() && key(cells[t_min]) == std::numeric_limits<int>::min()) ++t_min;
  while (t_max > t_min && key(cells[t_max - 1]) == std::numeric_limits<int>::max()) --t_max;
  const std::span<const int> all(cells);
  const auto tour_a = [&](std::size_t t) { return tour_steps(pa, all.first(t)); };
  const auto tour_b = [&](std::size_t t) { return tour_steps(pb, all.subspan(t)); };
  std::size_t lo = t_min;
  std::size_t hi = t_max;
  while (lo < hi) {  // the first t at which a's tour is at least b's (the estimates cross)
    const std::size_t mid = (lo + hi) / 2;
    if (tour_a(mid) >= tour_b(mid)) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  std::size_t t = lo;
  int end = std::max(tour_a(t), tour_b(t));
  if (t > t_min) {
    const int before = std::max(tour_a(t - 1), tour_b(t - 1));
    if (before <= end) {
      t -= 1;
      end = before;
    }
  }
  *later = end;
  return t;
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
    const int steps = tour_steps(positions_[j], prior_[j]);
    if (steps > giver_steps) {
      giver_steps = steps;
      giver = static_cast<int>(j);
    }
  }
  if (giver < 0) return false;
  auto& cells = prior_[static_cast<std::size_t>(giver)];
  int later = 0;
  const std::size_t t =
      split_tours(k, pos, giver, positions_[static_cast<std::size_t>(giver)], cells, &later);
  // Only when it saves the giver at least a strip's width of steps.
  if (t == 0 || later + (2 * h2_ + 1) > giver_steps) return false;
  prior_[ku].assign(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(t));
  cells.erase(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(t));
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
      const int now = std::max(tour_steps(pa, cells_a), tour_steps(pb, cells_b));
      split_cells_.assign(cells_a.begin(), cells_a.end());
      split_cells_.insert(split_cells_.end(), cells_b.begin(), cells_b.end());
      int later = 0;
      const std::size_t t = split_tours(a, pa, b, pb, split_cells_, &later);
      if (later >= now) continue;
      cells_a.assign(split_cells_.begin(), split_cells_.begin() + static_cast<std::ptrdiff_t>(t));
      cells_b.assign(split_cells_.begin() + static_cast<std::ptrdiff_t>(t), split_cells_.end());
    }
  }
}

grid::Cell SweepInspectPlanner::rejoin_point(int k, const Uav& p, grid::Cell pos,
                                             const sim::PlannerView& view) const {
  // From the point where it left the strip (on the strip's centre line, at z = 2) the UAV saw the
  // strip band up to h2 cells ahead, and on the way below it saw more of it; from a point r of the
  // centre line the footprint sees h2 cells behind r. So it may rejoin at any r, towards the strip
  // end it is flying to, up to where it now is, that leaves no cell of the band between the two
  // footprints unobserved.
  const grid::Cell end = p.sweep.target();
  const bool rows = leg_along_x(p.axis, p.resume, end);
  const int end_along = rows ? end.x : end.y;
  const int resume_along = rows ? p.resume.x : p.resume.y;
  const int line = rows ? p.resume.y : p.resume.x;
  if ((rows ? end.y : end.x) != line || end_along == resume_along) return p.resume;
  const int dir = end_along > resume_along ? 1 : -1;
  const int reach = std::min(std::max(0, dir * ((rows ? pos.x : pos.y) - resume_along)),
                             std::abs(end_along - resume_along));
  const auto& map = view.map;
  const int across_size = rows ? map.height() : map.width();
  int ahead = 0;
  for (int r = 1; r <= reach; ++r) {
    // The band's cells across at `along`, just behind r's footprint, must have been observed.
    const int along = resume_along + dir * (r - h2_ - 1);
    if (r > 2 * h2_ + 1) {
      bool gap = false;
      for (int a = std::max(0, line - h2_); a <= std::min(across_size - 1, line + h2_); ++a) {
        const int i = rows ? map.index(along, a) : map.index(a, along);
        if (map[i] != sim::kNotHull && unobserved(view, i)) gap = true;
      }
      if (gap) break;
    }
    const grid::Cell candidate =
        rows ? grid::Cell{resume_along + dir * r, line} : grid::Cell{line, resume_along + dir * r};
    if (uav_distances_[static_cast<std::size_t>(k)]->allowed(candidate)) ahead = r;
  }
  return rows ? grid::Cell{resume_along + dir * ahead, line}
              : grid::Cell{line, resume_along + dir * ahead};
}

bool SweepInspectPlanner::leg_sees_unobserved(grid::Cell a, grid::Cell b, bool low,
                                              const sim::PlannerView& view) const {
  // At z = 1 (a low sweep) the footprint is s1 wide, and it also inspects the detected cells.
  const auto& map = view.map;
  const int h = low ? h1_ : h2_;
  const int x_lo = std::max(0, std::min(a.x, b.x) - h);
  const int x_hi = std::min(map.width() - 1, std::max(a.x, b.x) + h);
  const int y_lo = std::max(0, std::min(a.y, b.y) - h);
  const int y_hi = std::min(map.height() - 1, std::max(a.y, b.y) + h);
  for (int y = y_lo; y <= y_hi; ++y) {
    for (int x = x_lo; x <= x_hi; ++x) {
      const int i = map.index(x, y);
      if (unobserved(view, i) || (low && map[i] == sim::kCorrosionSeen)) return true;
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
