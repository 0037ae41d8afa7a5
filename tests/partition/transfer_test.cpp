// The `transfer` partitioner (docs/partition.md): every result goes through the shared partition
// checker (every hull cell owned once, regions 4-connected and holding their starts, sizes as
// reported, balance within the tolerance) — on the default hull for n = 1 … 32, random hulls with
// random starts, starts bunched at one launch point, shares, weights, a bottleneck, no-fly zones, a
// walled-in start, determinism and input errors.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/partition/transfer_partitioner.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "random_hull.hpp"
#include "support/partition_checker.hpp"

namespace hullinspect {
namespace {

using partition::Partition;
using partition::PartitionRequest;
using partition::TransferOptions;
using partition::TransferPartitioner;
using testing::valid_partition;

PartitionRequest request_for(const world::HullMask& hull, std::vector<grid::Cell> starts) {
  PartitionRequest r;
  r.hull = &hull;
  r.starts = std::move(starts);
  return r;
}

std::vector<grid::Cell> default_starts(const world::HullMask& hull, int n) {
  world::MissionParams p;
  p.uavs = n;
  return world::start_cells(p, hull);
}

world::HullMask text_hull(const std::string& rows) {
  return world::parse_text_mask(rows, "test");
}

// Converged: connected, holding the starts, and every region within one cell of its desired size
// (the documented goal is ±1 cell or ±0.5 %, whichever is larger; this is the stricter one).
void expect_balanced(const PartitionRequest& request, const Partition& p) {
  EXPECT_TRUE(p.converged) << (p.warnings.empty() ? "" : p.warnings[0]);
  EXPECT_TRUE(p.warnings.empty());
  EXPECT_TRUE(valid_partition(request, p));
  EXPECT_TRUE(valid_partition(request, p, {.tolerance = 1.0}));
  for (std::size_t k = 0; k < p.region_cells.size(); ++k) {
    EXPECT_LT(std::abs(p.region_cells[k] - p.desired_weight[k]), 1.0) << "UAV " << k;
  }
}

TEST(Transfer, IsRegisteredButNotTheDefault) {
  EXPECT_EQ(partition::kDefaultPartitioner, "darp");
  auto p = partition::make_partitioner("transfer");
  EXPECT_NE(dynamic_cast<TransferPartitioner*>(p.get()), nullptr);
  EXPECT_EQ(partition::resolve_partitioner_options("transfer").at("round-limit"), "100000");
}

TEST(Transfer, DefaultHullOneToThirtyTwoUavs) {
  const auto& hull = world::default_hull();
  const TransferPartitioner transfer;
  for (int n = 1; n <= 32; ++n) {
    SCOPED_TRACE(n);
    const auto request = request_for(hull, default_starts(hull, n));
    const Partition p = transfer.partition(request);
    expect_balanced(request, p);
    EXPECT_EQ(std::accumulate(p.region_cells.begin(), p.region_cells.end(), 0), hull.cell_count());
  }
}

TEST(Transfer, ExactDivisionIsExact) {
  const auto hull = text_hull("XXXXXXXXXXXX\nXXXXXXXXXXXX\nXXXXXXXXXXXX\nXXXXXXXXXXXX\n");
  const auto request = request_for(hull, {{0, 0}, {1, 0}, {2, 0}, {11, 3}});
  const Partition p = TransferPartitioner().partition(request);
  expect_balanced(request, p);
  EXPECT_EQ(p.tolerance, 0.0);
  EXPECT_EQ(p.region_cells, (std::vector<int>{12, 12, 12, 12}));
}

TEST(Transfer, RandomStartsOnTheDefaultHull) {
  // Ten random start sets for small fleets (the full n = 1 … 32 sweep is bench/transfer_bench).
  const auto& hull = world::default_hull();
  const TransferPartitioner transfer;
  for (int n : {2, 5, 12, 20}) {
    for (std::uint64_t draw = 0; draw < 10; ++draw) {
      SCOPED_TRACE(::testing::Message() << "n " << n << ", draw " << draw);
      const auto request = request_for(hull, testing::random_starts(hull, n, 1000 * n + draw));
      expect_balanced(request, transfer.partition(request));
    }
  }
}

TEST(Transfer, EscapeRoundsFreeRegionsStuckBehindArms) {
  // bench/transfer_bench's start sets for n = 24 … 27 on the default hull: one set of each got
  // stuck (regions whose only cells beside the under-full ones were necks of long arms) before the
  // escape rounds, in all 8 attempts; now all ten of each balance.
  const auto& hull = world::default_hull();
  const TransferPartitioner transfer;
  for (int n : {24, 25, 26, 27}) {
    for (std::uint64_t draw = 0; draw < 10; ++draw) {
      SCOPED_TRACE(::testing::Message() << "n " << n << ", draw " << draw);
      const auto request = request_for(hull, testing::random_starts(hull, n, 1000 * n + draw));
      expect_balanced(request, transfer.partition(request));
    }
  }
}

TEST(Transfer, RegrowthBalancesTheSetsTheSeededAttemptsLeft) {
  // Random start sets on the default hull that ended unbalanced after all 8 seeded attempts
  // (bench/transfer_bench: RandomStarts n = 17 draw 9, n = 23 draw 4, n = 30 draw 3; FreshStarts
  // n = 19 draw 7, n = 28 draw 0): each holds starts a few cells apart whose Voronoi cells are
  // pockets far below their share, and the transfers wound the regions into arms. None is walled
  // in by start cells (no warning says so); the regrowth attempts (offsets, then fronts) balance
  // them. Start lists as drawn, so the test does not depend on the draw.
  const std::vector<std::vector<grid::Cell>> sets = {
      {{33, 18},
       {47, 12},
       {70, 26},
       {112, 20},
       {131, 15},
       {51, 16},
       {20, 18},
       {72, 2},
       {109, 24},
       {70, 25},
       {110, 13},
       {74, 26},
       {150, 21},
       {84, 29},
       {98, 22},
       {46, 10},
       {41, 28}},
      {{179, 24}, {83, 24},  {204, 15}, {224, 26}, {202, 5},  {138, 4},  {79, 16}, {188, 24},
       {66, 22},  {23, 25},  {146, 10}, {102, 24}, {135, 19}, {138, 5},  {161, 4}, {175, 16},
       {181, 8},  {160, 21}, {47, 17},  {207, 10}, {197, 4},  {141, 20}, {157, 13}},
      {{197, 3},  {132, 17}, {186, 15}, {146, 14}, {49, 21},  {119, 15}, {148, 29}, {148, 22},
       {161, 27}, {156, 24}, {89, 6},   {71, 8},   {127, 16}, {51, 13},  {108, 25}, {199, 3},
       {155, 8},  {124, 11}, {161, 9},  {42, 14},  {78, 18},  {182, 5},  {205, 17}, {185, 20},
       {26, 16},  {165, 28}, {226, 27}, {57, 12},  {169, 29}, {92, 27}},
      {{63, 22},
       {190, 21},
       {80, 29},
       {106, 11},
       {30, 3},
       {48, 10},
       {192, 18},
       {107, 1},
       {107, 23},
       {67, 29},
       {96, 27},
       {146, 12},
       {181, 15},
       {125, 4},
       {82, 17},
       {73, 0},
       {118, 15},
       {86, 28},
       {84, 9}},
      {{144, 22}, {1, 17},   {79, 12}, {63, 21}, {183, 16}, {49, 25},  {198, 14},
       {6, 9},    {179, 10}, {29, 2},  {57, 19}, {0, 14},   {112, 23}, {86, 7},
       {28, 10},  {207, 19}, {5, 28},  {53, 27}, {6, 27},   {0, 22},   {163, 20},
       {211, 10}, {66, 15},  {52, 5},  {82, 9},  {1, 26},   {20, 23},  {208, 23}},
  };
  const auto& hull = world::default_hull();
  const TransferPartitioner transfer;
  for (const auto& starts : sets) {
    SCOPED_TRACE(starts.size());
    const auto request = request_for(hull, starts);
    expect_balanced(request, transfer.partition(request));
  }
  // The seeded attempts alone still end unbalanced (what the regrowths are for; one set, as each
  // run of 8 failing attempts is slow under the sanitizers).
  const auto first = request_for(hull, sets.front());
  EXPECT_FALSE(TransferPartitioner({.attempts = 8, .regrow = false}).partition(first).converged);
}

TEST(Transfer, AdaptiveRegrowthBalancesASetTheFixedStepsLeft) {
  // RandomStarts n = 27 draw 6 on the default hull: the offsets regrowth (steps bounded by 4
  // distance steps per growth) moves the over-full regions beside each other in lockstep, so the
  // largest one never shrinks; plain, offsets, fronts and the first seeded attempt all end
  // unbalanced, and so did the seeded regrowths after them (attempts = 2: 43.6 cells off). The
  // adaptive regrowth (per-region step bounds, Rprop-like) balances it.
  const std::vector<grid::Cell> starts = {
      {183, 21}, {193, 20}, {216, 15}, {198, 3},  {164, 20}, {163, 11}, {62, 9},
      {106, 13}, {183, 25}, {199, 3},  {149, 8},  {55, 14},  {220, 28}, {108, 0},
      {212, 13}, {65, 18},  {21, 7},   {127, 15}, {65, 2},   {216, 23}, {82, 0},
      {26, 27},  {199, 14}, {126, 26}, {115, 12}, {97, 21},  {187, 8}};
  const auto request = request_for(world::default_hull(), starts);
  const Partition p = TransferPartitioner({.attempts = 2}).partition(request);
  expect_balanced(request, p);
  // Deterministic: the regrowths draw nothing, so another seed gives the same partition.
  auto reseeded = request;
  reseeded.seed = 99;
  const Partition again = TransferPartitioner({.attempts = 2}).partition(reseeded);
  EXPECT_TRUE(std::ranges::equal(again.owner.values(), p.owner.values()));
}

TEST(Transfer, StuckAttemptsEndEarly) {
  // FreshStarts n = 26 draw 6 on the default hull, the one random set of 1280 that no attempt
  // balances (six starts share the stern; see docs/partition.md). Each attempt used to go on
  // through its n escape rounds, 11599 rounds in all; an attempt now ends after max(8, n / 2)
  // escape rounds in a row that did not improve Σ|error|. Still a connected partition holding
  // every start, with the warning.
  const std::vector<grid::Cell> starts = {
      {64, 15}, {109, 13}, {129, 0}, {63, 6},  {12, 21}, {152, 5}, {44, 11},  {89, 5},   {29, 20},
      {55, 27}, {39, 28},  {87, 17}, {25, 21}, {124, 2}, {111, 2}, {137, 23}, {184, 28}, {111, 12},
      {29, 5},  {99, 5},   {82, 16}, {92, 16}, {115, 1}, {0, 27},  {51, 24},  {15, 9}};
  const auto request = request_for(world::default_hull(), starts);
  const Partition p = TransferPartitioner().partition(request);
  EXPECT_FALSE(p.converged);
  EXPECT_LT(p.iterations, 10000);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("(13 attempts)"), std::string::npos) << p.warnings[0];
  EXPECT_TRUE(valid_partition(request, p));  // connected, holding the starts, sizes as reported
}

TEST(Transfer, AStartWalledInByStartCellsIsReportedAsInfeasible) {
  // UAV 0 starts in a corner whose two neighbours are UAV 1's and UAV 2's starts: any region
  // holding UAV 0's start and no other start is that one cell, so no partition reaches its 8.
  const auto hull = text_hull("XXXXXX\nXXXXXX\nXXXXXX\nXXXXXX\n");
  const auto request = request_for(hull, {{0, 0}, {1, 0}, {0, 1}});
  const Partition p = TransferPartitioner().partition(request);
  EXPECT_FALSE(p.converged);
  EXPECT_TRUE(valid_partition(request, p));
  EXPECT_EQ(p.region_cells[0], 1);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0],
            "transfer: no balanced partition exists: UAV 0's start (0, 0) is walled in by the "
            "start cells of UAVs 1 and 2, so its region can hold at most 1 of its target 8 cells; "
            "returned the best connected partition reached (largest imbalance 7)");
}

