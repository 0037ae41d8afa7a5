// Sweep-Inspect's regions (docs/sweep-inspect.md, "Regions"): the band partition with its
// flight-balanced cuts, and the columns swept at z = 1.

#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/band_partition.hpp"
#include "hullinspect/planners/prior_weights.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::planners {

std::shared_ptr<const partition::Partition> SweepInspectPlanner::band_partition(
    const partition::PartitionRequest& request, const PlannerContext& context) {
  // One boustrophedon over the hull's bands (s1 wide in dense columns, s2 elsewhere), cut into
  // pieces of equal work, in the weights' unit (a clean cell swept at z = 2; a step sweeps s2
  // of them): a band is one step a row and about one more to reach it (its width across, less
  // the rows its trimmed ends save); at z = 2 a cell adds the inspections the weights expect
  // there (their excess over 1), at z = 1 nothing (it is inspected when seen).
  std::vector<int> width_of_column(static_cast<std::size_t>(width_), s2_);
  for (std::size_t x = 0; x < dense_column_.size(); ++x) {
    if (dense_column_[x] != 0) width_of_column[x] = s1_;
  }
  std::vector<int> band_start = column_band_starts(width_of_column);
  // An inspection on detection (a descent, a flight across the band and back, a climb) costs
  // more than its weight says, which is a planned z = 1 tour's (the prior's cells when toured).
  // The tours, though, are re-split among neighbours after the partition (balance_prior_tours): a
  // piece shrunk for its whole tour would lose sweep to pieces that then also take part of its
  // tour, and end early; so a toured prior cell weighs only kPriorTourWeight of an inspection.
  const bool toured = options_.prior_first && !prior_dropped_;
  grid::Grid<double> extra = request.weights;
  for (int i = 0; i < extra.size(); ++i) {
    const bool dense =
        !dense_column_.empty() && dense_column_[static_cast<std::size_t>(i % width_)] != 0;
    const double factor = toured && context.prior[i] == 1 ? kPriorTourWeight : kInspectionWeight;
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
    if (!tours && one_plane && reach_ == nullptr)
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
  // A piece's planned end depends only on its rows (owner_ holds exactly them) and its UAV's
  // start, and the passes try the same cuts again: each piece's end is planned once per rows.
  std::map<std::array<std::size_t, 3>, double> planned;
  const auto planned_end = [&](int piece) {
    const std::array<std::size_t, 3> key{static_cast<std::size_t>(piece), first_row(piece),
                                         end_row(piece)};
    const auto known = planned.find(key);
    if (known != planned.end()) return known->second;
    const int k = rows.uav_of_piece(piece);
    piece_columns_ = rows.columns(first_row(piece), end_row(piece));
    // The narrowed columns hold only for this plan, also when it throws (the partition then
    // falls back and the mission's sweeps read every column).
    struct WholeColumnsAfter {
      decltype(piece_columns_)& columns;
      ~WholeColumnsAfter() { columns = {0, -1}; }
    } whole_columns_after{piece_columns_};
    const double end = planned_sweep_steps(k, context.starts[static_cast<std::size_t>(k)]) +
                       rows.extra(first_row(piece), end_row(piece)) / step;
    planned.emplace(key, end);
    return end;
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
  for (int round = 0; round < kBalanceRounds; ++round) {
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
  double steps = flight_steps(k, from, first);
  if (p.other_part && !first.empty()) {
    const auto second = part_strips(k, !p.low, first.back());
    steps += flight_steps(k, first.back(), second);
  }
  return steps;
}

double SweepInspectPlanner::flight_steps(int k, grid::Cell from,
                                         const std::vector<grid::Cell>& waypoints) {
  double steps = 0;
  for (const grid::Cell w : waypoints) {
    steps += flight(k, from, w);
    from = w;
  }
  return steps;
}

int SweepInspectPlanner::flight(int k, grid::Cell a, grid::Cell b) {
  // The service's flight (Manhattan without no-fly zones); a position it cannot reach counts as
  // Manhattan, as the follower then flies as far as it can.
  const int d = uav_distances_[static_cast<std::size_t>(k)]->distance(a, b);
  return d == grid::kUnreachable ? grid::manhattan(a, b) : d;
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
  // No dense column: empty, so that a sweep's planning does not read a column's flag per cell.
  if (std::none_of(dense_column_.begin(), dense_column_.end(), [](char d) { return d != 0; }))
    dense_column_.clear();
}

}  // namespace hullinspect::planners
