// Sweep-Inspect's choice among candidate sweep plans (planners/sweep_chooser.hpp): the chooser on
// hand-made candidates (smallest total, ties to the earliest), and each generator of
// planners/sweep_approach.hpp on a small grid: the plain plan listed first, every candidate
// seeing every cell and costed as its flight, the chosen one the shortest.
#include "hullinspect/planners/sweep_chooser.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "hullinspect/planners/sweep_approach.hpp"
#include "sweep_coverage.hpp"

namespace hullinspect::planners {
namespace {
using sweep_coverage::unseen_cells;

SweepCandidate costing(double reach, double bands) {
  SweepCandidate candidate;
  candidate.cost = {reach, bands};
  return candidate;
}

TEST(SweepChooser, TakesTheSmallestTotalNotTheShortestReach) {
  const std::vector<SweepCandidate> candidates{costing(10, 50), costing(2, 61), costing(25, 30),
                                               costing(0, 80)};
  EXPECT_EQ(choose_plan(candidates), 2u);
}

TEST(SweepChooser, ATieGoesToTheEarliestCandidate) {
  EXPECT_EQ(choose_plan(std::vector<SweepCandidate>{costing(4, 6), costing(0, 10)}), 0u);
  EXPECT_EQ(choose_plan(std::vector<SweepCandidate>{costing(9, 9), costing(0, 10), costing(10, 0),
                                                    costing(5, 5)}),
            1u);
  EXPECT_EQ(choose_plan(std::vector<SweepCandidate>{costing(3, 4)}), 0u);
}

TEST(SweepChooser, TakeChosenMovesThePlanOut) {
  std::vector<SweepCandidate> candidates{costing(1, 9), costing(1, 5), costing(1, 7)};
  candidates[1].plan.waypoints = {{1, 2}, {3, 2}};
  candidates[1].plan.approach = 1;
  const SweepPlan plan = take_chosen(candidates);
  EXPECT_EQ(plan.waypoints, (std::vector<grid::Cell>{{1, 2}, {3, 2}}));
  EXPECT_EQ(plan.approach, 1u);
}

TEST(SweepChooser, ManhattanCostSplitsReachFromBands) {
  const PlanCost cost = manhattan_cost({0, 0}, {{3, 4}, {3, 10}, {8, 10}});
  EXPECT_EQ(cost.reach, 7);
  EXPECT_EQ(cost.bands, 11);
  EXPECT_EQ(cost.total(), 18);
  EXPECT_EQ(manhattan_cost({5, 5}, {}).total(), 0);
}

/// Every candidate sees all of `owner`'s cells of UAV 0 and is costed as its flight from `from`.
void expect_complete_and_costed(const std::vector<SweepCandidate>& candidates,
                                const grid::Grid<std::int16_t>& owner, int h, grid::Cell from) {
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    SCOPED_TRACE(::testing::Message() << "candidate " << i);
    const auto& waypoints = candidates[i].plan.waypoints;
    EXPECT_EQ(unseen_cells(owner, 0, h, from, waypoints), 0);
    EXPECT_EQ(candidates[i].cost.total(), flight_length(from, waypoints));
  }
}

// The 21 × 30 rectangle of SweepApproach.ExactPlanOnARectangle: the plain sweep (101 steps, 18 of
// them to its first band) first, then the edge approaches; the chooser takes the 87-step one.
TEST(SweepCandidates, ApproachCandidatesOnARectangle) {
  grid::Grid<std::int16_t> owner(21, 30, 0);
  SweepScratch scratch;
  const SweepRequest request{0, 7, BandAxis::kColumns, true, {}, true};
  const grid::Cell from{10, 15};
  const auto candidates = approach_candidates(owner, request, from, scratch);
  ASSERT_GT(candidates.size(), 1u);
  EXPECT_EQ(candidates[0].plan.waypoints, plain_sweep(owner, request, from));
  EXPECT_EQ(candidates[0].cost.reach, 18);
  EXPECT_EQ(candidates[0].cost.total(), 101);
  expect_complete_and_costed(candidates, owner, 3, from);
  const std::size_t chosen = choose_plan(candidates);
  EXPECT_EQ(candidates[chosen].cost.total(), 87);
  EXPECT_EQ(candidates[chosen].plan.approach, 1u);
  // The approach (12 steps down the centre line) and the flight on to the first band are reach.
  EXPECT_EQ(candidates[chosen].cost.reach, 12 + 7);
  for (const auto& candidate : candidates) EXPECT_FALSE(candidate.plan.own_band_first);
}

// The 40 × 30 rectangle in row bands of 5 of SweepApproach.OwnBandFirstOnARectangle: with the own
// band first allowed, those plans join the candidates and the 249-step one is chosen.
TEST(SweepCandidates, OwnBandFirstCandidatesOnARectangle) {
  grid::Grid<std::int16_t> owner(40, 30, 0);
  SweepScratch scratch;
  SweepRequest request{0, 5, BandAxis::kRows, true, {}, true};
  const grid::Cell from{20, 15};
  const auto without = approach_candidates(owner, request, from, scratch);
  request.own_band_first = true;
  const auto with = approach_candidates(owner, request, from, scratch);
  EXPECT_GT(with.size(), without.size());
  expect_complete_and_costed(with, owner, 2, from);
  EXPECT_EQ(without[choose_plan(without)].cost.total(), 254);
  const SweepCandidate& chosen = with[choose_plan(with)];
  EXPECT_TRUE(chosen.plan.own_band_first);
  EXPECT_EQ(chosen.cost.total(), 249);
}

// The ragged region of SweepApproach.TwoBlockSweepOnARaggedRegion (row bands of 5, so cuts at
// x = 5, 10, ..., 35): the plain sweep (188 steps) and each cut with either block first.
TEST(SweepCandidates, TwoBlockCandidatesOnARaggedRegion) {
  const auto owner = sweep_coverage::ragged_region();
  const SweepRequest request{0, 5, BandAxis::kRows, true, {}, true};
  const grid::Cell from{10, 7};
  const auto plain = plain_sweep(owner, request, from);
  const auto candidates = two_block_candidates(owner, request, from, plain);
  ASSERT_EQ(candidates.size(), 1u + 2u * 7u);
  EXPECT_EQ(candidates[0].plan.waypoints, plain);
  EXPECT_EQ(candidates[0].cost.total(), 188);
  expect_complete_and_costed(candidates, owner, 2, from);
  EXPECT_EQ(candidates[choose_plan(candidates)].cost.total(), 162);
}

// Rows first, then columns, over a wide and a tall rectangle in bands of 5 from a corner. 42 × 10
// in rows: two bands of 37 steps (2 to 39) and 5 between them, 79 after the 4 to (2, 2); in
// columns: nine bands of 5 and eight flights of 5 between them, 85. The tall 10 × 42 the other
// way round: the chooser takes the bands along the longer side.
TEST(SweepCandidates, AxisCandidatesOnWideAndTallRectangles) {
  const grid::Cell from{0, 0};
  grid::Grid<std::int16_t> wide(42, 10, 0);
  const auto across_wide = axis_candidates(wide, 0, 5, from, {});
  ASSERT_EQ(across_wide.size(), 2u);
  EXPECT_EQ(across_wide[0].plan.waypoints, band_sweep(wide, 0, 5, BandAxis::kRows, true, from));
  EXPECT_EQ(across_wide[1].plan.waypoints, band_sweep(wide, 0, 5, BandAxis::kColumns, true, from));
  expect_complete_and_costed(across_wide, wide, 2, from);
  EXPECT_EQ(across_wide[0].cost.total(), 4 + 79);
  EXPECT_EQ(choose_plan(across_wide), 0u);
  grid::Grid<std::int16_t> tall(10, 42, 0);
  const auto across_tall = axis_candidates(tall, 0, 5, from, {});
  expect_complete_and_costed(across_tall, tall, 2, from);
  EXPECT_EQ(choose_plan(across_tall), 1u);
  // A square: both flights equal, and the tie keeps rows.
  grid::Grid<std::int16_t> square(10, 10, 0);
  const auto across_square = axis_candidates(square, 0, 5, from, {});
  EXPECT_EQ(across_square[0].cost.total(), across_square[1].cost.total());
  EXPECT_EQ(choose_plan(across_square), 0u);
}

}  // namespace
}  // namespace hullinspect::planners
