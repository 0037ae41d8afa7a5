#include "hullinspect/planners/prior_tour_split.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace hullinspect::planners {

PriorTourSplitter::PriorTourSplitter(int width, int half, std::size_t capacity)
    : width_(width), half_(half) {
  left_.reserve(capacity);
}

int PriorTourSplitter::tour_steps(grid::Cell from, std::span<const int> cells) {
  // Positions, not indices: the nearest-first loop reads every cell left at every leg.
  left_.clear();
  for (const int i : cells) left_.push_back(cell(i));
  int steps = 0;
  grid::Cell at = from;
  while (!left_.empty()) {
    int best_d = std::numeric_limits<int>::max();
    grid::Cell best{};
    for (const grid::Cell c : left_) {
      const grid::Cell q{std::clamp(at.x, c.x - half_, c.x + half_),
                         std::clamp(at.y, c.y - half_, c.y + half_)};
      const int d = grid::manhattan(at, q);
      if (d < best_d) {
        best_d = d;
        best = q;
        if (d == 0) break;  // none is nearer, and the first of equals is kept
      }
    }
    steps += best_d;
    // Seen on the way: within half of the leg along x (row at.y), then of the leg along y.
    const int x_lo = std::min(at.x, best.x) - half_;
    const int x_hi = std::max(at.x, best.x) + half_;
    const int y_lo = std::min(at.y, best.y) - half_;
    const int y_hi = std::max(at.y, best.y) + half_;
    std::erase_if(left_, [&](grid::Cell c) {
      const bool along_x = std::abs(c.y - at.y) <= half_ && c.x >= x_lo && c.x <= x_hi;
      const bool along_y = std::abs(c.x - best.x) <= half_ && c.y >= y_lo && c.y <= y_hi;
      return along_x || along_y;
    });
    at = best;
  }
  return steps;
}

PriorTourSplitter::Split PriorTourSplitter::split(grid::Cell pa, grid::Cell pb,
                                                  std::vector<int>& cells, const OnlyOne& only) {
  const auto key = [&](int i) {
    const int side = only(i);
    if (side != 0)
      return side < 0 ? std::numeric_limits<int>::min() : std::numeric_limits<int>::max();
    const grid::Cell c = cell(i);
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
  return {t, end};
}

}  // namespace hullinspect::planners
