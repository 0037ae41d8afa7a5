// The prior tour's order (planners/open_tour.hpp): a permutation of the points, no 2-opt or
// Or-opt move left that would shorten it, near the optimum of small instances found by brute
// force, and the exact tour of a hand instance; its repair where it changed.
#include "hullinspect/planners/open_tour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
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

/// Flies a tour of clustered points to its end: at each leg the UAV flies to the first point left,
/// which sees every point within its footprint there; `next` orders the points left from there.
/// Returns the steps flown (the legs' costs).
template <typename Next>
int fly_tour(grid::Cell from, std::vector<grid::Cell> points, const OpenTourCost& cost,
             Next&& next) {
  plan_open_tour(from, points, cost);
  int flown = 0;
  grid::Cell at = from;
  std::vector<std::size_t> touched;
  while (!points.empty()) {
    flown += cost.leg(at, points.front());
    at = points.front();
    // Seen: within the reach of the point flown to (Chebyshev); the nodes beside each gap change.
    std::vector<grid::Cell> left;
    touched.assign({0, 1});
    bool dropped = false;
    for (const grid::Cell c : points) {
      if (std::max(std::abs(c.x - at.x), std::abs(c.y - at.y)) <= cost.reach) {
        dropped = true;
        continue;
      }
      if (dropped) {
        touched.push_back(left.size());
        touched.push_back(left.size() + 1);
        dropped = false;
      }
      left.push_back(c);
    }
    points = std::move(left);
    next(at, points, touched);
  }
  return flown;
}

std::vector<grid::Cell> clustered_points(Stream& rng, int clusters) {
  std::vector<grid::Cell> points;
  for (int c = 0; c < clusters; ++c) {
    const grid::Cell centre{rng.below(120), rng.below(40)};
    const int side = 1 + rng.below(5);
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) points.push_back({centre.x + x, centre.y + y});
    }
  }
  return points;
}

// A tour repaired where it changed: the points it was given, never longer than before the repair,
// and no 2-opt or Or-opt move at the new start's edge (the touched nodes 0 and 1) left that would
// shorten it.
TEST(OpenTourRepair, LeavesNoImprovingMoveAtTheStart) {
  Stream rng{3};
  const OpenTourCost cost{.reach = 2};
  int improved = 0;
  for (int instance = 0; instance < 60; ++instance) {
    std::vector<grid::Cell> input = random_points(rng, 3 + rng.below(40));
    plan_open_tour({rng.below(60), rng.below(30)}, input, cost);
    const grid::Cell from{rng.below(60), rng.below(30)};  // the UAV moved elsewhere
    std::vector<grid::Cell> tour = input;
    const std::vector<std::size_t> start{0, 1};  // the start's edge changed
    repair_open_tour(from, tour, start, cost);

    ASSERT_TRUE(same_points(input, tour)) << "instance " << instance;
    const int repaired = cost.of(from, tour);
    EXPECT_LE(repaired, cost.of(from, input)) << "instance " << instance;
    if (repaired < cost.of(from, input)) ++improved;
    const auto size = static_cast<std::ptrdiff_t>(tour.size());
    for (std::ptrdiff_t j = 2; j <= size; ++j) {  // reversals of a prefix: the start's edge
      std::vector<grid::Cell> t = tour;
      std::reverse(t.begin(), t.begin() + j);
      EXPECT_GE(cost.of(from, t), repaired) << "instance " << instance << " 2-opt 0.." << j;
    }
    for (std::ptrdiff_t len = 1; len <= std::min<std::ptrdiff_t>(3, size); ++len) {
      std::vector<grid::Cell> rest = tour;  // the first run moved anywhere, either way round
      const std::vector<grid::Cell> run(tour.begin(), tour.begin() + len);
      rest.erase(rest.begin(), rest.begin() + len);
      for (std::ptrdiff_t at = 1; at <= static_cast<std::ptrdiff_t>(rest.size()); ++at) {
        for (bool reversed : {false, true}) {
          std::vector<grid::Cell> t = rest;
          t.insert(t.begin() + at, run.begin(), run.end());
          if (reversed) std::reverse(t.begin() + at, t.begin() + at + len);
          EXPECT_GE(cost.of(from, t), repaired)
              << "instance " << instance << " or-opt 0+" << len << " to " << at;
        }
      }
    }
  }
  EXPECT_GE(improved, 10);  // the instances do exercise the repair
}

// Moves are looked for only at the touched nodes and where moves changed the tour: with none
// touched, even a poor tour is left as it is.
TEST(OpenTourRepair, NothingTouchedNothingChanged) {
  std::vector<grid::Cell> tour{{50, 0}, {0, 0}, {40, 0}, {10, 0}};
  const std::vector<grid::Cell> input = tour;
  repair_open_tour({0, 0}, tour, {}, {.reach = 0});
  EXPECT_EQ(tour, input);
  const std::vector<std::size_t> all{0, 1, 2, 3, 4};
  repair_open_tour({0, 0}, tour, all, {.reach = 0});
  EXPECT_EQ(OpenTourCost{.reach = 0}.of({0, 0}, tour), 50);  // 0, 10, 40, 50
}

// Flying clustered tours to their end, repairing the tour where it changed after each leg flies
// no more than 3 % further in total than planning it anew after each leg.
TEST(OpenTourRepair, FliesAsShortAsReplanningEachLeg) {
  Stream rng{9};
  const OpenTourCost cost{.reach = 2};
  long long replanned_total = 0;
  long long repaired_total = 0;
  for (int instance = 0; instance < 20; ++instance) {
    const std::vector<grid::Cell> input = clustered_points(rng, 5 + rng.below(20));
    const grid::Cell from{rng.below(120), rng.below(40)};
    replanned_total += fly_tour(from, input, cost, [&](grid::Cell at, auto& points, const auto&) {
      plan_open_tour(at, points, cost);
    });
    repaired_total +=
        fly_tour(from, input, cost, [&](grid::Cell at, auto& points, const auto& touched) {
          repair_open_tour(at, points, touched, cost);
        });
  }
  EXPECT_LE(static_cast<double>(repaired_total), 1.03 * static_cast<double>(replanned_total))
      << repaired_total << " against " << replanned_total;
}

}  // namespace
}  // namespace hullinspect::planners
