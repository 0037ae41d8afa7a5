#include "hullinspect/grid/distance_service.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace hullinspect::grid {
namespace {

// A tiny deterministic generator for test grids (the project's streams live in world).
struct Lcg {
  std::uint64_t state;
  int below(int n) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(n));
  }
};

Grid<std::uint8_t> random_allowed(int w, int h, int blocked_percent, std::uint64_t seed) {
  Lcg rng{seed};
  Grid<std::uint8_t> allowed(w, h, 1);
  for (int i = 0; i < allowed.size(); ++i) allowed[i] = rng.below(100) < blocked_percent ? 0 : 1;
  return allowed;
}

// Reference: relax "d[n] = min(d[n], d[c] + 1)" over the whole grid until nothing changes, where
// only allowed cells and the sources pass a path on (a different algorithm from the service's BFS).
Grid<int> brute_distances(const Grid<std::uint8_t>& allowed, const std::vector<int>& sources) {
  Grid<int> d(allowed.width(), allowed.height(), kUnreachable);
  for (int s : sources) d[s] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < d.size(); ++i) {
      if (d[i] >= kUnreachable || (allowed[i] == 0 && d[i] != 0)) continue;
      const Cell c = d.cell(i);
      for (int k = 0; k < 4; ++k) {
        const Cell n{c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]};
        if (!d.contains(n) || d[n] <= d[i] + 1) continue;
        d[n] = d[i] + 1;
        changed = true;
      }
    }
  }
  return d;
}

TEST(DistanceService, WithoutNoFlyEveryAnswerIsManhattanWithoutSearching) {
  DistanceService d(9, 5);
  EXPECT_FALSE(d.has_no_fly());
  for (int i = 0; i < 45; ++i) {
    for (int j = 0; j < 45; ++j) {
      const Cell a{i % 9, i / 9};
      const Cell b{j % 9, j / 9};
      ASSERT_EQ(d.distance(a, b), manhattan(a, b));
      // The project's rule: along x first, then along y.
      Cell expect = a;
      if (b.x != a.x) {
        expect.x += b.x > a.x ? 1 : -1;
      } else if (b.y != a.y) {
        expect.y += b.y > a.y ? 1 : -1;
      }
      ASSERT_EQ(d.next_step(a, b), expect);
    }
  }
  EXPECT_EQ(d.searches(), 0);
  const Grid<int>& f = d.field({3, 2});
  for (int i = 0; i < f.size(); ++i) EXPECT_EQ(f[i], manhattan(f.cell(i), Cell{3, 2}));
  EXPECT_EQ(d.viewpoint({4, 4}, 2), (Cell{4, 4}));
}

TEST(DistanceService, WallWithOneGap) {
  // x = 4 is a wall except at y = 0: from (0, 4) to (8, 4) the flight goes down to the gap.
  Grid<std::uint8_t> allowed(9, 5, 1);
  for (int y = 1; y < 5; ++y) allowed(4, y) = 0;
  DistanceService d(allowed);
  EXPECT_TRUE(d.has_no_fly());
  EXPECT_EQ(d.no_fly_count(), 4);
  EXPECT_EQ(d.distance({0, 4}, {8, 4}), 16);
  EXPECT_EQ(d.distance({3, 0}, {5, 0}), 2);
  std::vector<Cell> path;
  ASSERT_TRUE(d.append_path({0, 4}, {8, 4}, path));
  ASSERT_EQ(path.size(), 16u);
  Cell at{0, 4};
  for (const Cell& c : path) {
    EXPECT_EQ(manhattan(at, c), 1);
    EXPECT_TRUE(d.allowed(c)) << c.x << "," << c.y;
    at = c;
  }
  // A wall cell is reached as a path end from either side, never entered by next_step().
  EXPECT_EQ(d.distance({3, 3}, {4, 3}), 1);
  EXPECT_EQ(d.next_step({3, 3}, {4, 3}), (Cell{3, 3}));
  EXPECT_FALSE(d.append_path({3, 3}, {4, 3}, path));
  // The nearest allowed position whose 3 × 3 footprint holds the wall cell (4, 3): (3, 3) and
  // (5, 3) are at distance 1; the lower (y, x) wins.
  EXPECT_EQ(d.viewpoint({4, 3}, 1), (Cell{3, 3}));
}

