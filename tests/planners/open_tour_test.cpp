// The prior tour's order (planners/open_tour.hpp): a permutation of the points, no 2-opt or
// Or-opt move left that would shorten it, near the optimum of small instances found by brute
// force, and the exact tour of a hand instance.
#include "hullinspect/planners/open_tour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace hullinspect::planners {
namespace {

/// A small explicit generator (splitmix64), so the instances are the same everywhere.
struct Stream {
  std::uint64_t state;
  int below(int n) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return static_cast<int>((z ^ (z >> 31)) % static_cast<std::uint64_t>(n));
  }
};

std::vector<grid::Cell> random_points(Stream& rng, int m) {
  std::vector<grid::Cell> points;
  for (int i = 0; i < m; ++i) points.push_back({rng.below(60), rng.below(30)});
  return points;
}

bool cell_less(grid::Cell a, grid::Cell b) {
  return a.y != b.y ? a.y < b.y : a.x < b.x;
}

/// The tour holds the input's points, each as often (a permutation of them).
bool same_points(std::vector<grid::Cell> input, std::vector<grid::Cell> tour) {
  std::sort(input.begin(), input.end(), cell_less);
  std::sort(tour.begin(), tour.end(), cell_less);
  return input == tour;
}

TEST(OpenTour, LegsWithinTheFootprintCostNothing) {
  const OpenTourCost cost{.reach = 2};
  EXPECT_EQ(cost.leg({0, 0}, {2, 2}), 0.0);
  EXPECT_EQ(cost.leg({0, 0}, {5, 1}), 3.0);
  EXPECT_EQ(cost.leg({0, 0}, {-4, 7}), 2.0 + 5.0);
}

TEST(OpenTour, EmptyAndSinglePoint) {
  std::vector<grid::Cell> none;
  plan_open_tour({0, 0}, none, {.reach = 2});
  EXPECT_TRUE(none.empty());
  std::vector<grid::Cell> one{{4, 4}};
  plan_open_tour({0, 0}, one, {.reach = 2});
  EXPECT_EQ(one.front(), (grid::Cell{4, 4}));
}

TEST(OpenTour, IsAPermutationWithNoImprovingMoveLeft) {
  Stream rng{7};
  for (int instance = 0; instance < 60; ++instance) {
    const int m = 2 + rng.below(40);
    const std::vector<grid::Cell> input = random_points(rng, m);
    const OpenTourCost cost{.reach = 2};
    const grid::Cell from{rng.below(60), rng.below(30)};
    std::vector<grid::Cell> tour = input;
    plan_open_tour(from, tour, cost);

    ASSERT_TRUE(same_points(input, tour)) << "instance " << instance;

    const int planned = cost.of(from, tour);
    const auto size = static_cast<std::ptrdiff_t>(tour.size());
    // Every 2-opt move: reverse tour[i, j).
    for (std::ptrdiff_t i = 0; i < size; ++i) {
      for (std::ptrdiff_t j = i + 2; j <= size; ++j) {
        std::vector<grid::Cell> t = tour;
        std::reverse(t.begin() + i, t.begin() + j);
        EXPECT_GE(cost.of(from, t), planned)
            << "instance " << instance << " 2-opt " << i << ".." << j;
      }
    }
    // Every Or-opt move: a run of 1-3 points taken out and put back anywhere, either way round.
    for (std::ptrdiff_t len = 1; len <= 3; ++len) {
      for (std::ptrdiff_t i = 0; i + len <= size; ++i) {
        std::vector<grid::Cell> rest = tour;
        const std::vector<grid::Cell> run(tour.begin() + i, tour.begin() + i + len);
        rest.erase(rest.begin() + i, rest.begin() + i + len);
        for (std::ptrdiff_t at = 0; at <= static_cast<std::ptrdiff_t>(rest.size()); ++at) {
          for (bool reversed : {false, true}) {
            std::vector<grid::Cell> t = rest;
            t.insert(t.begin() + at, run.begin(), run.end());
            if (reversed) std::reverse(t.begin() + at, t.begin() + at + len);
            EXPECT_GE(cost.of(from, t), planned)
                << "instance " << instance << " or-opt " << i << "+" << len << " to " << at;
          }
        }
      }
    }
  }
}

