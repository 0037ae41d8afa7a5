#include "hullinspect/planners/open_tour.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace hullinspect::planners {

int OpenTourCost::leg(grid::Cell a, grid::Cell b) const {
  return std::max(0, std::abs(a.x - b.x) - reach) + std::max(0, std::abs(a.y - b.y) - reach);
}

int OpenTourCost::of(grid::Cell from, std::span<const grid::Cell> points) const {
  int total = 0;
  grid::Cell at = from;
  for (const grid::Cell p : points) {
    total += leg(at, p);
    at = p;
  }
  return total;
}

namespace {

/// Node i of the tour: 0 is the start, i ≥ 1 is points[i − 1].
struct Nodes {
  grid::Cell from;
  std::span<grid::Cell> points;
  grid::Cell operator()(std::size_t i) const { return i == 0 ? from : points[i - 1]; }
  std::size_t last() const { return points.size(); }
};

void nearest_neighbour(grid::Cell from, std::span<grid::Cell> points, const OpenTourCost& cost) {
  grid::Cell at = from;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::size_t best = i;
    int best_d = std::numeric_limits<int>::max();
    for (std::size_t j = i; j < points.size(); ++j) {
      const int d = cost.leg(at, points[j]);
      if (d < best_d) {
        best_d = d;
        best = j;
      }
    }
    std::swap(points[i], points[best]);
    at = points[i];
  }
}

/// One pass of 2-opt: reverses nodes i..j where that is shorter. True if it changed the tour.
bool two_opt_pass(const Nodes& node, const OpenTourCost& cost) {
  const std::size_t m = node.last();
  bool improved = false;
  for (std::size_t i = 1; i < m; ++i) {
    for (std::size_t j = i + 1; j <= m; ++j) {
      // The edges into i and out of j change (out of j: none when j is the last node).
      const int before =
          cost.leg(node(i - 1), node(i)) + (j < m ? cost.leg(node(j), node(j + 1)) : 0);
      const int after =
          cost.leg(node(i - 1), node(j)) + (j < m ? cost.leg(node(i), node(j + 1)) : 0);
      if (after < before) {
        std::reverse(node.points.begin() + static_cast<std::ptrdiff_t>(i - 1),
                     node.points.begin() + static_cast<std::ptrdiff_t>(j));
        improved = true;
      }
    }
  }
  return improved;
}

/// One pass of Or-opt: moves the run of nodes a..b (1–3 of them) to after node t, forward or
/// reversed, where that is shorter. True if it changed the tour.
bool or_opt_pass(const Nodes& node, const OpenTourCost& cost) {
  const std::size_t m = node.last();
  bool improved = false;
  for (std::size_t len = 1; len <= 3; ++len) {
    for (std::size_t a = 1; a + len - 1 <= m; ++a) {
      const std::size_t b = a + len - 1;
      // Taking the run out joins a − 1 to b + 1 (or makes a − 1 the last node).
      const int removed =
          cost.leg(node(a - 1), node(a)) +
          (b < m ? cost.leg(node(b), node(b + 1)) - cost.leg(node(a - 1), node(b + 1)) : 0);
      int best_gain = 0;
      std::size_t best_t = 0;
      bool best_reversed = false;
      for (std::size_t t = 0; t <= m; ++t) {
        if (t + 1 >= a && t <= b) continue;  // next to or inside the run: no move
        // Between t and t + 1, or after the last node.
        const bool at_end = t == m;
        const int base = at_end ? 0 : cost.leg(node(t), node(t + 1));
        const int forward =
            cost.leg(node(t), node(a)) + (at_end ? 0 : cost.leg(node(b), node(t + 1)));
        const int reversed =
            cost.leg(node(t), node(b)) + (at_end ? 0 : cost.leg(node(a), node(t + 1)));
        if (removed - (forward - base) > best_gain) {
          best_gain = removed - (forward - base);
          best_t = t;
          best_reversed = false;
        }
        if (removed - (reversed - base) > best_gain) {
          best_gain = removed - (reversed - base);
          best_t = t;
          best_reversed = true;
        }
      }
      if (best_gain > 0) {
        // Points index = node − 1: the run is points[a − 1, b), the insertion point after node t.
        const auto it = node.points.begin();
        const auto first = static_cast<std::ptrdiff_t>(a - 1);
        const auto past = static_cast<std::ptrdiff_t>(b);
        const auto t = static_cast<std::ptrdiff_t>(best_t);
        const auto run = static_cast<std::ptrdiff_t>(len);
        if (t < first) {
          std::rotate(it + t, it + first, it + past);
          if (best_reversed) std::reverse(it + t, it + t + run);
        } else {
          std::rotate(it + first, it + past, it + t);
          if (best_reversed) std::reverse(it + t - run, it + t);
        }
        improved = true;
      }
    }
  }
  return improved;
}

void improve_passes(grid::Cell from, std::span<grid::Cell> points, const OpenTourCost& cost) {
  const Nodes node{from, points};
  // Each pass that changes the tour shortens it by at least 1; the cap only bounds the time on
  // pathological inputs.
  constexpr int kMaxPasses = 50;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    const bool two = two_opt_pass(node, cost);
    const bool or_ = or_opt_pass(node, cost);
    if (!two && !or_) break;
  }
}

}  // namespace

void plan_open_tour_exhaustive(grid::Cell from, std::span<grid::Cell> points,
                               const OpenTourCost& cost) {
  nearest_neighbour(from, points, cost);
  improve_passes(from, points, cost);
}

void plan_open_tour(grid::Cell from, std::span<grid::Cell> points, const OpenTourCost& cost) {
  if (points.size() <= kExhaustiveTourPoints) {
    plan_open_tour_exhaustive(from, points, cost);
  } else {
    plan_open_tour_neighbours(from, points, cost);
  }
}

}  // namespace hullinspect::planners
