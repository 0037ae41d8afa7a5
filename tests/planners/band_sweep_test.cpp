// The detection-plane sweep of Sweep-Inspect (planners/band_sweep.hpp): every owned cell lies in
// the footprint of some position flown along a band, for both band directions, trimmed or not;
// trimming only shortens the flight; exact waypoints on a small region.
#include "hullinspect/planners/band_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/planners/waypoint_follower.hpp"
#include "hullinspect/world/hull.hpp"
#include "sweep_coverage.hpp"

namespace hullinspect::planners {
namespace {
using sweep_coverage::unseen_cells;

TEST(BandSweep, EveryOwnedCellIsSeenForBothDirectionsTrimmedOrNot) {
  const auto& hull = world::default_hull();
  for (int n : {1, 3, 4, 8}) {
    partition::PartitionRequest request;
    request.hull = &hull;
    request.starts = sweep_coverage::spread_starts(hull.width(), n);
    const auto partition = partition::make_partitioner("transfer", {})->partition(request);
    for (int s : {3, 5, 7, 9, 11}) {
      for (const BandAxis axis : {BandAxis::kRows, BandAxis::kColumns}) {
        for (int k = 0; k < n; ++k) {
          const grid::Cell from = request.starts[static_cast<std::size_t>(k)];
          const auto full = band_sweep(partition.owner, k, s, axis, false, from);
          const auto trimmed = band_sweep(partition.owner, k, s, axis, true, from);
          SCOPED_TRACE(::testing::Message() << "n=" << n << " s=" << s << " uav=" << k
                                            << " columns=" << (axis == BandAxis::kColumns));
          EXPECT_EQ(unseen_cells(partition.owner, k, (s - 1) / 2, from, full), 0);
          EXPECT_EQ(unseen_cells(partition.owner, k, (s - 1) / 2, from, trimmed), 0);
          EXPECT_LE(flight_length(from, trimmed), flight_length(from, full));
        }
      }
    }
  }
}

TEST(BandSweep, ColumnBandsOfARectangleStartAtItsLeftEdgeAndAreTrimmed) {
  // A 10 × 9 region at x = 4…13, y = 0…8 in a 20 × 9 grid; s = 3: bands x = 4–6, 7–9, 10–12 and
  // 13 (ceil(10 / 3) = 4), flown at x = 5, 8, 11, 14 — the last clamped to the band's centre
  // x = 13 + 1 — between y = 1 and 7 when trimmed (0 … 8 untrimmed).
  grid::Grid<std::int16_t> owner(20, 9, -1);
  for (int y = 0; y < 9; ++y)
    for (int x = 4; x <= 13; ++x) owner(x, y) = 0;
  const auto trimmed = band_sweep(owner, 0, 3, BandAxis::kColumns, true, {4, 0});
  const std::vector<grid::Cell> expected{{5, 1},  {5, 7},  {8, 7},  {8, 1},
                                         {11, 1}, {11, 7}, {14, 7}, {14, 1}};
  EXPECT_EQ(trimmed, expected);
  const auto full = band_sweep(owner, 0, 3, BandAxis::kColumns, false, {4, 0});
  EXPECT_EQ(full.front(), (grid::Cell{5, 0}));
  EXPECT_EQ(full[1], (grid::Cell{5, 8}));
  // Rows: bands y = 0–2, 3–5, 6–8 at y = 1, 4, 7; trimmed between x = 5 and 12.
  const auto rows = band_sweep(owner, 0, 3, BandAxis::kRows, true, {4, 0});
  const std::vector<grid::Cell> expected_rows{{5, 1}, {12, 1}, {12, 4}, {5, 4}, {5, 7}, {12, 7}};
  EXPECT_EQ(rows, expected_rows);
  EXPECT_TRUE(band_sweep(owner, 1, 3, BandAxis::kColumns, true, {0, 0}).empty());
}

// A sweep's tail handed over cuts its waypoints: keep(n) keeps the next n not yet reached, keep(n,
// c) ends them at c instead of the rest; the reached ones never come back.
TEST(WaypointFollower, KeepCutsTheWaypointsNotYetReached) {
  WaypointFollower follower;
  follower.assign({{0, 0}, {0, 5}, {3, 5}, {3, 0}});
  EXPECT_EQ(follower.next_action({0, 0}), sim::step_towards({0, 0}, {0, 5}));  // {0, 0} reached
  follower.keep(2);
  ASSERT_EQ(follower.remaining().size(), 2U);
  EXPECT_EQ(follower.remaining()[1], (grid::Cell{3, 5}));
  follower.keep(1, {2, 5});
  ASSERT_EQ(follower.remaining().size(), 2U);
  EXPECT_EQ(follower.remaining()[0], (grid::Cell{0, 5}));
  EXPECT_EQ(follower.remaining()[1], (grid::Cell{2, 5}));
  follower.keep(5);  // more than there are: nothing changes
  EXPECT_EQ(follower.remaining().size(), 2U);
  follower.keep(0, {0, 3});
  ASSERT_EQ(follower.remaining().size(), 1U);
  EXPECT_EQ(follower.target(), (grid::Cell{0, 3}));
  EXPECT_FALSE(follower.finished({0, 0}));
  EXPECT_TRUE(follower.finished({0, 3}));
}

}  // namespace
}  // namespace hullinspect::planners
