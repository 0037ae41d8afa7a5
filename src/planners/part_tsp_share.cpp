#include "hullinspect/planners/part_tsp_share.hpp"

#include <algorithm>
#include <limits>

#include "hullinspect/grid/distance.hpp"

namespace hullinspect::planners::part_tsp {

namespace {
double cell_work(const LocalMaps& maps, std::int8_t value) {
  return value == sim::kCorrosionSeen
             ? static_cast<double>(maps.layout(2).s) / static_cast<double>(maps.layout(1).s)
             : 1.0;
}
}  // namespace

double remaining_work(const LocalMaps& maps, int k) {
  return maps.unknown_cells(k) +
         cell_work(maps, sim::kCorrosionSeen) * maps.corrosion_to_inspect(k);
}

void region_cells(const LocalMaps& maps, int k, bool every_cell, std::vector<int>& out) {
  out.clear();
  const int w = maps.width();
  for (int y = 0; y < maps.height(); ++y) {
    for (int x = maps.x_begin(k); x < maps.x_end(k); ++x) {
      const int i = y * w + x;
      if (maps.owner(i) != k) continue;
      const std::int8_t v = maps.value(i);
      if (every_cell || v == sim::kUnknown || v == sim::kCorrosionSeen) out.push_back(i);
    }
  }
}

bool helper_piece(const LocalMaps& maps, std::span<const int> cells,
                  const grid::Grid<int>& d_helper, const grid::Grid<int>& d_owner,
                  double owner_steps, double min_steps,
                  std::vector<std::pair<long long, int>>& order, std::vector<int>& piece) {
  piece.clear();
  order.clear();
  double total = 0;
  int d_near = grid::kUnreachable;
  for (int i : cells) {
    total += cell_work(maps, maps.value(i));
    const int dh = d_helper[i];
    const int dk = d_owner[i];
    if (dh >= grid::kUnreachable) continue;  // the helper cannot get there: stays with the owner
    d_near = std::min(d_near, dh);
    // A cell the owner cannot reach (not expected: a region lies in its owner's flight part)
    // goes first.
    const long long key = dk >= grid::kUnreachable ? std::numeric_limits<long long>::min()
                                                   : static_cast<long long>(dh) - dk;
    order.emplace_back(key, i);
  }
  if (order.empty()) return false;
  if (owner_steps <= 0) return false;
  const double fraction = (owner_steps - d_near) / (2 * owner_steps);
  if (fraction * owner_steps < min_steps) return false;
  const double target = fraction * total;
  std::sort(order.begin(), order.end());
  double taken = 0;
  for (const auto& [key, i] : order) {
    if (taken >= target) break;
    taken += cell_work(maps, maps.value(i));
    piece.push_back(i);
  }
  std::sort(piece.begin(), piece.end());
  return true;
}

int plan_tail(std::span<const PlannedVisit> visits, std::span<const grid::Cell> waypoints,
              grid::Cell owner_pos, grid::Cell helper_pos, double min_steps) {
  const std::size_t v = visits.size();
  if (v < 2 || waypoints.size() + 1 < 2 * v) return -1;
  // waypoints[w(i)] is visit i's entry (i ≥ 1); a begun first visit has only its exit left.
  const std::size_t offset = 2 * v - waypoints.size();  // 1 when the first visit is begun
  auto entry = [&](std::size_t i) { return waypoints[2 * i - offset]; };
  const int total = plan_length(owner_pos, waypoints);
  int best = -1;
  int best_end = total;
  int prefix = 0;  // the owner's flight to the exit of visit m − 1
  grid::Cell at = owner_pos;
  std::size_t w = 0;
  for (std::size_t m = 1; m < v; ++m) {
    const std::size_t exit_of_previous = 2 * m - 1 - offset;
    for (; w <= exit_of_previous; ++w) {
      prefix += grid::manhattan(at, waypoints[w]);
      at = waypoints[w];
    }
    const int tail = total - prefix - grid::manhattan(at, entry(m));
    const int helper_end = grid::manhattan(helper_pos, entry(m)) + tail;
    const int end = std::max(prefix, helper_end);
    if (end < best_end) {
      best_end = end;
      best = static_cast<int>(m);
    }
  }
  if (best < 0 || total - best_end < min_steps) return -1;
  return best;
}

void visit_cells(const LocalMaps& maps, int k, int z, std::int8_t value, const PlannedVisit& visit,
                 std::vector<int>& out) {
  const StripLayout& layout = maps.layout(z);
  const StripSegment& s = visit.segment;
  int x0 = s.x_left;
  int x1 = s.x_right;
  int y0 = layout.first_row(s.strip);
  int y1 = layout.last_row(s.strip);
  if (s.point != grid::kNoCell) {
    const int half = world::footprint_half(layout.s);
    x0 = std::max(0, s.point.x - half);
    x1 = std::min(maps.width() - 1, s.point.x + half);
    y0 = std::max(0, s.point.y - half);
    y1 = std::min(maps.height() - 1, s.point.y + half);
  }
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const int i = y * maps.width() + x;
      if (maps.owner(i) == k && maps.value(i) == value) out.push_back(i);
    }
  }
}

int plan_length(grid::Cell pos, std::span<const grid::Cell> waypoints) {
  int steps = 0;
  for (const grid::Cell& w : waypoints) {
    steps += grid::manhattan(pos, w);
    pos = w;
  }
  return steps;
}

void flight_field(grid::DistanceService& distances, grid::Cell from, grid::Grid<int>& out) {
  if (distances.searched()) {
    out = distances.field(from);  // same size: the copy reuses out's storage
    return;
  }
  for (int i = 0; i < out.size(); ++i) out[i] = grid::manhattan(from, out.cell(i));
}

}  // namespace hullinspect::planners::part_tsp
