#include "hullinspect/planners/coop_frontier_shrinking_field.hpp"

#include <algorithm>
#include <cstdlib>

#include "hullinspect/grid/distance.hpp"

namespace hullinspect::planners {

CellWindow affected_window(std::span<const int> removed, const grid::Grid<int>& distance) {
  const int w = distance.width();
  const int h = distance.height();
  CellWindow window{w, -1, h, -1};
  for (const int s : removed) {
    const int sx = s % w;
    const int sy = s / w;
    // Along s's row and column, as far as s stays a nearest member.
    int x0 = sx;
    while (x0 > 0 && distance(x0 - 1, sy) == sx - x0 + 1) --x0;
    int x1 = sx;
    while (x1 + 1 < w && distance(x1 + 1, sy) == x1 + 1 - sx) ++x1;
    int y0 = sy;
    while (y0 > 0 && distance(sx, y0 - 1) == sy - y0 + 1) --y0;
    int y1 = sy;
    while (y1 + 1 < h && distance(sx, y1 + 1) == y1 + 1 - sy) ++y1;
    window.x0 = std::min(window.x0, x0);
    window.x1 = std::max(window.x1, x1);
    window.y0 = std::min(window.y0, y0);
    window.y1 = std::max(window.y1, y1);
  }
  return window;
}

long long remove_members(std::span<const int> removed, const grid::Grid<std::uint8_t>& members,
                         grid::Grid<int>& distance) {
  const CellWindow inner = affected_window(removed, distance);
  if (inner.empty()) return 0;
  const int w = distance.width();
  const int h = distance.height();
  // The window and its ring (clipped to the grid: no member lies beyond it).
  const int x0 = std::max(0, inner.x0 - 1);
  const int x1 = std::min(w - 1, inner.x1 + 1);
  const int y0 = std::max(0, inner.y0 - 1);
  const int y1 = std::min(h - 1, inner.y1 + 1);
  constexpr int kFar = grid::kUnreachable;
  int* d = distance.values().data();
  const std::uint8_t* m = members.values().data();
  for (int y = inner.y0; y <= inner.y1; ++y) {
    int* row = d + static_cast<std::ptrdiff_t>(y) * w;
    const std::uint8_t* s = m + static_cast<std::ptrdiff_t>(y) * w;
    for (int x = inner.x0; x <= inner.x1; ++x) row[x] = s[x] ? 0 : kFar;
  }
  // The two passes of grid::manhattan_distance_transform, over the window, from these values.
  for (int y = y0; y <= y1; ++y) {
    int* row = d + static_cast<std::ptrdiff_t>(y) * w;
    if (y > y0) {
      const int* below = row - w;
      for (int x = x0; x <= x1; ++x) row[x] = std::min(row[x], below[x] + 1);
    }
    for (int x = x0 + 1; x <= x1; ++x) row[x] = std::min(row[x], row[x - 1] + 1);
  }
  for (int y = y1; y >= y0; --y) {
    int* row = d + static_cast<std::ptrdiff_t>(y) * w;
    if (y < y1) {
      const int* above = row + w;
      for (int x = x0; x <= x1; ++x) row[x] = std::min(row[x], above[x] + 1);
    }
    for (int x = x1 - 1; x >= x0; --x) row[x] = std::min(row[x], row[x + 1] + 1);
    for (int x = x0; x <= x1; ++x) row[x] = std::min(row[x], kFar);
  }
  return static_cast<long long>(x1 - x0 + 1) * (y1 - y0 + 1);
}

}  // namespace hullinspect::planners
