// Sweep-Inspect's approach to its sweep (planners/sweep_approach.hpp): the flight it plans,
// approach and bands (or its own band first), sees every cell of the region, for pieces of the
// band partition and irregular regions, both band axes and footprints 3-11; it is never longer
// than the plain sweep and shorter over a fleet starting in mid-piece; exact waypoints on a
// rectangle; two_block_sweep on a ragged region.
#include "hullinspect/planners/sweep_approach.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/planners/band_partition.hpp"
#include "hullinspect/world/hull.hpp"
#include "sweep_coverage.hpp"

namespace hullinspect::planners {
namespace {
using sweep_coverage::unseen_cells;

/// Checks the plan of every UAV of `owner` from `starts`: every cell seen, never longer than the
/// plain sweep; returns the steps saved over all of them.
int check_plans(const grid::Grid<std::int16_t>& owner, const std::vector<grid::Cell>& starts, int s,
                BandAxis axis, std::span<const int> band_start, bool own_band_first = false) {
  SweepScratch scratch;
  int saved = 0;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    SweepRequest request{static_cast<int>(k), s, axis, true, band_start, true};
    request.own_band_first = own_band_first;
    const SweepPlan plan = approach_and_sweep(owner, request, starts[k], scratch);
    const auto plain = plain_sweep(owner, request, starts[k]);
    SCOPED_TRACE(::testing::Message()
                 << "uav " << k << " s " << s << " rows " << (axis == BandAxis::kRows)
                 << " own band first " << own_band_first);
    EXPECT_EQ(unseen_cells(owner, static_cast<int>(k), (s - 1) / 2, starts[k], plan.waypoints), 0);
    const int length = flight_length(starts[k], plan.waypoints);
    EXPECT_LE(length, flight_length(starts[k], plain));
    EXPECT_LE(plan.approach, 3u);
    if (plan.approach == 0 && !plan.own_band_first) {
      EXPECT_EQ(plan.waypoints, plain);
    }
    if (!own_band_first) {
      EXPECT_FALSE(plan.own_band_first);
    }
    saved += flight_length(starts[k], plain) - length;
  }
  return saved;
}

TEST(SweepApproach, SeesEveryCellOfBandPiecesAndIsShorterFromMidPiece) {
  const auto& hull = world::default_hull();
  for (int s : {5, 7, 9, 11}) {
    const std::vector<int> band_start = column_band_starts(std::vector<int>(hull.width(), s));
    for (int n : {2, 4, 8}) {
      const auto starts = sweep_coverage::spread_starts(hull.width(), n);
      const auto pieces = band_order_partition(hull, {}, band_start, starts, s, s);
      // From a start in the middle of its piece the plain sweep first flies to a band's end
      // over cells its bands see again: the fleet's flights are shorter with the approach.
      for (const bool own_band_first : {false, true}) {
        EXPECT_GT(
            check_plans(pieces.owner, starts, s, BandAxis::kColumns, band_start, own_band_first), 0)
            << "s " << s << " n " << n;
      }
    }
  }
}

TEST(SweepApproach, SeesEveryCellOfIrregularRegionsForBothAxes) {
  const auto& hull = world::default_hull();
  for (int n : {1, 3, 5}) {
    partition::PartitionRequest request;
    request.hull = &hull;
    for (int k = 0; k < n; ++k)
      request.starts.push_back({(2 * k + 1) * hull.width() / (2 * n), 5 + 7 * k % 20});
    const auto partition = partition::make_partitioner("transfer", {})->partition(request);
    for (int s : {3, 7, 11}) {
      for (const BandAxis axis : {BandAxis::kRows, BandAxis::kColumns}) {
        for (const bool own_band_first : {false, true})
          check_plans(partition.owner, request.starts, s, axis, {}, own_band_first);
      }
    }
  }
}

// A 21 × 30 region in column bands of 7 (centres 3, 10, 17), from (10, 15). The plain sweep flies
// to (3, 26) and then three whole bands: 18 + 23 + 7 + 23 + 7 + 23 = 101 steps. Down the middle
// band's centre line to row 3 first (12 steps) sees its lower 19 rows, so that band is flown over
// rows 22-26 only: 12 + 7 + 23 + 7 + 4 + 11 + 23 = 87 (the first of the 87-step plans found).
TEST(SweepApproach, ExactPlanOnARectangle) {
  grid::Grid<std::int16_t> owner(21, 30, 0);
  SweepScratch scratch;
  const SweepRequest request{0, 7, BandAxis::kColumns, true, {}, true};
  const grid::Cell from{10, 15};
  const auto plain = plain_sweep(owner, request, from);
  EXPECT_EQ(plain,
            (std::vector<grid::Cell>{{3, 26}, {3, 3}, {10, 3}, {10, 26}, {17, 26}, {17, 3}}));
  EXPECT_EQ(flight_length(from, plain), 101);
  const SweepPlan plan = approach_and_sweep(owner, request, from, scratch);
  EXPECT_EQ(plan.approach, 1u);
  EXPECT_EQ(plan.waypoints, (std::vector<grid::Cell>{
                                {10, 3}, {3, 3}, {3, 26}, {10, 26}, {10, 22}, {17, 26}, {17, 3}}));
  EXPECT_EQ(flight_length(from, plan.waypoints), 87);
  EXPECT_EQ(unseen_cells(owner, 0, 3, from, plan.waypoints), 0);
}

// A 40 × 30 region in row bands of 5 (centres 2, 7, ..., 27), from (20, 15) in its fourth band.
// The plain sweep first flies 29 steps to (37, 27), then six whole bands: 264 steps (the edge
// approach: 254). Own band first: the four bands from its own down, their cells up to the cut
// h = 2 after it (x <= 22), from (20, 17): 2 + 4·18 + 3·5 = 89 steps; then the rest from (20, 2),
// those bands' right parts up and the two top bands whole: 160 steps, 249 in all.
TEST(SweepApproach, OwnBandFirstOnARectangle) {
  grid::Grid<std::int16_t> owner(40, 30, 0);
  SweepScratch scratch;
  SweepRequest request{0, 5, BandAxis::kRows, true, {}, true};
  const grid::Cell from{20, 15};
  EXPECT_EQ(flight_length(from, plain_sweep(owner, request, from)), 264);
  EXPECT_EQ(flight_length(from, approach_and_sweep(owner, request, from, scratch).waypoints), 254);
  request.own_band_first = true;
  const SweepPlan plan = approach_and_sweep(owner, request, from, scratch);
  EXPECT_TRUE(plan.own_band_first);
  EXPECT_EQ(plan.approach, 0u);
  EXPECT_EQ(plan.waypoints, (std::vector<grid::Cell>{
                                {20, 17}, {2, 17},  {2, 12},  {20, 12}, {20, 7}, {2, 7},   {2, 2},
                                {20, 2},  {25, 2},  {37, 2},  {37, 7},  {25, 7}, {25, 12}, {37, 12},
                                {37, 17}, {25, 17}, {37, 22}, {2, 22},  {2, 27}, {37, 27}}));
  EXPECT_EQ(flight_length(from, plan.waypoints), 249);
  EXPECT_EQ(unseen_cells(owner, 0, 2, from, plan.waypoints), 0);
}

// two_block_sweep on a ragged region in row bands of 5: columns 0-19 hold rows 0-9 only (two
// bands), columns 20-39 all 30 rows (six), from (10, 7). The plain sweep flies to (2, 2), the two
// low bands across all 40 columns and the four high ones from (22, 12): 13 + 35 + 5 + 35 + 25 +
// 4 · 15 + 3 · 5 = 188 steps. Cut at x = 15: the left block's two bands from (12, 7), 2 + 10 + 5
// + 10 = 27 steps to (12, 2), then the right block's six from (17, 2), 5 + 20 + 5 + 20 + 10 +
// 4 · 15 + 3 · 5 = 135: 162 in all. Both see every cell. A region one band wide keeps its
// plain sweep.
TEST(SweepApproach, TwoBlockSweepOnARaggedRegion) {
  const auto owner = sweep_coverage::ragged_region();
  const SweepRequest request{0, 5, BandAxis::kRows, true, {}, true};
  const grid::Cell from{10, 7};
  const auto plain = plain_sweep(owner, request, from);
  EXPECT_EQ(flight_length(from, plain), 188);
  const auto blocks = two_block_sweep(owner, request, from, plain);
  EXPECT_EQ(blocks, (std::vector<grid::Cell>{{12, 7},
                                             {2, 7},
                                             {2, 2},
                                             {12, 2},
                                             {17, 2},
                                             {37, 2},
                                             {37, 7},
                                             {17, 7},
                                             {22, 12},
                                             {37, 12},
                                             {37, 17},
                                             {22, 17},
                                             {22, 22},
                                             {37, 22},
                                             {37, 27},
                                             {22, 27}}));
  EXPECT_EQ(flight_length(from, blocks), 162);
  EXPECT_EQ(unseen_cells(owner, 0, 2, from, plain), 0);
  EXPECT_EQ(unseen_cells(owner, 0, 2, from, blocks), 0);
  // A region one band wide has no cut between bands.
  grid::Grid<std::int16_t> strip(40, 30, -1);
  for (int y = 0; y < 30; ++y) {
    for (int x = 20; x < 25; ++x) strip(x, y) = 0;
  }
  const auto one = plain_sweep(strip, request, from);
  EXPECT_EQ(two_block_sweep(strip, request, from, one), one);
}

}  // namespace
}  // namespace hullinspect::planners
