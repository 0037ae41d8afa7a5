#include "hullinspect/planners/sweep_approach.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>

#include "hullinspect/planners/owned_runs.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::planners {

namespace {

/// The waypoints flown backwards when their far end is nearer to `from`.
void nearer_end_first(std::vector<grid::Cell>& waypoints, grid::Cell from, bool nearer_end) {
  if (nearer_end && waypoints.size() > 1 &&
      grid::manhattan(from, waypoints.back()) < grid::manhattan(from, waypoints.front()))
    std::reverse(waypoints.begin(), waypoints.end());
}

/// The bounding box of the cells where `owner` is `uav`, in one scan (x_hi < 0: none).
struct OwnedBox {
  int x_lo, x_hi, y_lo, y_hi;
};
OwnedBox owned_box(const grid::Grid<std::int16_t>& owner, int uav) {
  OwnedBox box{owner.width(), -1, owner.height(), -1};
  for (int y = 0; y < owner.height(); ++y) {
    for (int x = 0; x < owner.width(); ++x) {
      if (owner(x, y) != uav) continue;
      box.x_lo = std::min(box.x_lo, x);
      box.x_hi = std::max(box.x_hi, x);
      box.y_lo = std::min(box.y_lo, y);
      box.y_hi = std::max(box.y_hi, y);
    }
  }
  return box;
}

/// The own-band plans: in two parts (approach_candidates' doc) over `region` (the owner's
/// bands of request.uav), appended to `candidates`.
void own_band_first(const grid::Grid<std::int16_t>& owner, const SweepRequest& request,
                    const RegionBands& region, grid::Cell from, int across_lo, int across_hi,
                    SweepScratch& scratch, std::vector<SweepCandidate>& candidates) {
  const bool rows = request.axis == BandAxis::kRows;
  const int s = request.band;
  const int h = world::footprint_half(s);
  const int across_size = rows ? owner.height() : owner.width();
  const int along_size = rows ? owner.width() : owner.height();
  // Each band's cells along it, as the last cell at or before and the first at or after each
  // along coordinate, so that a band cut anywhere is two extents read in O(1).
  const std::size_t count = region.bands.size();
  const auto at = [along_size](std::size_t j, int a) {
    return j * static_cast<std::size_t>(along_size) + static_cast<std::size_t>(a);
  };
  scratch.last_upto.assign(count * static_cast<std::size_t>(along_size), -1);
  scratch.first_from.assign(count * static_cast<std::size_t>(along_size),
                            std::numeric_limits<int>::max());
  for (int y = 0; y < owner.height(); ++y) {
    for (int x = request.x_lo; x <= request.x_hi; ++x) {
      if (owner(x, y) != request.uav) continue;
      const int a = rows ? x : y;
      const auto j = static_cast<std::size_t>(((rows ? y : x) - region.origin) / s);
      scratch.last_upto[at(j, a)] = a;
      scratch.first_from[at(j, a)] = a;
    }
  }
  for (std::size_t j = 0; j < count; ++j) {
    for (int a = 1; a < along_size; ++a)
      scratch.last_upto[at(j, a)] =
          std::max(scratch.last_upto[at(j, a)], scratch.last_upto[at(j, a - 1)]);
    for (int a = along_size - 2; a >= 0; --a)
      scratch.first_from[at(j, a)] =
          std::min(scratch.first_from[at(j, a)], scratch.first_from[at(j, a + 1)]);
  }
  const int from_along = rows ? from.x : from.y;
  const int from_across = std::clamp(rows ? from.y : from.x, across_lo, across_hi);
  const int own = (from_across - region.origin) / s;
  const auto last_upto = [&](std::size_t j, int a) {
    return a < 0 ? -1 : scratch.last_upto[at(j, std::min(a, along_size - 1))];
  };
  const auto first_from = [&](std::size_t j, int a) {
    return a >= along_size ? std::numeric_limits<int>::max()
                           : scratch.first_from[at(j, std::max(a, 0))];
  };
  scratch.first.origin = region.origin;
  scratch.second.origin = region.origin;
  for (const int offset : {0, -h, h}) {
    const int cut = from_along + offset;
    for (const int across_side : {1, -1}) {
      // along_side 0: the bands' whole extents; -1: their cells up to the cut; 1: from it.
      for (const int along_side : {0, -1, 1}) {
        if (offset != 0 && along_side == 0) continue;  // no cut: once
        scratch.first.bands.assign(count, BandExtent{});
        scratch.second.bands.assign(count, BandExtent{});
        bool any = false;
        for (std::size_t j = 0; j < count; ++j) {
          const BandExtent e = region.bands[j];
          if (e.hi < 0) continue;
          BandExtent& one = scratch.first.bands[j];
          BandExtent& two = scratch.second.bands[j];
          if (across_side * (static_cast<int>(j) - own) < 0) {
            two = e;
          } else if (along_side == 0) {
            one = e;
          } else {
            // The cells on the first part's side of the cut, and the others; near_end is the
            // last along coordinate of the lower side.
            const int near_end = along_side < 0 ? cut : cut - 1;
            const BandExtent low{e.lo, last_upto(j, near_end)};
            const BandExtent high{first_from(j, near_end + 1), e.hi};
            (along_side < 0 ? one : two) = low.lo <= low.hi ? low : BandExtent{};
            (along_side < 0 ? two : one) = high.lo <= high.hi ? high : BandExtent{};
          }
          any = any || one.hi >= 0;
        }
        if (!any) continue;
        auto first =
            sweep_bands(scratch.first, s, request.axis, request.trim_ends, from, across_size);
        nearer_end_first(first, from, request.nearer_end);
        if (first.empty()) continue;
        auto second = sweep_bands(scratch.second, s, request.axis, request.trim_ends, first.back(),
                                  across_size);
        nearer_end_first(second, first.back(), request.nearer_end);
        SweepCandidate candidate;
        candidate.plan.waypoints = std::move(first);
        candidate.plan.waypoints.insert(candidate.plan.waypoints.end(), second.begin(),
                                        second.end());
        candidate.plan.own_band_first = true;
        candidate.cost = manhattan_cost(from, candidate.plan.waypoints);
        candidates.push_back(std::move(candidate));
      }
    }
  }
}

}  // namespace

