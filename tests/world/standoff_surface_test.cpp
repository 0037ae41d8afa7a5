// Where a UAV stands off from an unrolled hull at every grid position: its own surface point where
// the cell has surface, else the nearest surface point of its column at the position's own height.
#include <gtest/gtest.h>

#include <cmath>

#include "hullinspect/world/mesh_hull.hpp"
#include "hullinspect/world/standoff_surface.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::world {
namespace {

TEST(StandoffSurface, CellsKeepTheirSurfaceAndTheRestBorrowTheirColumns) {
  MeshImportOptions o;
  o.side = HullSide::both;
  o.cell_size = 1.0;
  // The Wigley hull narrows toward the keel, so the lower cuts are shorter than the deck's and
  // the grid's ends have positions without surface.
  const MeshImport imported = import_mesh_file(testing::wigley_stl(testing::WigleyHull{}), o);
  const HullGeometry& g = *imported.hull.geometry();
  const StandoffSurface s = standoff_surface(g);
  ASSERT_EQ(s.point.width(), g.width());
  ASSERT_EQ(s.point.height(), g.height());
  int borrowed = 0;
  for (int x = 0; x < g.width(); ++x) {
    for (int y = 0; y < g.height(); ++y) {
      const Normal n = s.normal(x, y);
      EXPECT_NEAR(std::hypot(n.x, n.y, n.z), 1.0, 1e-5) << x << ", " << y;
      if (g.coverage(x, y) > 0) {
        EXPECT_EQ(s.point(x, y), g.surface(x, y)) << x << ", " << y;
        EXPECT_EQ(n, g.normal(x, y)) << x << ", " << y;
        continue;
      }
      ++borrowed;
      EXPECT_FLOAT_EQ(s.point(x, y).z, static_cast<float>(g.centre_z(y))) << x << ", " << y;
      // The nearest row of the column with surface lends its X, Y and normal.
      int nearest = -1;
      for (int d = 1; d < g.height() && nearest < 0; ++d) {
        if (y - d >= 0 && g.coverage(x, y - d) > 0)
          nearest = y - d;
        else if (y + d < g.height() && g.coverage(x, y + d) > 0)
          nearest = y + d;
      }
      if (nearest < 0) continue;
      EXPECT_EQ(s.point(x, y).x, g.surface(x, nearest).x) << x << ", " << y;
      EXPECT_EQ(s.point(x, y).y, g.surface(x, nearest).y) << x << ", " << y;
      EXPECT_EQ(n, g.normal(x, nearest)) << x << ", " << y;
    }
  }
  EXPECT_GT(borrowed, 0) << "no position without surface: the test proves nothing";
}

TEST(StandoffSurface, OneSideHullsHaveNone) {
  MeshImportOptions o;
  o.cell_size = 1.0;
  const MeshImport imported = import_mesh_file(testing::wigley_stl(testing::WigleyHull{}), o);
  EXPECT_EQ(standoff_surface(*imported.hull.geometry()).point.size(), 0);
}

}  // namespace
}  // namespace hullinspect::world
