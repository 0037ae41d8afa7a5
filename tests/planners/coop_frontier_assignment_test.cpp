// The utility (eq. 13), the reduction (eq. 17) and the greedy assignment (eqs. 15–16), checked
// against numbers worked out by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "hullinspect/grid/distance.hpp"
#include "hullinspect/planners/coop_frontier_assignment.hpp"
#include "hullinspect/planners/coop_frontier_fields.hpp"
#include "hullinspect/planners/coop_frontier_utilities.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::planners {
namespace {

using grid::Cell;

TEST(CoopFrontierUtility, FollowsEquation13) {
  // α = 0.25, d_HP = 2, d_C = 4: 0.25/2 + 0.75/4 = 0.3125.
  EXPECT_DOUBLE_EQ(frontier_utility(0.25, 2, 4), 0.3125);
  // d_C is clamped to 1: 0.25/2 + 0.75/1.
  EXPECT_DOUBLE_EQ(frontier_utility(0.25, 2, 0), 0.875);
  // An empty set's term contributes 0.
  EXPECT_DOUBLE_EQ(frontier_utility(0.25, grid::kUnreachable, 4), 0.1875);
  EXPECT_DOUBLE_EQ(frontier_utility(0.25, 2, grid::kUnreachable), 0.125);
  EXPECT_DOUBLE_EQ(frontier_utility(0.25, grid::kUnreachable, grid::kUnreachable), 0.0);
}

TEST(CoopFrontierUtility, ReductionFollowsEquation17) {
  EXPECT_DOUBLE_EQ(utility_reduction(0, 7), 0.0);
  EXPECT_DOUBLE_EQ(utility_reduction(7, 7), 0.5);
  EXPECT_DOUBLE_EQ(utility_reduction(3.5, 7), 0.25);
  EXPECT_DOUBLE_EQ(utility_reduction(13.9, 7), 13.9 / 14);
  EXPECT_DOUBLE_EQ(utility_reduction(14, 7), 1.0);
  EXPECT_DOUBLE_EQ(utility_reduction(30, 7), 1.0);
  EXPECT_DOUBLE_EQ(utility_reduction(11, 11), 0.5);
}

TEST(CoopFrontierAssigner, OneRobotTakesTheArgmaxOfEquation15) {
  // Robot at (1, 0), β = 1. Scores U + β/max(1, d):
  //   (0, 0): 0.5 + 1/1 = 1.5   (5, 0): 1.0 + 1/4 = 1.25   (2, 0): 0 + 1/1 = 1.0
  const std::array<Cell, 3> frontiers{Cell{0, 0}, Cell{5, 0}, Cell{2, 0}};
  const std::array<double, 3> utility{0.5, 1.0, 0.0};
  const std::array<Cell, 1> robots{Cell{1, 0}};
  std::array<int, 1> chosen{};
  FrontierAssigner a;
  a.configure(1.0, 7, 100);
  a.assign(frontiers, utility, {}, robots, chosen);
  EXPECT_EQ(chosen[0], 0);
  ASSERT_EQ(a.picks().size(), 1u);
  EXPECT_DOUBLE_EQ(a.picks()[0].score, 1.5);

  // With β = 0.1 the utility wins: (5, 0): 1.0 + 0.1/4 = 1.025 > (0, 0): 0.5 + 0.1 = 0.6.
  a.configure(0.1, 7, 100);
  a.assign(frontiers, utility, {}, robots, chosen);
  EXPECT_EQ(chosen[0], 1);
  EXPECT_DOUBLE_EQ(a.picks()[0].score, 1.025);
}

TEST(CoopFrontierAssigner, HeldTargetsReduceUtilitiesFirst) {
  // s2 = 7: P(d) = d/14 below 14. A held target at (4, 0) reduces
  //   (5, 0) (d = 1):  1.0 · 1/14       (0, 0) (d = 4): 0.5 · 4/14 = 1/7
  //   (2, 0) (d = 2):  0 · 2/14 = 0     (40, 0) (d = 36): 0.8, unchanged.
  // Robot at (1, 0), β = 0.1: (0, 0): 1/7 + 0.1 = 0.2429   (5, 0): 1/14 + 0.025 = 0.0964
  //   (2, 0): 0.1   (40, 0): 0.8 + 0.1/39 = 0.80256  → (40, 0).
  const std::array<Cell, 4> frontiers{Cell{0, 0}, Cell{5, 0}, Cell{2, 0}, Cell{40, 0}};
  const std::array<double, 4> utility{0.5, 1.0, 0.0, 0.8};
  const std::array<Cell, 1> held{Cell{4, 0}};
  const std::array<Cell, 1> robots{Cell{1, 0}};
  std::array<int, 1> chosen{};
  FrontierAssigner a;
  a.configure(0.1, 7, 100);
  a.assign(frontiers, utility, held, robots, chosen);
  EXPECT_EQ(chosen[0], 3);
  EXPECT_NEAR(a.picks()[0].score, 0.8 + 0.1 / 39, 1e-12);
  // After the pick (40, 0) itself is reduced to 0 (P(0) = 0); the others keep the held reduction.
  const auto reduced = a.reduced_utility();
  EXPECT_NEAR(reduced[0], 0.5 * 4.0 / 14.0, 1e-12);
  EXPECT_NEAR(reduced[1], 1.0 / 14.0, 1e-12);
  EXPECT_DOUBLE_EQ(reduced[2], 0.0);
  EXPECT_DOUBLE_EQ(reduced[3], 0.0);
}

TEST(CoopFrontierAssigner, AdjacentRobotsGoToDifferentFrontiersThroughEquation17) {
  // Robots at (0, 0) and (1, 0); frontiers A = (2, 0) with U = 1 and B = (20, 0) with U = 0.9;
  // β = 1, s2 = 7.
  // First pick: r0: A 1 + 1/2 = 1.5, B 0.9 + 1/20 = 0.95; r1: A 1 + 1/1 = 2.0, B 0.9 + 1/19.
  //   → (r1, A), score 2. Reduction: A · P(0) = 0; B is 18 ≥ 14 away: unchanged.
  // Second pick: r0: A 0 + 1/2 = 0.5, B 0.9 + 1/20 = 0.95 → (r0, B).
  const std::array<Cell, 2> frontiers{Cell{2, 0}, Cell{20, 0}};
  const std::array<double, 2> utility{1.0, 0.9};
  const std::array<Cell, 2> robots{Cell{0, 0}, Cell{1, 0}};
  std::array<int, 2> chosen{};
  FrontierAssigner a;
  a.configure(1.0, 7, 100);
  a.assign(frontiers, utility, {}, robots, chosen);
  EXPECT_EQ(chosen[0], 1);
  EXPECT_EQ(chosen[1], 0);
  ASSERT_EQ(a.picks().size(), 2u);
  EXPECT_EQ(a.picks()[0].robot, 1);
  EXPECT_DOUBLE_EQ(a.picks()[0].score, 2.0);
  EXPECT_EQ(a.picks()[1].robot, 0);
  EXPECT_DOUBLE_EQ(a.picks()[1].score, 0.95);

  // A partial reduction: B = (8, 0) is 6 from A, so after the first pick U_B = 0.9 · 6/14 = 0.3857;
  // second pick: r0: A 0.5, B 0.3857 + 1/8 = 0.5107 → B still, with that exact score.
  const std::array<Cell, 2> near{Cell{2, 0}, Cell{8, 0}};
  a.assign(near, utility, {}, robots, chosen);
  EXPECT_EQ(chosen[0], 1);
  EXPECT_NEAR(a.picks()[1].score, 0.9 * 6.0 / 14.0 + 1.0 / 8.0, 1e-12);
  EXPECT_NEAR(a.reduced_utility()[1], 0.0, 1e-12);  // B itself was then reduced by P(0)

  // Without utility to spread them (all U = 0) both take the nearest frontier: a shared target.
  const std::array<double, 2> none{0.0, 0.0};
  a.assign(frontiers, none, {}, robots, chosen);
  EXPECT_EQ(chosen[0], 0);
  EXPECT_EQ(chosen[1], 0);
}

TEST(CoopFrontierAssigner, EuclideanDistanceInTheReduction) {
  // Held target (0, 0); frontier (3, 4) is 5 away (Euclidean, 7 Manhattan): U · 5/14.
  const std::array<Cell, 1> frontiers{Cell{3, 4}};
  const std::array<double, 1> utility{0.7};
  const std::array<Cell, 1> held{Cell{0, 0}};
  const std::array<Cell, 1> robots{Cell{3, 4}};
  std::array<int, 1> chosen{};
  FrontierAssigner a;
  a.configure(2.0, 7, 100);
  a.assign(frontiers, utility, held, robots, chosen);
  // Score: 0.7 · 5/14 + 2 / max(1, 0) = 0.25 + 2.
  EXPECT_NEAR(a.picks()[0].score, 2.25, 1e-12);
}

TEST(CoopFrontierAssigner, TiesGoToTheLowestRobotThenTheLowestYX) {
  // Two robots at the same cell, four frontiers one step away and U = 0 everywhere, so every score
  // is 0 + 1/1 and the reduction changes nothing: robot 0 picks first and takes the lowest (y, x),
  // then robot 1 faces the same four equal scores.
  const std::array<Cell, 4> frontiers{Cell{6, 5}, Cell{4, 5}, Cell{5, 6}, Cell{5, 4}};
  const std::array<double, 4> utility{0.0, 0.0, 0.0, 0.0};
  const std::array<Cell, 2> robots{Cell{5, 5}, Cell{5, 5}};
  std::array<int, 2> chosen{};
  FrontierAssigner a;
  a.configure(1.0, 7, 100);
  a.assign(frontiers, utility, {}, robots, chosen);
  ASSERT_EQ(a.picks().size(), 2u);
  EXPECT_EQ(a.picks()[0].robot, 0);
  EXPECT_EQ(chosen[0], 3);  // (5, 4): lowest y
  EXPECT_EQ(chosen[1], 3);  // U = 0 everywhere: the same tie-break again
}

TEST(CoopFrontierAssigner, NoFrontiersLeavesRobotsUnassigned) {
  const std::array<Cell, 2> robots{Cell{0, 0}, Cell{1, 0}};
  std::array<int, 2> chosen{5, 5};
  FrontierAssigner a;
  a.configure(1.0, 7, 100);
  a.assign(std::span<const Cell>{}, std::span<const double>{}, {}, robots, chosen);
  EXPECT_EQ(chosen[0], -1);
  EXPECT_EQ(chosen[1], -1);
  EXPECT_TRUE(a.picks().empty());
}

}  // namespace
}  // namespace hullinspect::planners

