// Local maps of Part-TSP: M^k holds R_k only, takes UAV k's readings only, and reports detections
// and inspections as UAV k saw them.

#include <gtest/gtest.h>

#include <vector>

#include "hullinspect/planners/part_tsp_local_map.hpp"

namespace hullinspect::planners::part_tsp {
namespace {

// 6 × 4 grid: columns 0–2 belong to UAV 0, 3–5 to UAV 1, cell (5, 3) is not hull.
grid::Grid<std::int16_t> two_regions() {
  grid::Grid<std::int16_t> owner(6, 4, 0);
  for (int y = 0; y < 4; ++y)
    for (int x = 3; x < 6; ++x) owner(x, y) = 1;
  owner(5, 3) = -1;
  return owner;
}

grid::Grid<std::int8_t> prior_with(std::vector<grid::Cell> ones) {
  grid::Grid<std::int8_t> prior(6, 4, 0);
  prior(5, 3) = -1;
  for (auto c : ones) prior[c] = 1;
  return prior;
}

sim::Reading reading(const grid::Grid<std::int16_t>& g, int x, int y, std::int8_t value) {
  return sim::Reading{g.index(x, y), value, 0};
}

TEST(PartTspLocalMaps, StartsFromThePriorOnlyWhenAskedTo) {
  const auto owner = two_regions();
  const auto prior = prior_with({{1, 1}, {4, 2}, {4, 3}});
  LocalMaps with(owner, prior, true, 2, 3, 5);
  EXPECT_EQ(with.corrosion_to_inspect(0), 1);
  EXPECT_EQ(with.corrosion_to_inspect(1), 2);
  EXPECT_EQ(with.unknown_cells(0), 11);
  EXPECT_EQ(with.unknown_cells(1), 9);
  EXPECT_EQ(with.value(owner.index(4, 2)), sim::kCorrosionSeen);
  EXPECT_EQ(with.value(owner.index(5, 3)), sim::kNotHull);
  LocalMaps without(owner, prior, false, 2, 3, 5);
  EXPECT_EQ(without.corrosion_to_inspect(0), 0);
  EXPECT_EQ(without.corrosion_to_inspect(1), 0);
  EXPECT_EQ(without.unknown_cells(0), 12);
  EXPECT_EQ(without.unknown_cells(1), 11);
  EXPECT_EQ(with.x_begin(1), 3);
  EXPECT_EQ(with.x_end(1), 6);
}

TEST(PartTspLocalMaps, IgnoresReadingsOfOtherRegions) {
  const auto owner = two_regions();
  LocalMaps maps(owner, prior_with({}), false, 2, 3, 5);
  // UAV 0 sees cells of region 1: M^1 must not change (no communication), nor M^0.
  const std::vector<sim::Reading> r = {reading(owner, 3, 0, sim::kClean),
                                       reading(owner, 4, 0, sim::kCorrosionSeen)};
  const auto events = maps.ingest(0, r);
  EXPECT_FALSE(events.detection);
  EXPECT_EQ(maps.value(owner.index(3, 0)), sim::kUnknown);
  EXPECT_EQ(maps.value(owner.index(4, 0)), sim::kUnknown);
  EXPECT_EQ(maps.unknown_cells(1), 11);
  // The same readings from UAV 1 count.
  EXPECT_TRUE(maps.ingest(1, r).detection);
  EXPECT_EQ(maps.value(owner.index(3, 0)), sim::kClean);
  EXPECT_EQ(maps.corrosion_to_inspect(1), 1);
  EXPECT_EQ(maps.unknown_cells(1), 9);
}

TEST(PartTspLocalMaps, DetectionIsTheFirstSightFromZ2EvenOfAPriorCell) {
  const auto owner = two_regions();
  LocalMaps maps(owner, prior_with({{1, 1}}), true, 2, 3, 5);
  const std::vector<sim::Reading> seen = {reading(owner, 1, 1, sim::kCorrosionSeen)};
  EXPECT_TRUE(maps.ingest(0, seen).detection);   // already 2 from the prior: still a detection
  EXPECT_FALSE(maps.ingest(0, seen).detection);  // second sight: not
  EXPECT_EQ(maps.corrosion_to_inspect(0), 1);
  const std::vector<sim::Reading> close = {reading(owner, 1, 1, sim::kInspected)};
  const auto inspected = maps.ingest(0, close);
  EXPECT_TRUE(inspected.inspection);
  EXPECT_FALSE(inspected.detection);
  EXPECT_EQ(maps.corrosion_to_inspect(0), 0);
  EXPECT_FALSE(maps.ingest(0, close).inspection);  // already 3
  // Seen again from z = 2 after the inspection: stays 3.
  maps.ingest(0, seen);
  EXPECT_EQ(maps.value(owner.index(1, 1)), sim::kInspected);
  EXPECT_EQ(maps.corrosion_to_inspect(0), 0);
}

TEST(PartTspLocalMaps, FalsePositivePriorCellIsClearedAndUnknownCorrosionInspectedDirectly) {
  const auto owner = two_regions();
  LocalMaps maps(owner, prior_with({{0, 0}}), true, 2, 3, 5);
  const std::vector<sim::Reading> r = {reading(owner, 0, 0, sim::kClean),
                                       reading(owner, 2, 3, sim::kInspected)};
  const auto events = maps.ingest(0, r);
  EXPECT_TRUE(events.inspection);  // 0 → 3 at z = 1 is an inspection
  EXPECT_FALSE(events.detection);
  EXPECT_EQ(maps.corrosion_to_inspect(0), 0);
  EXPECT_EQ(maps.unknown_cells(0), 10);
}

TEST(PartTspLocalMaps, ColumnCountsFollowTheStripLayoutOfEachPlane) {
  const auto owner = two_regions();  // b = 4: s1 = 3 → strips {0,1,2}, {3}; s2 = 5 → {0..3}
  LocalMaps maps(owner, prior_with({{4, 3}}), true, 2, 3, 5);
  EXPECT_EQ(maps.layout(1).strips(), 2);
  EXPECT_EQ(maps.layout(1).flight_row(0), 1);
  EXPECT_EQ(maps.layout(1).flight_row(1), 3);  // min(3 + 1, b − 1)
  EXPECT_EQ(maps.layout(2).strips(), 1);
  EXPECT_EQ(maps.layout(2).flight_row(0), 2);
  EXPECT_EQ(maps.column_count(1, 1, sim::kCorrosionSeen, 1, 4), 1);
  EXPECT_EQ(maps.column_count(1, 1, sim::kUnknown, 1, 4), 0);
  EXPECT_EQ(maps.column_count(1, 1, sim::kUnknown, 0, 4), 3);
  EXPECT_EQ(maps.column_count(1, 2, sim::kUnknown, 0, 4), 3);
  EXPECT_EQ(maps.column_count(1, 2, sim::kCorrosionSeen, 0, 4), 1);
  EXPECT_EQ(maps.column_cells(1, 2, 0, 5), 3);  // (5, 3) is not hull
  EXPECT_EQ(maps.column_cells(0, 2, 0, 4), 0);  // not in region 0
  const std::vector<sim::Reading> r = {reading(owner, 4, 3, sim::kInspected),
                                       reading(owner, 4, 0, sim::kClean)};
  maps.ingest(1, r);
  EXPECT_EQ(maps.column_count(1, 1, sim::kCorrosionSeen, 1, 4), 0);
  EXPECT_EQ(maps.column_count(1, 2, sim::kUnknown, 0, 4), 2);
}

}  // namespace
}  // namespace hullinspect::planners::part_tsp
