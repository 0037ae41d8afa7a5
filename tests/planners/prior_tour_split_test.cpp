// Sweep-Inspect's prior-tour estimates and splits (planners/prior_tour_split.hpp) on row 0 of a
// grid 20 wide, footprint half-width 1: the nearest-first estimate, the split of cells at the
// ends of the row between UAVs at either end, and cells only one UAV may reach.
#include "hullinspect/planners/prior_tour_split.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace hullinspect::planners {
namespace {

constexpr int kWidth = 20;
constexpr grid::Cell kLeft{0, 0};
constexpr grid::Cell kRight{19, 0};

int both(int) {
  return 0;
}

TEST(PriorTourSplit, NearestFirstEstimateSeesCellsAlongItsLegs) {
  PriorTourSplitter tours(kWidth, 1, 16);
  EXPECT_EQ(tours.tour_steps(kLeft, {}), 0);
  // To (4, 0), whose footprint holds (5, 0): 4 steps.
  EXPECT_EQ(tours.tour_steps(kLeft, std::vector<int>{5}), 4);
  // (6, 0) is not seen from (4, 0): one step more.
  EXPECT_EQ(tours.tour_steps(kLeft, std::vector<int>{6, 5}), 5);
  // (3, 1) is seen on the way to (4, 0) (within 1 of the leg along row 0).
  EXPECT_EQ(tours.tour_steps(kLeft, std::vector<int>{5, kWidth + 3}), 4);
  // A cell two rows up: the position (5, 1).
  EXPECT_EQ(tours.tour_steps(kLeft, std::vector<int>{2 * kWidth + 6}), 6);
}

// Cells 2, 3 near the left UAV and 16, 17 near the right one: each takes its own two, both
// tours 2 steps; the cut one earlier would leave the right UAV 15 steps.
TEST(PriorTourSplit, EachUavTakesTheCellsNearerToIt) {
  PriorTourSplitter tours(kWidth, 1, 16);
  std::vector<int> cells{16, 3, 17, 2};
  const auto split = tours.split(kLeft, kRight, cells, both);
  EXPECT_EQ(cells, (std::vector<int>{2, 3, 16, 17}));
  EXPECT_EQ(split.first, 2u);
  EXPECT_EQ(split.later, 2);
}

TEST(PriorTourSplit, CellsOnlyOneMayReachAreItsWhateverTheDistance) {
  PriorTourSplitter tours(kWidth, 1, 16);
  std::vector<int> cells{2, 3, 16, 17};
  // 17 only the left UAV's, 2 only the right one's.
  const auto only = [](int i) { return i == 17 ? -1 : i == 2 ? 1 : 0; };
  const auto split = tours.split(kLeft, kRight, cells, only);
  EXPECT_EQ(cells.front(), 17);
  EXPECT_EQ(cells.back(), 2);
  EXPECT_GE(split.first, 1u);
  EXPECT_LT(split.first, cells.size());
  const std::span<const int> all(cells);
  EXPECT_EQ(split.later, std::max(tours.tour_steps(kLeft, all.first(split.first)),
                                  tours.tour_steps(kRight, all.subspan(split.first))));
}

TEST(PriorTourSplit, AllCellsNearOneUavAreSharedWhenThatEndsEarlier) {
  PriorTourSplitter tours(kWidth, 1, 16);
  // Six cells spread over columns 1-16 of row 0: the left UAV alone would fly 15 steps; the
  // right one takes the far cells and both end sooner.
  std::vector<int> cells{1, 4, 7, 10, 13, 16};
  const int alone = tours.tour_steps(kLeft, cells);
  const auto split = tours.split(kLeft, kRight, cells, both);
  EXPECT_GT(split.first, 0u);
  EXPECT_LT(split.first, cells.size());
  EXPECT_LT(split.later, alone);
}

}  // namespace
}  // namespace hullinspect::planners
