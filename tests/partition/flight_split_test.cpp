// Partitions per flight component (docs/model.md §8, partition/flight_split.hpp): a no-fly wall
// that cuts the flight space gives each part's hull cells to the UAVs starting in that part;
// one flight space leaves every partitioner's result untouched.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "hullinspect/partition/fallback.hpp"
#include "hullinspect/partition/flight_split.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/random.hpp"
#include "support/no_fly_layouts.hpp"
#include "support/partition_checker.hpp"

namespace hullinspect::testing {
namespace {

// A request as a mission makes it (planners::add_no_fly): flyable positions and who sees what.
struct SplitRequest {
  world::Reachability reach;
  partition::PartitionRequest request;
};

SplitRequest make_request(const world::HullMask& hull, const NoFlyMask& no_fly,
                          std::vector<grid::Cell> starts, int s1 = 5, int s2 = 7) {
  SplitRequest s;
  s.reach = world::compute_reachability(hull, &no_fly, s1, s2, starts);
  s.request.hull = &hull;
  s.request.starts = std::move(starts);
  s.request.allowed = s.reach.flyable;
  s.request.seen_from = s.reach.seen_from;
  return s;
}

partition::Partition split(const partition::PartitionRequest& request, const std::string& name) {
  const auto partitioner = partition::make_partitioner(name);
  return partition::partition_per_flight_component(
      request, [&](const partition::PartitionRequest& one) { return partitioner->partition(one); });
}

// Brute force, independent of compute_reachability: every hull cell a flight component is said to
// see lies in the footprint (z = 1 if any flyable position sees it at z = 1, else z = 2) of a
// position of that component; a cell said to be seen by none lies in no flyable footprint.
::testing::AssertionResult seen_from_is_right(const world::HullMask& hull, const SplitRequest& s,
                                              int s1, int s2) {
  auto covered_by = [&](grid::Cell c, int half, int component) {
    for (int y = c.y - half; y <= c.y + half; ++y) {
      for (int x = c.x - half; x <= c.x + half; ++x) {
        if (!hull.mask().contains(x, y) || !s.reach.flyable(x, y)) continue;
        if (component < 0 || s.reach.flight_component(x, y) == component) return true;
      }
    }
    return false;
  };
  for (int i : hull.cells()) {
    const grid::Cell c = hull.mask().cell(i);
    const int half = covered_by(c, (s1 - 1) / 2, -1) ? (s1 - 1) / 2 : (s2 - 1) / 2;
    const int seen = s.reach.seen_from[i];
    if (seen < 0 ? covered_by(c, half, -1) : !covered_by(c, half, seen)) {
      return ::testing::AssertionFailure()
             << fmt::format("cell ({}, {}) said to be seen from {}", c.x, c.y, seen);
    }
  }
  return ::testing::AssertionSuccess();
}

// The default hull with a full-height wall at x = 100 (a wall that cuts the flight space in two).
NoFlyMask wall_at_100() {
  NoFlyMask m(world::default_hull().width(), world::default_hull().height(), 0);
  no_fly_box(m, 100, 0, 100, 29);
  return m;
}

TEST(FlightSplit, WallWithUavsOnBothSidesInUnequalNumbers) {
  const auto& hull = world::default_hull();
  const SplitRequest s =
      make_request(hull, wall_at_100(), {{20, 15}, {60, 15}, {90, 15}, {180, 15}});
  EXPECT_EQ(s.reach.flight_components, 2);
  EXPECT_TRUE(seen_from_is_right(hull, s, 5, 7));
  EXPECT_EQ(partition::start_components(s.request), (std::vector<int>{0, 0, 0, 1}));
  for (const auto& info : partition::partitioner_registry()) {
    SCOPED_TRACE(info.name);
    const partition::Partition p = split(s.request, info.name);
    PartitionCheck check;
    check.regions_hold_starts = info.name != "stripes";  // stripes ignores the starts
    EXPECT_TRUE(valid_partition(s.request, p, check));
    // The wall's column goes to the left (its viewpoint ties break to the lowest x); z = 1 sees
    // two columns past the wall from each side.
    int left = 0;
    for (int i : hull.cells()) left += hull.mask().cell(i).x <= 100 ? 1 : 0;
    EXPECT_EQ(p.region_cells[3], hull.cell_count() - left) << "UAV 3 alone on the right";
    EXPECT_EQ(p.region_cells[0] + p.region_cells[1] + p.region_cells[2], left);
    EXPECT_DOUBLE_EQ(p.desired_weight[0], left / 3.0);
  }
}

TEST(FlightSplit, AFullHeightWallGivesNoRegionAcrossIt) {
  const auto& hull = world::default_hull();
  world::MissionParams params;
  params.uavs = 4;
  const auto starts = world::start_cells(params, hull);
  const SplitRequest s = make_request(hull, wall_at_100(), starts);
  // Before: DARP over hull cells gave UAV 1, starting at (86, 15), cells beyond the wall.
  const partition::Partition darp_alone = partition::make_partitioner("darp")->partition(s.request);
  EXPECT_FALSE(valid_partition(s.request, darp_alone));
  const partition::Partition p = partition::partition_with_fallback("darp", {}, s.request);
  EXPECT_TRUE(valid_partition(s.request, p));
  EXPECT_TRUE(p.converged);
  EXPECT_TRUE(p.fallback.empty());
}

TEST(FlightSplit, OneFlightSpaceIsLeftToThePartitioner) {
  const auto& hull = world::default_hull();
  NoFlyMask m(hull.width(), hull.height(), 0);
  no_fly_box(m, 40, 10, 40, 29);  // a mooring line: the flight space stays one, every cell is seen
  world::MissionParams params;
  params.uavs = 4;
  const SplitRequest s = make_request(hull, m, world::start_cells(params, hull));
  EXPECT_EQ(s.reach.flight_components, 1);
  EXPECT_EQ(s.reach.unreachable_z2, 0);
  for (const auto& info : partition::partitioner_registry()) {
    SCOPED_TRACE(info.name);
    const partition::Partition alone = partition::make_partitioner(info.name)->partition(s.request);
    EXPECT_EQ(split(s.request, info.name).owner, alone.owner);
  }
  partition::PartitionRequest plain = s.request;
  plain.allowed = {};
  plain.seen_from = {};
  EXPECT_EQ(partition::partition_with_fallback("darp", {}, plain).owner,
            partition::make_partitioner("darp")->partition(plain).owner);
}

TEST(FlightSplit, UnseenCellsAreNotCountedInTheBalance) {
  // Every UAV left of the wall: the right side is seen by no one. Those cells join the regions
  // next to them afterwards; the seen cells are balanced.
  const auto& hull = world::default_hull();
  const SplitRequest s = make_request(hull, wall_at_100(), {{20, 15}, {60, 15}, {90, 15}});
  EXPECT_EQ(s.reach.flight_components, 1);
  EXPECT_GT(s.reach.unreachable_z2, 3000);
  const partition::Partition p = partition::partition_with_fallback("darp", {}, s.request);
  EXPECT_TRUE(valid_partition(s.request, p));
  EXPECT_TRUE(p.converged);
  const int seen = hull.cell_count() - s.reach.unreachable_z2;
  for (int k = 0; k < 3; ++k) {
    int own_seen = 0;
    for (int i : hull.cells()) own_seen += p.owner[i] == k && s.reach.seen_from[i] >= 0 ? 1 : 0;
    EXPECT_NEAR(own_seen, seen / 3.0, 1.0) << "UAV " << k;
  }
}

// A U-shaped hull (a bar along the bottom, two uprights) with a no-fly wall across at y = 4: the
// upper flight space sees the tops of both uprights, two pieces of hull with starts in only one.
TEST(FlightSplit, APieceWithoutAStartGoesWholeToTheNearestUav) {
  grid::Grid<std::uint8_t> u(20, 12, 0);
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 20; ++x) u(x, y) = y < 2 || x < 4 || x >= 16 ? 1 : 0;
  }
  const world::HullMask hull(std::move(u), "test:u");
  NoFlyMask m(20, 12, 0);
  no_fly_box(m, 0, 4, 19, 4);
  const SplitRequest s = make_request(hull, m, {{10, 0}, {0, 9}, {3, 6}});
  ASSERT_EQ(s.reach.flight_components, 2);
  EXPECT_TRUE(seen_from_is_right(hull, s, 5, 7));
  const partition::Partition p = partition::partition_with_fallback("darp", {}, s.request);
  PartitionCheck check;
  check.regions_connected = false;
  EXPECT_TRUE(valid_partition(s.request, p, check));
  // The right upright's top (x ≥ 16, y ≥ 5) is closer by flight to UAV 2 at (3, 6) than to UAV 1.
  for (int y = 5; y < 12; ++y) {
    for (int x = 16; x < 20; ++x) EXPECT_EQ(p.owner(x, y), 2) << x << "," << y;
  }
  for (int x = 4; x < 16; ++x) EXPECT_EQ(p.owner(x, 0), 0);
  EXPECT_TRUE(p.converged);
}

