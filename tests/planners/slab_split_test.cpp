// Column slabs that end together (Sweep-Inspect's re-split at a failure off the band grid).

#include "hullinspect/planners/slab_split.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace hullinspect::planners {
namespace {

constexpr int kWidth = 20;
constexpr int kHeight = 5;

/// Every cell of a 20 × 5 grid, sorted by column (then row).
std::vector<int> all_cells_by_column() {
  std::vector<int> cells;
  for (int x = 0; x < kWidth; ++x) {
    for (int y = 0; y < kHeight; ++y) cells.push_back(y * kWidth + x);
  }
  return cells;
}

/// The owner of each cell after split_in_slabs; every cell must be assigned exactly once.
std::vector<int> split(const std::vector<int>& cells,
                       const std::vector<std::pair<int, grid::Cell>>& uavs,
                       const std::vector<double>& load, double per_column) {
  std::vector<int> owner(static_cast<std::size_t>(kWidth * kHeight), -1);
  split_in_slabs(cells, kWidth, uavs, load, per_column, [&](int k, int i) {
    EXPECT_EQ(owner[static_cast<std::size_t>(i)], -1) << "cell " << i << " assigned twice";
    owner[static_cast<std::size_t>(i)] = k;
  });
  for (int i : cells) EXPECT_NE(owner[static_cast<std::size_t>(i)], -1) << "cell " << i;
  return owner;
}

int count(const std::vector<int>& owner, int k) {
  return static_cast<int>(std::count(owner.begin(), owner.end(), k));
}

TEST(SlabSplit, SlabsGoLeftToRightInTheOrderGiven) {
  const auto cells = all_cells_by_column();
  const auto owner = split(cells, {{2, {0, 0}}, {0, {10, 2}}, {1, {19, 4}}}, {0, 0, 0}, 0.0);
  // Walking the cells in column order, the owners come as runs 2, 0, 1.
  std::vector<int> runs;
  for (int i : cells) {
    const int k = owner[static_cast<std::size_t>(i)];
    if (runs.empty() || runs.back() != k) runs.push_back(k);
  }
  EXPECT_EQ(runs, (std::vector<int>{2, 0, 1}));
}

TEST(SlabSplit, EqualUavsGetEqualSlabs) {
  // No loads, no flight cost: 100 cells among 4 UAVs, 25 each (within the bisection's 0.25).
  const auto owner =
      split(all_cells_by_column(), {{0, {0, 0}}, {1, {5, 0}}, {2, {10, 0}}, {3, {15, 0}}},
            {0, 0, 0, 0}, 0.0);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(count(owner, k), 25) << "UAV " << k;
}

TEST(SlabSplit, ALoadOrAFlightGivesAUavLess) {
  const auto cells = all_cells_by_column();
  // UAV 0 still has 20 cells' worth of other work: the later of the two ends is earliest when it
  // takes 20 fewer cells (40 against 60).
  const auto loaded = split(cells, {{0, {0, 0}}, {1, {19, 0}}}, {20.0, 0.0}, 0.0);
  EXPECT_EQ(count(loaded, 0), 40);
  EXPECT_EQ(count(loaded, 1), 60);
  // Both UAVs at the right end, a column's flight costing 5: the left slab's UAV pays for its
  // flight there and gets less.
  const auto far = split(cells, {{0, {19, 0}}, {1, {19, 0}}}, {0.0, 0.0}, 5.0);
  EXPECT_LT(count(far, 0), count(far, 1));
}

TEST(SlabSplit, NothingToSplitAssignsNothing) {
  int calls = 0;
  split_in_slabs({}, kWidth, std::vector<std::pair<int, grid::Cell>>{{0, {0, 0}}},
                 std::vector<double>{0.0}, 1.0, [&](int, int) { ++calls; });
  const std::vector<int> cells = all_cells_by_column();
  split_in_slabs(cells, kWidth, {}, {}, 1.0, [&](int, int) { ++calls; });
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace hullinspect::planners