// Against the best order of every permutation (up to 7 points): never worse than 1.25× the
// optimum, and the optimum itself on most instances.
TEST(OpenTour, NearTheBruteForceOptimum) {
  Stream rng{11};
  int optimal = 0;
  double excess = 0.0;
  constexpr int kInstances = 150;
  for (int instance = 0; instance < kInstances; ++instance) {
    const int m = 3 + rng.below(5);
    std::vector<grid::Cell> points = random_points(rng, m);
    const OpenTourCost cost{.reach = 2};
    const grid::Cell from{30, 15};
    std::vector<grid::Cell> tour = points;
    plan_open_tour(from, tour, cost);
    std::sort(points.begin(), points.end(), cell_less);
    int best = cost.of(from, points);
    while (std::next_permutation(points.begin(), points.end(), cell_less))
      best = std::min(best, cost.of(from, points));
    const int planned = cost.of(from, tour);
    EXPECT_LE(planned, 1.25 * best) << "instance " << instance;
    if (planned == best) ++optimal;
    if (best > 0) excess += static_cast<double>(planned) / best - 1.0;
  }
  EXPECT_GE(optimal, kInstances * 8 / 10);
  EXPECT_LE(excess / kInstances, 0.02);
}

// Points along a row, the UAV in the middle: it sweeps the nearer side first, then all the way to
// the other end (3 + 2·8 out to x = 0, 28 back to x = 30, 3·8 on to x = 60, each leg less the
// reach), not the farther side first (81).
TEST(OpenTour, AHandInstance) {
  std::vector<grid::Cell> points;
  for (int x = 0; x <= 60; x += 10) points.push_back({x, 5});
  const grid::Cell from{25, 5};
  const OpenTourCost cost{.reach = 2};
  plan_open_tour(from, points, cost);
  EXPECT_EQ(points.front().x, 20);
  EXPECT_EQ(points.back().x, 60);
  EXPECT_EQ(cost.of(from, points), 71);
}

// Many points (clustered like a prior's corrosion): the neighbour-list search returns a
// permutation no more than 10 % longer than the exhaustive search's on any instance, 3 % in
// total.
TEST(OpenTour, NeighbourListsNearTheExhaustiveSearch) {
  Stream rng{5};
  long long exhaustive_total = 0;
  long long neighbours_total = 0;
  for (int instance = 0; instance < 12; ++instance) {
    std::vector<grid::Cell> input;
    const int clusters = 10 + rng.below(30);
    for (int c = 0; c < clusters; ++c) {
      const grid::Cell centre{rng.below(400), rng.below(60)};
      const int side = 1 + rng.below(6);
      for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) input.push_back({centre.x + x, centre.y + y});
      }
    }
    const grid::Cell from{rng.below(400), rng.below(60)};
    const OpenTourCost cost{.reach = 2};
    std::vector<grid::Cell> exhaustive = input;
    plan_open_tour_exhaustive(from, exhaustive, cost);
    std::vector<grid::Cell> neighbours = input;
    plan_open_tour_neighbours(from, neighbours, cost);

    ASSERT_TRUE(same_points(input, neighbours)) << "instance " << instance;
    exhaustive_total += cost.of(from, exhaustive);
    neighbours_total += cost.of(from, neighbours);
    EXPECT_LE(cost.of(from, neighbours), 1.1 * cost.of(from, exhaustive))
        << "instance " << instance;
  }
  EXPECT_LE(static_cast<double>(neighbours_total), 1.03 * static_cast<double>(exhaustive_total));
}

}  // namespace
}  // namespace hullinspect::planners
