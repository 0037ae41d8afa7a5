// No-fly reachability on a grid that closes on itself (docs/model.md §8, docs/hulls.md
// "Neighbours"): a position walled off in the grid's own plane but reachable across the seam is
// flyable, and the flight components join across it.

#include <gtest/gtest.h>

#include <string>

#include "hullinspect/world/no_fly.hpp"
#include "support/seam_hull.hpp"

namespace hullinspect::world {
namespace {

// 30 × 6 cells round a cylinder, with a no-fly wall over column 15 from the bottom to the top.
struct WalledRing {
  HullMask hull = testing::seam_cylinder_hull([] {
    std::string rows;
    for (int y = 0; y < 6; ++y) rows += std::string(30, 'X') + "\n";
    return rows;
  }());
  NoFlyMask wall = [] {
    NoFlyMask m(30, 6, 0);
    for (int y = 0; y < 6; ++y) m(15, y) = 1;
    return m;
  }();
};

TEST(SeamReach, APositionBehindAWallIsReachedAcrossTheSeam) {
  const WalledRing r;
  const std::vector<grid::Cell> starts = {{3, 2}};
  const Reachability reach = compute_reachability(r.hull, &r.wall, 3, 7, starts);
  for (int x = 0; x < 30; ++x) {
    EXPECT_EQ(reach.flyable(x, 2), x == 15 ? 0 : 1) << x;
  }
  // Every hull cell, the wall's included, lies in some flyable footprint.
  EXPECT_EQ(reach.unreachable_z1, 0);
  EXPECT_EQ(reach.unreachable_z2, 0);
  EXPECT_EQ(reach.flight_components, 1);
  EXPECT_EQ(reach.flight_component(20, 2), 0);
  EXPECT_EQ(reach.seen_from(20, 2), 0);
}

TEST(SeamReach, StartsEitherSideOfTheWallShareOneFlightComponent) {
  const WalledRing r;
  const std::vector<grid::Cell> starts = {{3, 2}, {25, 4}};
  const Reachability reach = compute_reachability(r.hull, &r.wall, 3, 7, starts);
  EXPECT_EQ(reach.flight_components, 1);
  EXPECT_EQ(reach.flight_component(25, 4), reach.flight_component(3, 2));
  // The same wall on the grid without its seam splits the flight space in two.
  HullMask open = r.hull;
  HullGeometry g = *open.geometry();
  g.seam = false;
  open.attach_geometry(std::move(g));
  const Reachability split = compute_reachability(open, &r.wall, 3, 7, starts);
  EXPECT_EQ(split.flight_components, 2);
}

}  // namespace
}  // namespace hullinspect::world