namespace hullinspect::planners {
namespace {

// The literal eqs. 15–17: every round scans every (unassigned robot, frontier) pair.
std::vector<int> reference_assignment(std::span<const grid::Cell> frontiers, std::vector<double> u,
                                      std::span<const grid::Cell> held,
                                      std::span<const grid::Cell> robots, double beta, int s2) {
  auto reduce = [&](grid::Cell at) {
    for (std::size_t j = 0; j < frontiers.size(); ++j) {
      const double dx = frontiers[j].x - at.x;
      const double dy = frontiers[j].y - at.y;
      u[j] *= utility_reduction(std::sqrt(dx * dx + dy * dy), s2);
    }
  };
  for (const auto h : held) reduce(h);
  std::vector<int> chosen(robots.size(), -1);
  for (std::size_t round = 0; round < robots.size(); ++round) {
    int br = -1;
    int bf = -1;
    double bs = 0;
    for (std::size_t r = 0; r < robots.size(); ++r) {
      if (chosen[r] >= 0) continue;
      for (std::size_t j = 0; j < frontiers.size(); ++j) {
        const double s = u[j] + beta / std::max(1, grid::manhattan(robots[r], frontiers[j]));
        const bool better = br < 0 || s > bs ||
                            (s == bs && (static_cast<int>(r) < br ||
                                         (static_cast<int>(r) == br &&
                                          frontiers[j] < frontiers[static_cast<std::size_t>(bf)])));
        if (better) {
          br = static_cast<int>(r);
          bf = static_cast<int>(j);
          bs = s;
        }
      }
    }
    chosen[static_cast<std::size_t>(br)] = bf;
    reduce(frontiers[static_cast<std::size_t>(bf)]);
  }
  return chosen;
}

TEST(CoopFrontierAssigner, MatchesTheLiteralGreedyOnRandomInputs) {
  world::RandomStream rng(99, 0);
  FrontierAssigner a;
  for (int trial = 0; trial < 400; ++trial) {
    const int w = 5 + static_cast<int>(rng.below(60));
    const int h = 3 + static_cast<int>(rng.below(20));
    const int s2 = trial % 2 == 0 ? 7 : 11;
    const double beta = trial % 5 == 0 ? 0.0 : 0.25 * static_cast<double>(rng.below(12));
    std::vector<grid::Cell> frontiers(1 + rng.below(40));
    std::vector<double> utility(frontiers.size());
    for (std::size_t j = 0; j < frontiers.size(); ++j) {
      frontiers[j] = {static_cast<int>(rng.below(static_cast<std::uint64_t>(w))),
                      static_cast<int>(rng.below(static_cast<std::uint64_t>(h)))};
      // Coarse values so equal scores (tie-breaks) occur often.
      utility[j] = trial % 3 == 0 ? 0.0 : 0.25 * static_cast<double>(rng.below(4));
    }
    std::vector<grid::Cell> held(rng.below(3));
    for (auto& c : held) {
      c = {static_cast<int>(rng.below(static_cast<std::uint64_t>(w))),
           static_cast<int>(rng.below(static_cast<std::uint64_t>(h)))};
    }
    std::vector<grid::Cell> robots(1 + rng.below(8));
    for (auto& c : robots) {
      c = {static_cast<int>(rng.below(static_cast<std::uint64_t>(w))),
           static_cast<int>(rng.below(static_cast<std::uint64_t>(h)))};
    }
    std::vector<int> chosen(robots.size());
    a.configure(beta, s2, w + h);
    a.assign(frontiers, utility, held, robots, chosen);
    ASSERT_EQ(chosen, reference_assignment(frontiers, utility, held, robots, beta, s2))
        << "trial " << trial;
  }
}

}  // namespace
}  // namespace hullinspect::planners