TEST(Transfer, RandomHullsWithRandomStarts) {
  const TransferPartitioner transfer;
  int runs = 0;
  int converged = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto hull = testing::random_hull(seed, 30 + static_cast<int>(seed % 4) * 15,
                                           12 + static_cast<int>(seed % 3) * 6);
    for (int n = 2; n <= 8; ++n) {
      SCOPED_TRACE(::testing::Message() << "hull seed " << seed << ", n " << n);
      const auto request = request_for(hull, testing::random_starts(hull, n, seed * 10 + n));
      const Partition p = transfer.partition(request);
      // Always connected, holding the starts, sizes as reported; balanced when converged.
      EXPECT_TRUE(valid_partition(request, p));
      EXPECT_EQ(p.converged, p.warnings.empty());
      if (p.converged) {
        EXPECT_TRUE(valid_partition(request, p, {.tolerance = 1.0}));
      }
      ++runs;
      converged += p.converged;
    }
  }
  // Small hulls with holes, 2-8 UAVs at random (often adjacent) cells: measured 80 of 84 (78
  // before the regrowth attempts); none of the other 4 is walled in by start cells (so not proved
  // infeasible), but narrow passages between holes and bites may make them so.
  EXPECT_GE(converged, 80) << "of " << runs;
}

TEST(Transfer, StartsAtOneLaunchPoint) {
  // DARP's hard case (docs/partition.md): starts 3 cells apart at the stern's bottom corner. Four
  // still balance from their own starts (transfers pass cells along chains of regions); for larger
  // fleets the documented strategy is spread-starts: regions grown from the model's spread start
  // cells, each UAV flying to its own first.
  const auto& hull = world::default_hull();
  auto bunched = [&](int n) {
    std::vector<grid::Cell> starts;
    for (int k = 0; k < n; ++k) starts.push_back(hull.snap({30 + 3 * (k % 4), 2 + 3 * (k / 4)}));
    return starts;
  };
  const auto four = request_for(hull, bunched(4));
  expect_balanced(four, TransferPartitioner().partition(four));
  const TransferPartitioner spread({.spread_starts = true});
  for (int n : {4, 8, 16, 32}) {
    SCOPED_TRACE(n);
    const auto request = request_for(hull, bunched(n));
    const Partition p = spread.partition(request);
    EXPECT_TRUE(p.converged);
    EXPECT_TRUE(valid_partition(request, p, {.regions_hold_starts = false, .tolerance = 1.0}));
    // UAVs fan out in the order of their starts: the stern-most start gets the stern-most region.
    EXPECT_EQ(p.owner(0, hull.height() - 1), 0);
  }
}

