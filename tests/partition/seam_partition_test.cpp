// Partitions on a grid that closes on itself (docs/hulls.md "Neighbours"): a row's two ends are
// neighbours across the seam, so a region may hold cells on both sides of it and still be one
// connected piece; the shared partition checker counts its pieces across the seam too.

#include <gtest/gtest.h>

#include <string>

#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/partition/fallback.hpp"
#include "hullinspect/partition/stripes_partitioner.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/standoff_surface.hpp"
#include "support/partition_checker.hpp"
#include "support/seam_hull.hpp"

namespace hullinspect {
namespace {

using partition::PartitionRequest;
using testing::valid_partition;

// 40 × 4 cells round a cylinder: column 0 and column 39 meet at the seam.
world::HullMask ring() {
  std::string rows;
  for (int y = 0; y < 4; ++y) rows += std::string(40, 'X') + "\n";
  return testing::seam_cylinder_hull(rows);
}

// The request a mission on `hull` makes: its neighbour flights (their lengths and the seam).
PartitionRequest mission_request(const world::HullMask& hull, std::vector<grid::Cell> starts) {
  world::MissionParams params;
  params.cell_size_m = hull.geometry()->cell_size;
  PartitionRequest r;
  r.hull = &hull;
  r.starts = std::move(starts);
  r.flights = world::neighbour_flights(hull, params).longer_plane();
  return r;
}

TEST(SeamPartition, DarpGivesTheCellsAcrossTheSeamToTheUavNextToIt) {
  const world::HullMask hull = ring();
  const PartitionRequest request = mission_request(hull, {{1, 1}, {20, 1}});
  ASSERT_TRUE(request.flights.seam_links(1));
  const partition::Partition p = partition::DarpPartitioner().partition(request);
  EXPECT_TRUE(valid_partition(request, p));
  EXPECT_TRUE(p.converged) << (p.warnings.empty() ? "" : p.warnings[0]);
  // UAV 0, a column east of the seam, holds the columns just west of it: its region crosses the
  // seam (two pieces in the grid's own plane, one across the seam).
  for (int y = 0; y < hull.height(); ++y) {
    EXPECT_EQ(p.owner(0, y), 0) << y;
    EXPECT_EQ(p.owner(39, y), 0) << y;
    EXPECT_EQ(p.owner(36, y), 0) << y;
  }
  EXPECT_EQ(p.region_cells[0], 80);
}

TEST(SeamPartition, TheCheckerCountsARegionAcrossTheSeamAsOnePiece) {
  const world::HullMask hull = ring();
  PartitionRequest request = mission_request(hull, {{1, 1}, {20, 1}});
  // Columns 30..39 and 0..9 to UAV 0, the rest to UAV 1.
  partition::Partition p;
  p.owner = grid::Grid<std::int16_t>(40, 4, 1);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 40; ++x) p.owner(x, y) = x < 10 || x >= 30 ? 0 : 1;
  }
  p.region_cells = {80, 80};
  p.region_weight = {80, 80};
  p.desired_weight = {80, 80};
  EXPECT_TRUE(valid_partition(request, p));
  request.flights = {};  // the same grid without its seam: region 0 is two pieces
  EXPECT_FALSE(valid_partition(request, p));
}

TEST(SeamPartition, EveryPartitionerWithTheFallbackRuleMakesConnectedRegions) {
  // Starts near both ends of the grid and in its middle, on a hull with a notch at the seam's
  // bottom row.
  std::string rows;
  for (int y = 0; y < 5; ++y) rows += std::string(40, 'X') + "\n";
  rows += "." + std::string(38, 'X') + ".\n";
  const world::HullMask hull = testing::seam_cylinder_hull(rows);
  const PartitionRequest request = mission_request(hull, {{38, 2}, {1, 4}, {15, 3}, {25, 0}});
  for (const auto& info : partition::partitioner_registry()) {
    SCOPED_TRACE(info.name);
    const partition::Partition p = partition::partition_with_fallback(info.name, {}, request);
    EXPECT_TRUE(valid_partition(request, p));
  }
}

}  // namespace
}  // namespace hullinspect