namespace hullinspect::planners {
namespace {

class VectorUtilities final : public FrontierUtilities {
 public:
  VectorUtilities(const std::vector<double>& values, double ceiling)
      : values_(values), ceiling_(ceiling) {}
  double utility(int position) const override {
    ++reads;
    return values_[static_cast<std::size_t>(position)];
  }
  double score_ceiling(Cell, int m, double beta) const override {
    return ceiling_ + beta / std::max(1, m);
  }
  mutable int reads = 0;

 private:
  const std::vector<double>& values_;
  double ceiling_;
};

// The ring search over a frontier set gives the pairs of the literal greedy, with a tight ceiling
// (the largest utility) and with a loose one, on grids where the rings stop early and where they
// fall back to a scan.
TEST(CoopFrontierAssigner, RingSearchMatchesTheLiteralGreedy) {
  world::RandomStream rng(1234, 0);
  FrontierAssigner a;
  for (int trial = 0; trial < 600; ++trial) {
    const int w = 5 + static_cast<int>(rng.below(80));
    const int h = 3 + static_cast<int>(rng.below(40));
    const int s2 = trial % 2 == 0 ? 7 : 11;
    const double beta = trial % 7 == 0 ? 0.0 : 0.5 * static_cast<double>(1 + rng.below(10));
    IndexedCellSet set;
    set.reset(w, h);
    const int wanted = 1 + static_cast<int>(rng.below(trial % 4 == 0 ? 400 : 60));
    for (int k = 0; k < wanted; ++k) set.insert(static_cast<int>(rng.below(w * h)));
    const std::vector<grid::Cell> frontiers(set.cells().begin(), set.cells().end());
    std::vector<double> utility(frontiers.size());
    double largest = 0;
    for (double& u : utility) {
      // Coarse values so equal scores (tie-breaks) occur often.
      u = trial % 3 == 0 ? 0.5 : 0.5 + 0.25 * static_cast<double>(rng.below(5));
      largest = std::max(largest, u);
    }
    std::vector<grid::Cell> held(rng.below(4));
    for (auto& c : held) {
      c = {static_cast<int>(rng.below(static_cast<std::uint64_t>(w))),
           static_cast<int>(rng.below(static_cast<std::uint64_t>(h)))};
    }
    std::vector<grid::Cell> robots(1 + rng.below(8));
    for (auto& c : robots) {
      c = {static_cast<int>(rng.below(static_cast<std::uint64_t>(w))),
           static_cast<int>(rng.below(static_cast<std::uint64_t>(h)))};
    }
    const std::vector<int> expected =
        reference_assignment(frontiers, utility, held, robots, beta, s2);
    a.configure(beta, s2, w + h);
    const double ceiling = trial % 5 == 0 ? largest + 1.0 : largest;
    const VectorUtilities utilities(utility, ceiling);
    std::vector<int> chosen(robots.size());
    a.assign(set, utilities, held, robots, chosen);
    ASSERT_EQ(chosen, expected) << "trial " << trial;
    const std::vector<FrontierAssigner::Pick> ring_picks(a.picks().begin(), a.picks().end());
    a.assign(frontiers, utility, held, robots, chosen);
    ASSERT_EQ(ring_picks.size(), a.picks().size()) << "trial " << trial;
    for (std::size_t p = 0; p < ring_picks.size(); ++p) {
      EXPECT_EQ(ring_picks[p].score, a.picks()[p].score) << "trial " << trial << " pick " << p;
    }
  }
}

// Near the robot the rings stop long before F is read: one robot beside a frontier, β = 4, on a
// grid with a long frontier far away reads only the utilities close by.
TEST(CoopFrontierAssigner, RingSearchReadsOnlyNearbyUtilities) {
  IndexedCellSet set;
  set.reset(400, 50);
  for (int x = 0; x < 400; ++x) set.insert(49 * 400 + x);  // the top row
  set.insert(10 * 400 + 10);                               // (10, 10)
  const std::vector<double> utility(static_cast<std::size_t>(set.size()), 0.5);
  const VectorUtilities utilities(utility, 1.5);
  FrontierAssigner a;
  a.configure(4.0, 7, 450);
  const std::array<Cell, 1> robots{Cell{10, 9}};
  std::array<int, 1> chosen{};
  a.assign(set, utilities, {}, robots, chosen);
  EXPECT_EQ(set.cells()[static_cast<std::size_t>(chosen[0])], (Cell{10, 10}));
  EXPECT_EQ(utilities.reads, 1);
  // A loose ceiling only widens the search: same choice, still no scan of the top row.
  const VectorUtilities loose(utility, 3.0);
  a.assign(set, loose, {}, robots, chosen);
  EXPECT_EQ(set.cells()[static_cast<std::size_t>(chosen[0])], (Cell{10, 10}));
  EXPECT_EQ(loose.reads, 1);
}

}  // namespace
}  // namespace hullinspect::planners