TEST(Transfer, UnequalShares) {
  const auto& hull = world::default_hull();
  auto request = request_for(hull, default_starts(hull, 4));
  request.shares = {1, 2, 3, 4};
  const Partition p = TransferPartitioner().partition(request);
  expect_balanced(request, p);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(p.desired_weight[k], hull.cell_count() * static_cast<double>(k + 1) / 10.0, 1e-9);
  }
}

TEST(Transfer, WeightedCellsBalanceWeightNotArea) {
  const auto& hull = world::default_hull();
  auto request = request_for(hull, default_starts(hull, 4));
  request.weights = grid::Grid<double>(hull.width(), hull.height(), 1.0);
  for (int y = 0; y < hull.height(); ++y) {
    for (int x = 0; x < 60; ++x) request.weights(x, y) = 3.0;  // the stern is three times the work
  }
  const Partition p = TransferPartitioner().partition(request);
  ASSERT_TRUE(p.converged);
  EXPECT_EQ(p.tolerance, 3.0);  // one heaviest cell
  EXPECT_TRUE(valid_partition(request, p));
  EXPECT_LT(p.region_cells[0], p.region_cells[3] * 3 / 4);
}

TEST(Transfer, OneCellWideBottleneck) {
  std::string rows;
  for (int y = 0; y < 6; ++y) {
    rows += std::string(10, 'X') + (y == 2 ? std::string(6, 'X') : std::string(6, '.')) +
            std::string(10, 'X') + "\n";
  }
  const auto hull = text_hull(rows);
  for (const auto& starts : {std::vector<grid::Cell>{{2, 2}, {22, 3}},
                             std::vector<grid::Cell>{{1, 1}, {8, 4}, {24, 2}}}) {
    SCOPED_TRACE(starts.size());
    const auto request = request_for(hull, starts);
    expect_balanced(request, TransferPartitioner().partition(request));
  }
}

