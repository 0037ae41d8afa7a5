// OwnedRuns (planners/owned_runs.hpp): its box and bands equal a scan of the grid's cells
// (region_bands over the owner grid with the removed boxes' cells cleared), for regions with
// holes and several runs per line, both band axes, band widths 3-11, with and without a band
// grid, and boxes that clear a region's first columns.
#include "hullinspect/planners/owned_runs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "hullinspect/planners/band_partition.hpp"
#include "hullinspect/world/hull.hpp"
#include "sweep_coverage.hpp"

namespace hullinspect::planners {
namespace {

/// UAV `uav`'s cells of `owner` with the cells inside `removed` given to nobody.
grid::Grid<std::int16_t> cleared(grid::Grid<std::int16_t> owner, int uav,
                                 std::span<const LegBox> removed) {
  for (const LegBox& box : removed) {
    for (int y = box.y_lo; y <= box.y_hi; ++y)
      for (int x = box.x_lo; x <= box.x_hi; ++x)
        if (owner(x, y) == uav) owner(x, y) = -1;
  }
  return owner;
}

void expect_same_bands(const RegionBands& a, const RegionBands& b) {
  ASSERT_EQ(a.bands.size(), b.bands.size());
  if (a.bands.empty()) return;
  EXPECT_EQ(a.origin, b.origin);
  for (std::size_t j = 0; j < a.bands.size(); ++j) {
    EXPECT_EQ(a.bands[j].hi, b.bands[j].hi) << "band " << j;
    if (a.bands[j].hi >= 0) {
      EXPECT_EQ(a.bands[j].lo, b.bands[j].lo) << "band " << j;
    }
  }
}

/// The bounding box of `uav`'s cells, cell by cell.
LegBox scanned_box(const grid::Grid<std::int16_t>& owner, int uav) {
  LegBox box{owner.width(), -1, owner.height(), -1};
  for (int y = 0; y < owner.height(); ++y) {
    for (int x = 0; x < owner.width(); ++x) {
      if (owner(x, y) != uav) continue;
      box = {std::min(box.x_lo, x), std::max(box.x_hi, x), std::min(box.y_lo, y),
             std::max(box.y_hi, y)};
    }
  }
  return box;
}

/// A region of UAV 0 with holes: the ragged region less random cells, so that lines hold
/// several runs.
grid::Grid<std::int16_t> holed_region(std::mt19937& random) {
  auto owner = sweep_coverage::ragged_region();
  std::uniform_int_distribution<int> x(0, owner.width() - 1);
  std::uniform_int_distribution<int> y(0, owner.height() - 1);
  for (int i = 0; i < 150; ++i) owner(x(random), y(random)) = 1;
  return owner;
}

LegBox random_box(std::mt19937& random, int width, int height) {
  std::uniform_int_distribution<int> x(-3, width + 2);
  std::uniform_int_distribution<int> y(-3, height + 2);
  std::uniform_int_distribution<int> half(0, 5);
  const grid::Cell a{x(random), y(random)};
  // A leg is straight: along x or along y.
  const grid::Cell b = random() % 2 == 0 ? grid::Cell{x(random), a.y} : grid::Cell{a.x, y(random)};
  return leg_footprints(a, b, half(random), width, height);
}

TEST(OwnedRuns, BoxAndBandsEqualAScanOfTheCells) {
  std::mt19937 random(7);
  OwnedRuns runs;  // reused, as the planner does
  int several_runs = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto owner = holed_region(random);
    for (const BandAxis axis : {BandAxis::kRows, BandAxis::kColumns}) {
      runs.build(owner, 0, axis);
      const LegBox box = runs.box();
      const LegBox scanned = scanned_box(owner, 0);
      EXPECT_EQ(box.x_lo, scanned.x_lo);
      EXPECT_EQ(box.x_hi, scanned.x_hi);
      EXPECT_EQ(box.y_lo, scanned.y_lo);
      EXPECT_EQ(box.y_hi, scanned.y_hi);
      for (const int s : {3, 5, 7, 11}) {
        const std::vector<int> band_start =
            column_band_starts(std::vector<int>(static_cast<std::size_t>(owner.width()), s));
        for (const bool grid_given : {false, true}) {
          const std::span<const int> starts =
              grid_given ? std::span<const int>(band_start) : std::span<const int>();
          SCOPED_TRACE(::testing::Message()
                       << "trial " << trial << " rows " << (axis == BandAxis::kRows) << " s " << s);
          expect_same_bands(runs.bands(s, starts), region_bands(owner, 0, s, axis, starts));
          std::vector<LegBox> removed;
          for (int count = 1; count <= 3; ++count) {
            removed.push_back(random_box(random, owner.width(), owner.height()));
            expect_same_bands(runs.bands(s, starts, removed),
                              region_bands(cleared(owner, 0, removed), 0, s, axis, starts));
          }
        }
      }
    }
    // The holes give lines of several runs, and removed boxes that end inside a run.
    for (int x = 0; x < owner.width(); ++x) {
      int starts_of_runs = 0;
      for (int y = 0; y < owner.height(); ++y)
        starts_of_runs += owner(x, y) == 0 && (y == 0 || owner(x, y - 1) != 0);
      several_runs += starts_of_runs > 1;
    }
  }
  EXPECT_GT(several_runs, 0);
}

TEST(OwnedRuns, ABoxOverTheFirstColumnsMovesTheColumnBandsOrigin) {
  // Column bands start at the first column left with a cell: clearing columns 0-3 of the ragged
  // region starts them at column 4 (at the band grid's band of it when given).
  const auto owner = sweep_coverage::ragged_region();
  OwnedRuns runs;
  runs.build(owner, 0, BandAxis::kColumns);
  const std::vector<LegBox> removed{{0, 3, 0, 29}};
  const RegionBands own = runs.bands(5, {}, removed);
  EXPECT_EQ(own.origin, 4);
  expect_same_bands(own, region_bands(cleared(owner, 0, removed), 0, 5, BandAxis::kColumns));
  const std::vector<int> band_start = column_band_starts(std::vector<int>(40, 5));
  EXPECT_EQ(runs.bands(5, band_start, removed).origin, 0);
}

TEST(OwnedRuns, AnEmptyRegionHasNoBox) {
  const grid::Grid<std::int16_t> owner(10, 8, 1);
  OwnedRuns runs;
  for (const BandAxis axis : {BandAxis::kRows, BandAxis::kColumns}) {
    runs.build(owner, 0, axis);
    EXPECT_LT(runs.box().x_hi, 0);
    for (const BandExtent& e : runs.bands(3, {}).bands) EXPECT_LT(e.hi, 0);
  }
}

TEST(OwnedRuns, OnlyTheColumnsGivenAreRead) {
  auto owner = sweep_coverage::ragged_region();
  OwnedRuns runs;
  runs.build(owner, 0, BandAxis::kRows, 20, 29);
  const LegBox box = runs.box();
  EXPECT_EQ(box.x_lo, 20);
  EXPECT_EQ(box.x_hi, 29);
  expect_same_bands(runs.bands(7, {}), region_bands(owner, 0, 7, BandAxis::kRows, {}, 20, 29));
}

}  // namespace
}  // namespace hullinspect::planners