std::vector<grid::Cell> plain_sweep(const grid::Grid<std::int16_t>& owner,
                                    const SweepRequest& request, grid::Cell from) {
  auto waypoints = band_sweep(owner, request.uav, request.band, request.axis, request.trim_ends,
                              from, request.band_start, request.x_lo, request.x_hi);
  nearer_end_first(waypoints, from, request.nearer_end);
  return waypoints;
}

std::vector<SweepCandidate> two_block_candidates(const grid::Grid<std::int16_t>& owner,
                                                 const SweepRequest& request, grid::Cell from,
                                                 std::vector<grid::Cell> plain) {
  const OwnedBox box = owned_box(owner, request.uav);
  const int x_lo = box.x_lo;
  const int x_hi = box.x_hi;
  const bool rows = request.axis == BandAxis::kRows;
  const auto cut_here = [&](int x) {
    if (rows || request.band_start.empty()) return (x - x_lo) % request.band == 0;
    return request.band_start[static_cast<std::size_t>(x)] == x;
  };
  // A block is the request's columns on one side of the cut: band_sweep reads only those.
  SweepRequest left = request;
  SweepRequest right = request;
  left.x_lo = x_lo;
  right.x_hi = x_hi;
  std::vector<SweepCandidate> candidates(1);
  candidates[0].cost = manhattan_cost(from, plain);
  candidates[0].plan.waypoints = std::move(plain);
  for (int cut = x_lo + 1; cut <= x_hi; ++cut) {
    if (!cut_here(cut)) continue;
    left.x_hi = cut - 1;
    right.x_lo = cut;
    for (const bool left_first : {true, false}) {
      auto waypoints = plain_sweep(owner, left_first ? left : right, from);
      const grid::Cell end = waypoints.empty() ? from : waypoints.back();
      const auto rest = plain_sweep(owner, left_first ? right : left, end);
      waypoints.insert(waypoints.end(), rest.begin(), rest.end());
      SweepCandidate candidate;
      candidate.cost = manhattan_cost(from, waypoints);
      candidate.plan.waypoints = std::move(waypoints);
      candidates.push_back(std::move(candidate));
    }
  }
  return candidates;
}

std::vector<grid::Cell> two_block_sweep(const grid::Grid<std::int16_t>& owner,
                                        const SweepRequest& request, grid::Cell from,
                                        std::vector<grid::Cell> plain) {
  auto candidates = two_block_candidates(owner, request, from, std::move(plain));
  return take_chosen(candidates).waypoints;
}

std::vector<SweepCandidate> axis_candidates(const grid::Grid<std::int16_t>& owner, int uav,
                                            int band, grid::Cell from,
                                            std::span<const int> band_start) {
  std::vector<SweepCandidate> candidates(2);
  for (const BandAxis axis : {BandAxis::kRows, BandAxis::kColumns}) {
    SweepCandidate& candidate = candidates[axis == BandAxis::kRows ? 0 : 1];
    candidate.plan.waypoints = band_sweep(owner, uav, band, axis, true, from, band_start);
    candidate.cost = manhattan_cost(from, candidate.plan.waypoints);
  }
  return candidates;
}