TEST(Transfer, NoFlyZonesShapeTheGrowth) {
  // A no-fly wall across the middle of a 20 × 6 hull with one gap at the top: flights from the
  // left start reach the right half only around it, so with the wall the left region is the one
  // that has to grow towards the gap. The partition stays connected over hull cells and balanced.
  std::string rows;
  for (int y = 0; y < 6; ++y) rows += std::string(20, 'X') + "\n";
  const auto hull = text_hull(rows);
  auto request = request_for(hull, {{2, 0}, {17, 0}, {9, 0}});
  request.allowed = grid::Grid<std::uint8_t>(20, 6, 1);
  for (int y = 0; y < 5; ++y) request.allowed(12, y) = 0;
  const Partition walled = TransferPartitioner().partition(request);
  expect_balanced(request, walled);
  request.allowed = {};
  const Partition open = TransferPartitioner().partition(request);
  expect_balanced(request, open);
  EXPECT_FALSE(std::ranges::equal(walled.owner.values(), open.owner.values()));
}

TEST(Transfer, WalledInStartReturnsTheConnectedPartitionWithAWarning) {
  const auto corridor = text_hull(
      "XXXXXXXX\n"
      "XXXXXXXX\n"
      "XXXXXXXX\n"
      "XXXX....\n"
      "X.......\n");
  const auto request = request_for(corridor, {{0, 1}, {0, 0}, {6, 3}});
  const Partition p = TransferPartitioner().partition(request);
  EXPECT_FALSE(p.converged);
  EXPECT_TRUE(valid_partition(request, p));
  EXPECT_EQ(p.region_cells[1], 1);
  ASSERT_EQ(p.warnings.size(), 1u);
  // UAV 1's start is the tip of the dead end, whose only neighbour is UAV 0's start: provably
  // infeasible, so one attempt and the proof as the warning.
  EXPECT_NE(p.warnings[0].find("transfer: no balanced partition exists: UAV 1's start (0, 0) is "
                               "walled in by the start cell of UAV 0, so its region can hold at "
                               "most 1 of its target 10 cells; returned the best connected "
                               "partition reached (largest imbalance "),
            std::string::npos)
      << p.warnings[0];
  double worst = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    worst = std::max(worst, std::abs(p.region_weight[k] - p.desired_weight[k]));
  }
  EXPECT_DOUBLE_EQ(p.tolerance, worst);
}

