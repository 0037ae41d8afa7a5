#include "hullinspect/planners/lawnmower_no_fly.hpp"

#include <algorithm>
#include <cstdlib>

#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::planners {

namespace {

// Marks every cell within Chebyshev radius `half` of `p`.
void mark(grid::Grid<std::uint8_t>& covered, grid::Cell p, int half) {
  for (int y = std::max(0, p.y - half); y <= std::min(covered.height() - 1, p.y + half); ++y) {
    for (int x = std::max(0, p.x - half); x <= std::min(covered.width() - 1, p.x + half); ++x) {
      covered(x, y) = 1;
    }
  }
}

// The flown positions from `from` through `waypoints`, marked in `covered`; returns the end.
grid::Cell fly(grid::DistanceService& distances, grid::Cell from,
               const std::vector<grid::Cell>& waypoints, int half,
               grid::Grid<std::uint8_t>& covered, std::vector<grid::Cell>& scratch) {
  grid::Cell at = from;
  mark(covered, at, half);
  for (const grid::Cell& w : waypoints) {
    scratch.clear();
    distances.append_path(at, w, scratch);
    for (const grid::Cell& c : scratch) mark(covered, c, half);
    if (!scratch.empty()) at = scratch.back();
  }
  return at;
}

// Appends point visits until every cell of `targets` is covered (cells without a viewpoint at
// this footprint are left out): each time the uncovered target whose viewpoint is nearest to the
// current end (ties: lowest (y, x) of the cell), flown to along shortest paths.
grid::Cell visit_uncovered(grid::DistanceService& distances, grid::Cell at,
                           const std::vector<int>& targets, int half,
                           grid::Grid<std::uint8_t>& covered, std::vector<grid::Cell>& waypoints,
                           std::vector<grid::Cell>& scratch) {
  for (;;) {
    const grid::Grid<int>& field = distances.field(at);
    grid::Cell best = grid::kNoCell;
    int best_distance = grid::kUnreachable;
    for (int i : targets) {
      if (covered[i] != 0) continue;
      const grid::Cell v = distances.viewpoint(covered.cell(i), half);
      if (v == grid::kNoCell || field[v] >= best_distance) continue;
      best_distance = field[v];
      best = v;
    }
    if (best == grid::kNoCell) return at;
    waypoints.push_back(best);
    scratch.clear();
    distances.append_path(at, best, scratch);
    for (const grid::Cell& c : scratch) mark(covered, c, half);
    mark(covered, best, half);
    at = best;
  }
}

}  // namespace

StripColumns strip_columns(const grid::Grid<std::int16_t>& owner, int uav, int y_begin, int y_end) {
  StripColumns columns{owner.width(), -1};
  for (int y = y_begin; y < y_end; ++y) {
    for (int x = 0; x < owner.width(); ++x) {
      if (owner(x, y) == uav) {
        columns.first = std::min(columns.first, x);
        columns.last = std::max(columns.last, x);
      }
    }
  }
  return columns;
}

LawnmowerRoute lawnmower_route_around_no_fly(const grid::Grid<std::int16_t>& owner, int uav, int s1,
                                             int s2, grid::Cell from,
                                             grid::DistanceService& distances,
                                             const grid::Grid<std::uint8_t>& reach) {
  LawnmowerRoute route;
  const int b = owner.height();
  const int half1 = world::footprint_half(s1);
  const int half2 = world::footprint_half(s2);
  grid::Cell at = from;
  std::vector<std::pair<int, int>> runs;
  for (int y_begin = 0; y_begin < b; y_begin += s1) {
    const int y_end = std::min(b, y_begin + s1);
    const StripColumns columns = strip_columns(owner, uav, y_begin, y_end);
    if (columns.empty()) continue;
    const int x_min = columns.first;
    const int x_max = columns.last;
    const int row = std::min(y_begin + half1, b - 1);
    // The flight row split into runs of allowed positions; the gaps are flown around.
    runs.clear();
    for (int x = x_min; x <= x_max + 1; ++x) {
      const bool ok = x <= x_max && distances.allowed(grid::Cell{x, row});
      if (ok && (runs.empty() || runs.back().second != x - 1)) runs.emplace_back(x, x);
      if (ok) runs.back().second = x;
    }
    if (runs.empty()) continue;
    const grid::Cell left{runs.front().first, row};
    const grid::Cell right{runs.back().second, row};
    const bool reversed = distances.distance(at, right) < distances.distance(at, left);
    if (reversed) {
      for (auto r = runs.rbegin(); r != runs.rend(); ++r) {
        route.z1.push_back({r->second, row});
        route.z1.push_back({r->first, row});
      }
    } else {
      for (const auto& r : runs) {
        route.z1.push_back({r.first, row});
        route.z1.push_back({r.second, row});
      }
    }
    at = route.z1.back();
  }
  // What the sweep misses (behind no-fly runs) is visited point by point at z = 1; cells no z = 1
  // footprint reaches are seen from z = 2 after a climb.
  grid::Grid<std::uint8_t> covered(owner.width(), owner.height(), 0);
  std::vector<grid::Cell> scratch;
  at = fly(distances, from, route.z1, half1, covered, scratch);
  std::vector<int> z1_targets;
  std::vector<int> z2_targets;
  for (int i = 0; i < owner.size(); ++i) {
    if (owner[i] != uav) continue;
    if ((reach[i] & world::kReachZ1) != 0) {
      z1_targets.push_back(i);
    } else if ((reach[i] & world::kReachZ2) != 0) {
      z2_targets.push_back(i);
    }
  }
  at = visit_uncovered(distances, at, z1_targets, half1, covered, route.z1, scratch);
  covered.fill(0);
  visit_uncovered(distances, at, z2_targets, half2, covered, route.z2, scratch);
  return route;
}

}  // namespace hullinspect::planners
