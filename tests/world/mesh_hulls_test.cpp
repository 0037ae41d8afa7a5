// Real-shaped hulls: a Wigley hull against its analytic surface, and the DTC when installed.
#include <gtest/gtest.h>

#include <cmath>

#include "hullinspect/world/mesh_hull.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::world {
namespace {

using testing::WigleyHull;

double mask_area(const HullMask& h) {
  const double c = h.geometry()->cell_size;
  return h.cell_count() * c * c;
}

struct WigleyCase {
  WigleyHull hull;
  double cell;
};

class WigleyImport : public ::testing::TestWithParam<WigleyCase> {};

TEST_P(WigleyImport, AreaDepthAndNormalsMatchTheAnalyticHull) {
  const WigleyCase c = GetParam();
  const WigleyHull& w = c.hull;
  MeshImportOptions o;
  o.cell_size = c.cell;
  const HullMask h = import_mesh_file(testing::wigley_stl(w), o).hull;
  const HullGeometry& g = *h.geometry();
  // The side projection of a Wigley hull is the rectangle L × T. The mask differs from it by the
  // edge cells (at most half a cell per edge); the cases keep that under 1 %.
  const double analytic = w.length * w.draft;
  EXPECT_NEAR(mask_area(h), analytic, 0.01 * analytic);
  EXPECT_NEAR(g.x0, -w.length / 2, 1e-4);  // binary STL holds floats
  EXPECT_NEAR(g.z0, -w.draft, 1e-4);
  int checked = 0;
  for (int i : h.cells()) {
    const grid::Cell cell = h.mask().cell(i);
    const double x = g.centre_x(cell.x), z = g.centre_z(cell.y);
    if (z > 0) continue;  // the top row's centre may sit above the deck
    // Starboard: the surface is y = −f(x, z), f the half-breadth.
    EXPECT_NEAR(g.surface_y(cell.x, cell.y), -testing::wigley_half_breadth(w, x, z), 0.01)
        << cell.x << "," << cell.y;
    // Outward normal ∝ −(∂f/∂x, 1, ∂f/∂z).
    const double u = 2 * x / w.length, v = z / w.draft;
    const double fx = 0.5 * w.beam * (-2 * u * 2 / w.length) * (1 - v * v);
    const double fz = 0.5 * w.beam * (1 - u * u) * (-2 * v / w.draft);
    const double len = std::sqrt(fx * fx + 1 + fz * fz);
    const Normal n = g.normal[i];
    const double dot = -(n.x * fx + n.y + n.z * fz) / len;
    EXPECT_GT(dot, 0.999) << cell.x << "," << cell.y;
    EXPECT_GE(g.depth[i], 0.0f);
    ++checked;
  }
  EXPECT_GT(checked, h.cell_count() * 9 / 10);
}

INSTANTIATE_TEST_SUITE_P(
    Hulls, WigleyImport,
    ::testing::Values(WigleyCase{WigleyHull{}, 0.5},  // grid-aligned: 200 × 16 cells
                      WigleyCase{WigleyHull{101.3, 12, 8.3, 150, 30, true}, 0.25},
                      WigleyCase{WigleyHull{60.2, 8, 6.02, 120, 30, false}, 0.3}));

TEST(WigleyImport, PortSideMirrorsStarboard) {
  const auto stl = testing::wigley_stl(WigleyHull{});
  MeshImportOptions port;
  port.side = HullSide::port;
  const HullMask s = import_mesh_file(stl, {}).hull;
  const HullMask p = import_mesh_file(stl, port).hull;
  EXPECT_EQ(p.mask(), s.mask());
  EXPECT_NEAR(p.geometry()->side_plane_y, -s.geometry()->side_plane_y, 1e-6);
  for (int i : s.cells()) EXPECT_NEAR(p.geometry()->depth[i], s.geometry()->depth[i], 1e-4);
}

TEST(DtcImport, TheInstalledContainerShipAtFullScale) {
  std::string why;
  if (!testing::installed_dtc(why)) GTEST_SKIP() << why;
  const HullMask h = load_hull("dtc");
  const HullGeometry& g = *h.geometry();
  EXPECT_EQ(h.source(), "dtc");
  // 1:59.4 model: about 373 m long overall and 34 m from keel to deck at full scale.
  EXPECT_EQ(h.width(), 746);
  EXPECT_EQ(h.height(), 68);
  EXPECT_NEAR(g.x0, -0.113504 * 59.4, 1e-3);
  EXPECT_NEAR(g.z0, 0, 1e-6);
  // The half-breadth is B/2 ≈ 25.5 m amidships, so depth reaches about that from the centre plane.
  float deepest = 0;
  for (int i : h.cells()) deepest = std::max(deepest, g.depth[i]);
  EXPECT_NEAR(deepest, 0.429252 * 59.4, 0.05);
  EXPECT_NEAR(g.side_plane_y, 0, 0.5);
  // Amidships at mid-height the side is flat and vertical: normal ≈ (0, −1, 0).
  const Normal mid = g.normal(h.width() / 2, h.height() / 2);
  EXPECT_LT(mid.y, -0.99f);
  EXPECT_TRUE(h.is_hull(h.width() / 2, 0));
}

}  // namespace
}  // namespace hullinspect::world