TEST(Transfer, RoundLimitStopsEarlyWithAWarning) {
  const auto& hull = world::default_hull();
  const auto request = request_for(hull, default_starts(hull, 12));
  const Partition p = TransferPartitioner({.round_limit = 1}).partition(request);
  EXPECT_FALSE(p.converged);
  EXPECT_EQ(p.iterations, 1);
  EXPECT_TRUE(valid_partition(request, p));
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("in 1 round (1 attempt): round limit reached"), std::string::npos)
      << p.warnings[0];
}

TEST(Transfer, DeterministicAndSeedIndependentWhenTheFirstAttemptConverges) {
  const auto& hull = world::default_hull();
  auto request = request_for(hull, testing::random_starts(hull, 9, 77));
  const Partition a = TransferPartitioner().partition(request);
  request.seed = 12345;
  const Partition b = TransferPartitioner().partition(request);
  EXPECT_TRUE(std::ranges::equal(a.owner.values(), b.owner.values()));
}

TEST(Transfer, BadRequestsAreRejected) {
  const auto& hull = world::default_hull();
  const TransferPartitioner transfer;
  auto expect_error = [&](const PartitionRequest& r, const std::string& message) {
    try {
      transfer.partition(r);
      ADD_FAILURE() << "no error, expected " << message;
    } catch (const ParameterError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  expect_error(request_for(hull, {}), "uavs: must be at least 1 (got 0)");
  expect_error(request_for(hull, {{5, 40}}),
               "starts: start cell (5, 40) of UAV 0 is outside the 230 × 30 grid");
  expect_error(request_for(hull, {{40, 15}, {41, 15}, {40, 15}}),
               "starts: UAVs 0 and 2 both start on cell (40, 15); every UAV needs its own start "
               "cell");
  auto shares = request_for(hull, {{40, 15}, {41, 15}});
  shares.shares = {1, 0};
  expect_error(shares, "shares: share of UAV 1 is 0; shares must be finite and > 0");
  try {
    partition::make_partitioner("transfer", {{"round-limit", "0"}});
    ADD_FAILURE() << "round-limit 0 accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("transfer.round-limit"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hullinspect
