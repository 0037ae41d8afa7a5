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

int plan_length(grid::Cell pos, std::span<const grid::Cell> waypoints) {
  int steps = 0;
  for (const grid::Cell& w : waypoints) {
    steps += grid::manhattan(pos, w);
    pos = w;
  }
  return steps;
}

void flight_field(grid::DistanceService& distances, grid::Cell from, grid::Grid<int>& out) {
  if (distances.has_no_fly()) {
    out = distances.field(from);  // same size: the copy reuses out's storage
    return;
  }
  for (int i = 0; i < out.size(); ++i) out[i] = grid::manhattan(from, out.cell(i));
}

}  // namespace hullinspect::planners::part_tsp