std::vector<SweepCandidate> approach_candidates(const grid::Grid<std::int16_t>& owner,
                                                const SweepRequest& request, grid::Cell from,
                                                SweepScratch& scratch_space) {
  // The region's cells as runs along its bands, read once: its extent, the plain sweep's bands,
  // and each approach's bands (the region less the approach's footprints) come from the runs.
  OwnedRuns& runs = scratch_space.runs;
  runs.build(owner, request.uav, request.axis, request.x_lo, request.x_hi);
  const LegBox region_box = runs.box();
  const int x_lo = region_box.x_lo, x_hi = region_box.x_hi;
  const int y_lo = region_box.y_lo, y_hi = region_box.y_hi;
  std::vector<SweepCandidate> candidates(1);  // the plain sweep first
  if (x_hi < 0) return candidates;
  SweepRequest within = request;
  within.x_lo = x_lo;
  within.x_hi = x_hi;
  const RegionBands region = runs.bands(request.band, request.band_start);
  const int across_size = request.axis == BandAxis::kRows ? owner.height() : owner.width();
  std::vector<grid::Cell>& plain = candidates[0].plan.waypoints;
  plain = sweep_bands(region, request.band, request.axis, request.trim_ends, from, across_size);
  nearer_end_first(plain, from, request.nearer_end);
  candidates[0].cost = manhattan_cost(from, plain);
  if (plain.empty()) return candidates;
  const grid::Cell plain_first = plain.front();
  const bool rows = request.axis == BandAxis::kRows;
  // "along" runs along a band (y for column bands), "across" from band to band.
  const auto along = [rows](grid::Cell c) { return rows ? c.x : c.y; };
  const auto across = [rows](grid::Cell c) { return rows ? c.y : c.x; };
  const auto cell = [rows](int along_at, int across_at) {
    return rows ? grid::Cell{along_at, across_at} : grid::Cell{across_at, along_at};
  };
  const int along_lo = rows ? x_lo : y_lo;
  const int along_hi = rows ? x_hi : y_hi;
  const int across_lo = rows ? y_lo : x_lo;
  const int across_hi = rows ? y_hi : x_hi;
  const int h = world::footprint_half(request.band);
  if (along_lo + h > along_hi - h) return candidates;  // a region no taller than one footprint
  // The centre line of the band holding an across coordinate (band_sweep's bands).
  const auto centre = [&](int a) {
    int band_first = across_lo + (a - across_lo) / request.band * request.band;
    if (!rows && !request.band_start.empty())
      band_first = request.band_start[static_cast<std::size_t>(a)];
    return std::min(band_first + h, across_size - 1);
  };
  const int from_along = along(from);
  const int from_across = across(from);
  const std::array<int, 2> edges{along_lo + h, along_hi - h};
  const std::array<int, 2> lines{from_across,
                                 centre(std::clamp(from_across, across_lo, across_hi))};
  for (std::size_t l = 0; request.edge_approach && l < lines.size(); ++l) {
    const int line = lines[l];
    if (l > 0 && line == lines[0]) continue;  // on a band's centre line already
    for (const int edge : edges) {
      const std::array<int, 2> targets{line, across(plain_first)};
      for (std::size_t t = 0; t < targets.size(); ++t) {
        const int target = targets[t];
        if (t > 0 && target == targets[0]) continue;  // the plain sweep starts on this line
        // from → (line, from_along) → (line, edge) → (target, edge), each leg straight.
        const std::array<grid::Cell, 4> path{from, cell(from_along, line), cell(edge, line),
                                             cell(edge, target)};
        // The region less what the approach's footprints see.
        int length = 0;
        std::array<LegBox, 3> seen;  // one box per leg
        for (std::size_t leg = 1; leg < path.size(); ++leg) {
          const grid::Cell a = path[leg - 1];
          const grid::Cell b = path[leg];
          length += grid::manhattan(a, b);
          seen[leg - 1] = leg_footprints(a, b, h, owner.width(), owner.height());
        }
        auto sweep = sweep_bands(runs.bands(request.band, request.band_start, seen), request.band,
                                 request.axis, request.trim_ends, path.back(), across_size);
        nearer_end_first(sweep, path.back(), request.nearer_end);
        // The approach's legs and the flight to the first band are its reach.
        const PlanCost bands = manhattan_cost(path.back(), sweep);
        SweepCandidate candidate;
        candidate.cost = {length + bands.reach, bands.bands};
        std::vector<grid::Cell>& waypoints = candidate.plan.waypoints;
        for (std::size_t i = 1; i < path.size(); ++i) {
          if (path[i] != path[i - 1] && (waypoints.empty() || waypoints.back() != path[i]))
            waypoints.push_back(path[i]);
        }
        candidate.plan.approach = waypoints.size();
        waypoints.insert(waypoints.end(), sweep.begin(), sweep.end());
        candidates.push_back(std::move(candidate));
      }
    }
  }
  if (request.own_band_first)
    own_band_first(owner, within, region, from, across_lo, across_hi, scratch_space, candidates);
  return candidates;
}

SweepPlan approach_and_sweep(const grid::Grid<std::int16_t>& owner, const SweepRequest& request,
                             grid::Cell from, SweepScratch& scratch) {
  auto candidates = approach_candidates(owner, request, from, scratch);
  return take_chosen(candidates);
}

}  // namespace hullinspect::planners