// Random walls that cut the default hull's flight space (a staircase from bottom to top, or from
// left to right), one or two of them, and random starts: every partition is flyable, valid and
// deterministic.
NoFlyMask random_walls(world::RandomStream& rs, int width, int height) {
  auto below = [&](int n) { return static_cast<int>(rs.below(static_cast<std::uint64_t>(n))); };
  NoFlyMask m(width, height, 0);
  const int walls = 1 + below(2);
  for (int w = 0; w < walls; ++w) {
    const bool vertical = below(3) != 0;
    const int along = vertical ? height : width;
    const int across = vertical ? width : height;
    int at = (vertical ? 20 : 5) + below(across - (vertical ? 40 : 10));
    for (int t = 0; t < along; ++t) {
      const int step = below(3) - 1;
      const int next = std::clamp(at + step, 1, across - 2);
      for (int a = std::min(at, next); a <= std::max(at, next); ++a) {
        if (vertical)
          m(a, t) = 1;
        else
          m(t, a) = 1;
      }
      at = next;
    }
  }
  return m;
}

std::vector<grid::Cell> random_starts(world::RandomStream& rs, const world::HullMask& hull,
                                      const NoFlyMask& no_fly, int n) {
  std::vector<grid::Cell> starts;
  while (static_cast<int>(starts.size()) < n) {
    const int i = hull.cells()[rs.below(hull.cells().size())];
    const grid::Cell c = hull.mask().cell(i);
    if (no_fly[c] || std::find(starts.begin(), starts.end(), c) != starts.end()) continue;
    starts.push_back(c);
  }
  return starts;
}