TEST(DistanceService, ClosedWallLeavesTheOtherSideUnreachable) {
  Grid<std::uint8_t> allowed(7, 3, 1);
  for (int y = 0; y < 3; ++y) allowed(3, y) = 0;
  DistanceService d(allowed);
  EXPECT_EQ(d.distance({0, 0}, {6, 0}), kUnreachable);
  EXPECT_EQ(d.next_step({0, 0}, {6, 0}), (Cell{0, 0}));
  std::vector<Cell> path;
  EXPECT_FALSE(d.append_path({0, 0}, {6, 0}, path));
}

TEST(DistanceService, MatchesBruteForceOnRandomObstacleGrids) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const int w = 6 + static_cast<int>(seed % 7);
    const int h = 4 + static_cast<int>(seed % 5);
    const auto allowed = random_allowed(w, h, 10 + static_cast<int>(seed * 3 % 30), seed);
    DistanceService d(allowed, /*cached_fields=*/3);  // small cache: eviction is exercised
    for (int a = 0; a < allowed.size(); ++a) {
      const Grid<int> expect = brute_distances(allowed, {a});
      for (int b = 0; b < allowed.size(); ++b) {
        ASSERT_EQ(d.distance(allowed.cell(b), allowed.cell(a)), expect[b])
            << "seed " << seed << " from " << b << " to " << a;
      }
    }
    // Paths between allowed positions: continuous, allowed, as long as the distance.
    for (int a = 0; a < allowed.size(); a += 3) {
      for (int b = 0; b < allowed.size(); b += 5) {
        if (!allowed[a] || !allowed[b]) continue;
        const Cell from = allowed.cell(a);
        const Cell to = allowed.cell(b);
        const int length = d.distance(from, to);
        std::vector<Cell> path;
        ASSERT_EQ(d.append_path(from, to, path), length < kUnreachable);
        if (length >= kUnreachable) continue;
        ASSERT_EQ(static_cast<int>(path.size()), length);
        Cell at = from;
        for (const Cell& c : path) {
          ASSERT_EQ(manhattan(at, c), 1);
          ASSERT_TRUE(d.allowed(c));
          at = c;
        }
        ASSERT_EQ(at, to);
      }
    }
    // Multi-source fields.
    Lcg rng{seed + 100};
    Grid<std::uint8_t> sources(w, h, 0);
    std::vector<int> list;
    for (int k = 0; k < 3; ++k) {
      const int i = rng.below(allowed.size());
      sources[i] = 1;
      list.push_back(i);
    }
    Grid<int> out;
    d.distances_from(sources, out);
    EXPECT_EQ(out, brute_distances(allowed, list)) << "seed " << seed;
  }
}

TEST(DistanceService, ViewpointStaysInsideTheFootprint) {
  // A 3 × 3 no-fly block: its centre is seen from an allowed position at Chebyshev radius 2 only.
  Grid<std::uint8_t> allowed(7, 7, 1);
  for (int y = 2; y <= 4; ++y) {
    for (int x = 2; x <= 4; ++x) allowed(x, y) = 0;
  }
  DistanceService d(allowed);
  EXPECT_EQ(d.viewpoint({3, 3}, 1), kNoCell);
  const Cell v = d.viewpoint({3, 3}, 2);
  EXPECT_EQ(v, (Cell{3, 1}));  // Manhattan 2, lowest (y, x) among (3,1), (1,3), (5,3), (3,5)
  // No path leaves the block's centre (its neighbours are no-fly too).
  EXPECT_EQ(d.distance({3, 3}, v), kUnreachable);
}

TEST(DistanceService, RepeatedQueriesDoNotSearchAgain) {
  Grid<std::uint8_t> allowed(20, 10, 1);
  allowed(5, 5) = 0;
  DistanceService d(allowed);
  d.distance({0, 0}, {19, 9});
  const long long after_first = d.searches();
  for (int k = 0; k < 100; ++k) d.next_step({0, 0}, {19, 9});
  EXPECT_EQ(d.searches(), after_first);
}

}  // namespace
}  // namespace hullinspect::grid
