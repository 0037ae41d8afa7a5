#pragma once
// Helpers shared by the Part-TSP tests: a small exact segment-TSP solver to inject into the planner
// (independent of the tsp module's solvers), hand-made instances, and a plan observer.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::testing {

/// Held–Karp over (set of segments flown, last segment, its exit end): exact for up to 10
/// segments; beyond that, nearest entry first (enough for tests of the planner's mechanics).
class ReferenceSegmentTsp final : public tsp::TspSolver {
 public:
  tsp::TspSolution solve(const tsp::SegmentTsp& p) override {
    const int g = static_cast<int>(p.segments.size());
    tsp::TspSolution out;
    if (g == 0) return out;
    auto end = [&](int s, int e) { return e == 0 ? p.segments[s].first : p.segments[s].second; };
    if (g > 10) {
      std::vector<char> used(static_cast<std::size_t>(g), 0);
      grid::Cell at = p.start;
      for (int step = 0; step < g; ++step) {
        int best = -1, best_e = 0, best_d = std::numeric_limits<int>::max();
        for (int s = 0; s < g; ++s) {
          if (used[s]) continue;
          for (int e = 0; e < 2; ++e) {
            const int d = grid::manhattan(at, end(s, e));
            if (d < best_d) best = s, best_e = e, best_d = d;
          }
        }
        used[best] = 1;
        out.order.push_back({best, best_e == 1});
        at = end(best, 1 - best_e);
      }
      out.length = tsp::tour_length(p, out.order);
      return out;
    }
    const int full = 1 << g;
    const long long inf = std::numeric_limits<long long>::max() / 4;
    // dp[(mask * g + s) * 2 + e]: shortest path flying `mask`, ending at end e of segment s.
    std::vector<long long> dp(static_cast<std::size_t>(full) * g * 2, inf);
    std::vector<int> from(dp.size(), -1);
    auto at = [&](int mask, int s, int e) {
      return (static_cast<std::size_t>(mask) * g + s) * 2 + e;
    };
    for (int s = 0; s < g; ++s) {
      const long long len = grid::manhattan(p.segments[s].first, p.segments[s].second);
      for (int e = 0; e < 2; ++e)
        dp[at(1 << s, s, e)] = grid::manhattan(p.start, end(s, 1 - e)) + len;
    }
    for (int mask = 1; mask < full; ++mask) {
      for (int s = 0; s < g; ++s) {
        if (!(mask & (1 << s))) continue;
        for (int e = 0; e < 2; ++e) {
          const long long cur = dp[at(mask, s, e)];
          if (cur >= inf) continue;
          for (int t = 0; t < g; ++t) {
            if (mask & (1 << t)) continue;
            const long long len = grid::manhattan(p.segments[t].first, p.segments[t].second);
            for (int f = 0; f < 2; ++f) {
              const long long c = cur + grid::manhattan(end(s, e), end(t, 1 - f)) + len;
              const auto slot = at(mask | (1 << t), t, f);
              if (c < dp[slot]) dp[slot] = c, from[slot] = (s * 2 + e);
            }
          }
        }
      }
    }
    long long best = inf;
    int bs = 0, be = 0;
    for (int s = 0; s < g; ++s)
      for (int e = 0; e < 2; ++e)
        if (dp[at(full - 1, s, e)] < best) best = dp[at(full - 1, s, e)], bs = s, be = e;
    int mask = full - 1;
    while (bs >= 0) {
      // exit end e = 1 means the segment was flown first → second (not reversed).
      out.order.push_back({bs, be == 0});
      const int prev = from[at(mask, bs, be)];
      mask &= ~(1 << bs);
      if (prev < 0) break;
      bs = prev / 2;
      be = prev % 2;
    }
    std::reverse(out.order.begin(), out.order.end());
    out.length = best;
    out.optimal = true;
    return out;
  }
};

/// A Part-TSP planner with the reference solver injected.
inline std::unique_ptr<planners::PartTspPlanner> make_part_tsp(planners::PartTspOptions o) {
  return std::make_unique<planners::PartTspPlanner>(std::move(o),
                                                    std::make_unique<ReferenceSegmentTsp>());
}

/// Text rows (top row first, as world::parse_text_mask) to a matrix: '.' → -1, '0'/'1' as is.
inline grid::Grid<std::int8_t> parse_matrix(const std::vector<std::string>& rows_top_first) {
  const int b = static_cast<int>(rows_top_first.size());
  const int a = static_cast<int>(rows_top_first.front().size());
  grid::Grid<std::int8_t> m(a, b, -1);
  for (int r = 0; r < b; ++r) {
    for (int x = 0; x < a; ++x) {
      const char c = rows_top_first[static_cast<std::size_t>(r)][static_cast<std::size_t>(x)];
      m(x, b - 1 - r) = c == '.' ? -1 : static_cast<std::int8_t>(c - '0');
    }
  }
  return m;
}

/// An instance from hand-drawn truth and prior rows ('.' not hull, '0', '1'); the hull is where
/// the truth is not '.'.
struct HandInstance {
  world::HullMask hull;
  world::Instance instance;
};
inline HandInstance hand_instance(const std::vector<std::string>& truth,
                                  const std::vector<std::string>& prior) {
  std::string text;
  for (const auto& row : truth) {
    for (char c : row) text += c == '.' ? '.' : 'X';
    text += '\n';
  }
  HandInstance h{world::parse_text_mask(text, "hand-made"), {}};
  h.instance.truth = parse_matrix(truth);
  h.instance.prior = parse_matrix(prior);
  return h;
}

}  // namespace hullinspect::testing
