// Sweep-Inspect's help with a sweep's tail (planners/sweep_tail.hpp) on an open 20 × 10 grid,
// row bands: the estimate of a sweep left alone, the split along a band that ends the UAV and
// the helper together, the split at a leg between two bands, none when it saves too little, and
// never at a no-fly position.
#include "hullinspect/planners/sweep_tail.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace hullinspect::planners {
namespace {

const std::vector<grid::Cell> kOneBand{{19, 2}};

TEST(SweepTail, AloneIsTheWayBackAndTheWalkTimesItsCost) {
  EXPECT_DOUBLE_EQ(sweep_left_end({kOneBand, {0, 2}, 4, BandAxis::kRows}), 4 + kTailWalkCost * 19);
}

// One band from (0, 2) to (19, 2), the helper at (19, 5), 3 steps from its end: the UAV flies to
// (11, 2) (13.2 steps by the estimate), the helper from the far end back to (11, 2) (3 + 9.6).
TEST(SweepTail, SplitsABandWhereBothEndTogether) {
  grid::DistanceService open(20, 10);
  std::vector<int> walk;
  const SweepLeft left{kOneBand, {0, 2}, 0, BandAxis::kRows};
  const TailSplit split = split_sweep_tail(left, {19, 5}, open, 3, walk);
  EXPECT_EQ(split.leg, 0);
  EXPECT_EQ(split.at, (grid::Cell{11, 2}));
  EXPECT_FALSE(split.skip_leg);
  EXPECT_TRUE(split.backward);
  EXPECT_NEAR(split.end, kTailWalkCost * 11, 1e-9);
  // No split unless it saves at least min_saving of the 22.8 steps alone.
  EXPECT_EQ(split_sweep_tail(left, {19, 5}, open, 10, walk).leg, -1);
}

TEST(SweepTail, NeverSplitsAtANoFlyPosition) {
  grid::Grid<std::uint8_t> allowed(20, 10, 1);
  allowed(11, 2) = 0;
  grid::DistanceService flights(allowed);
  std::vector<int> walk;
  const TailSplit split =
      split_sweep_tail({kOneBand, {0, 2}, 0, BandAxis::kRows}, {19, 5}, flights, 3, walk);
  EXPECT_EQ(split.at, (grid::Cell{10, 2}));
}

// Two bands, (0, 2) → (19, 2) then (19, 7) → (0, 7), the helper at (0, 8) beside the second's
// end: the UAV flies the first band (22.8), the helper the second from its far end (1 + 22.8);
// neither flies the leg between them.
TEST(SweepTail, SplitsAtALegBetweenBands) {
  grid::DistanceService open(20, 10);
  std::vector<int> walk;
  const std::vector<grid::Cell> rest{{19, 2}, {19, 7}, {0, 7}};
  const TailSplit split =
      split_sweep_tail({rest, {0, 2}, 0, BandAxis::kRows}, {0, 8}, open, 3, walk);
  EXPECT_EQ(split.leg, 1);
  EXPECT_TRUE(split.skip_leg);
  EXPECT_EQ(split.at, (grid::Cell{19, 2}));
  EXPECT_TRUE(split.backward);
  EXPECT_NEAR(split.end, 1 + kTailWalkCost * 19, 1e-9);
}

}  // namespace
}  // namespace hullinspect::planners