TEST(FlightSplit, RandomSplittingWallsAndStarts) {
  const auto& hull = world::default_hull();
  int split_spaces = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    world::RandomStream rs(seed, 7);
    const NoFlyMask m = random_walls(rs, hull.width(), hull.height());
    const int n = 2 + static_cast<int>(rs.below(5));
    const SplitRequest s = make_request(hull, m, random_starts(rs, hull, m, n));
    split_spaces += s.reach.flight_components > 1 ? 1 : 0;
    SCOPED_TRACE(
        fmt::format("seed {}: {} UAVs, {} flight components", seed, n, s.reach.flight_components));
    EXPECT_TRUE(seen_from_is_right(hull, s, 5, 7));
    const partition::Partition p = partition::partition_with_fallback("darp", {}, s.request);
    PartitionCheck check;
    check.regions_connected = false;  // a piece without a start may be given whole
    EXPECT_TRUE(valid_partition(s.request, p, check));
    EXPECT_EQ(partition::partition_with_fallback("darp", {}, s.request).owner, p.owner);
    const partition::Partition t = split(s.request, "transfer");
    EXPECT_TRUE(valid_partition(s.request, t, check));
  }
  EXPECT_GE(split_spaces, 6) << "the walls should mostly cut the flight space";
}

TEST(FlightSplit, WeightsAndSharesFollowTheirUavs) {
  const auto& hull = world::default_hull();
  SplitRequest s = make_request(hull, wall_at_100(), {{20, 15}, {180, 15}, {60, 15}, {150, 15}});
  s.request.shares = {1, 1, 3, 3};  // UAVs 2 and 3 take three times the share of 0 and 1
  const partition::Partition p = partition::partition_with_fallback("darp", {}, s.request);
  EXPECT_TRUE(valid_partition(s.request, p));
  EXPECT_NEAR(p.region_cells[2], 3 * p.region_cells[0], 4);
  EXPECT_NEAR(p.region_cells[3], 3 * p.region_cells[1], 4);
}

}  // namespace
}  // namespace hullinspect::testing