namespace hullinspect::planners {
namespace {

// The planner's utilities (eq. 13 from the d_HP and d_C fields) and their bound — the floor of
// d_HP over F and the triangle inequality around each robot — give the ring search the pairs of
// the literal greedy.
TEST(CoopFrontierAssigner, RingSearchWithTheFieldBoundMatchesTheLiteralGreedy) {
  world::RandomStream rng(77, 0);
  FrontierAssigner a;
  for (int trial = 0; trial < 500; ++trial) {
    const int w = 5 + static_cast<int>(rng.below(90));
    const int h = 3 + static_cast<int>(rng.below(40));
    const int s2 = trial % 2 == 0 ? 7 : 11;
    const double beta = trial % 9 == 0 ? 0.0 : static_cast<double>(1 + rng.below(8));
    const double alpha = trial % 4 == 0 ? 0.5 : 1.0;
    const double base = trial % 3 == 0 ? 0.0 : 0.5;
    SourceDistanceField prior;
    SourceDistanceField detected;
    prior.reset(w, h, nullptr, 0);
    detected.reset(w, h, nullptr, 0);
    for (int k = static_cast<int>(rng.below(12)); k > 0; --k) {
      prior.set(static_cast<int>(rng.below(static_cast<std::uint64_t>(w * h))), true);
    }
    for (int k = static_cast<int>(rng.below(4)); k > 0; --k) {
      detected.set(static_cast<int>(rng.below(static_cast<std::uint64_t>(w * h))), true);
    }
    IndexedCellSet set;
    set.reset(w, h);
    for (int k = 1 + static_cast<int>(rng.below(trial % 4 == 1 ? 500 : 80)); k > 0; --k) {
      set.insert(static_cast<int>(rng.below(static_cast<std::uint64_t>(w * h))));
    }
    int floor = prior.empty() ? grid::kUnreachable : 63;
    for (const int i : set.indices()) floor = std::min(floor, prior.distance(i));
    if (floor > 0 && floor < grid::kUnreachable && trial % 5 == 0) floor -= 1;  // a loose floor
    const FieldUtilities utilities(alpha, base, set.indices(), w, &prior,
                                   alpha < 1.0 ? &detected : nullptr, floor, true);
    const std::vector<grid::Cell> frontiers(set.cells().begin(), set.cells().end());
    std::vector<double> utility(frontiers.size());
    for (std::size_t j = 0; j < utility.size(); ++j) {
      utility[j] = utilities.utility(static_cast<int>(j));
    }
    std::vector<grid::Cell> held(rng.below(4));
    for (auto& c : held) {
      c = {static_cast<int>(rng.below(static_cast<std::uint64_t>(w))),
           static_cast<int>(rng.below(static_cast<std::uint64_t>(h)))};
    }
    std::vector<grid::Cell> robots(1 + rng.below(8));
    for (auto& c : robots) {
      c = {static_cast<int>(rng.below(static_cast<std::uint64_t>(w))),
           static_cast<int>(rng.below(static_cast<std::uint64_t>(h)))};
    }
    a.configure(beta, s2, w + h);
    std::vector<int> chosen(robots.size());
    a.assign(set, utilities, held, robots, chosen);
    ASSERT_EQ(chosen, reference_assignment(frontiers, utility, held, robots, beta, s2))
        << "trial " << trial;
  }
}

}  // namespace
}  // namespace hullinspect::planners
