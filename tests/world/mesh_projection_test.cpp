// Projection of synthetic meshes (docs/model.md "Hulls from meshes"): coverage, depth buffer,
// axes, waterline, min-coverage, connectivity and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::world {
namespace {

using Vec = std::array<double, 3>;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

/// Two triangles forming the quad a-b-c-d (counter-clockwise seen from outside).
void quad(std::vector<MeshTriangle>& out, Vec a, Vec b, Vec c, Vec d) {
  out.push_back(MeshTriangle{{a, b, c}});
  out.push_back(MeshTriangle{{a, c, d}});
}

/// A closed box [x0,x1] × [y0,y1] × [z0,z1] with outward winding.
std::vector<MeshTriangle> box(double x0, double x1, double y0, double y1, double z0, double z1) {
  return testing::box_mesh(x0, x1, y0, y1, z0, z1);
}

/// A starboard-facing rectangle at y over [x0,x1] × [z0,z1].
void starboard_panel(std::vector<MeshTriangle>& t, double y, double x0, double x1, double z0,
                     double z1) {
  quad(t, {x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1});
}

MeshImportOptions options(HullSide side = HullSide::starboard) {
  MeshImportOptions o;
  o.side = side;
  return o;
}

TEST(MeshProjection, BoxFillsItsSideExactly) {
  for (HullSide side : {HullSide::starboard, HullSide::port}) {
    const MeshImport r = project_mesh(box(2, 6, -1, 1, 0, 2), options(side), "box");
    const HullMask& h = r.hull;
    EXPECT_EQ(h.width(), 8);
    EXPECT_EQ(h.height(), 4);
    EXPECT_EQ(h.cell_count(), 32);
    EXPECT_EQ(r.facets, 12);
    EXPECT_EQ(r.facing_facets, 2);
    const HullGeometry& g = *h.geometry();
    EXPECT_DOUBLE_EQ(g.x0, 2);
    EXPECT_DOUBLE_EQ(g.z0, 0);
    EXPECT_DOUBLE_EQ(g.side_plane_y, side == HullSide::port ? 1 : -1);
    for (int i = 0; i < h.mask().size(); ++i) {
      EXPECT_NEAR(g.depth[i], 0.0f, 1e-9);
      EXPECT_EQ(g.coverage[i], 1.0f);
      EXPECT_EQ(g.normal[i], (Normal{0, side == HullSide::port ? 1.0f : -1.0f, 0}));
    }
  }
}

TEST(MeshProjection, WedgeDepthFollowsTheSlope) {
  // A starboard face leaning out as it rises: y = −1 − 0.5 z over z in [0, 2].
  std::vector<MeshTriangle> t;
  quad(t, {0, -1, 0}, {3, -1, 0}, {3, -2, 2}, {0, -2, 2});
  const MeshImport r = project_mesh(t, options(), "wedge");
  const HullGeometry& g = *r.hull.geometry();
  EXPECT_DOUBLE_EQ(g.side_plane_y, -1.125);  // the innermost centre sample: row 0 at z = 0.25
  for (int y = 0; y < r.hull.height(); ++y) {
    const double expected = 0.5 * g.centre_z(y) - 0.125;
    for (int x = 0; x < r.hull.width(); ++x) {
      EXPECT_NEAR(g.depth(x, y), expected, 1e-6) << x << "," << y;
      EXPECT_NEAR(g.surface_y(x, y), -1 - 0.5 * g.centre_z(y), 1e-6);
      const Normal n = g.normal(x, y);
      EXPECT_NEAR(n.y, -2 / std::sqrt(5.0), 1e-6);
      EXPECT_NEAR(n.z, -1 / std::sqrt(5.0), 1e-6);
      EXPECT_NEAR(n.x, 0, 1e-6);
    }
  }
}

TEST(MeshProjection, NearestSurfaceWins) {
  // Two starboard panels overlapping over x in [1, 2]; the one further out (y = −3) wins there.
  std::vector<MeshTriangle> t;
  starboard_panel(t, -1, 0, 2, 0, 1);
  starboard_panel(t, -3, 1, 3, 0, 1);
  const MeshImport r = project_mesh(t, options(), "two");
  const HullGeometry& g = *r.hull.geometry();
  EXPECT_EQ(r.hull.width(), 6);
  EXPECT_DOUBLE_EQ(g.side_plane_y, -1);
  for (int x = 0; x < 6; ++x) {
    EXPECT_FLOAT_EQ(g.depth(x, 0), x < 2 ? 0.0f : 2.0f) << x;
    EXPECT_DOUBLE_EQ(g.surface_y(x, 1), x < 2 ? -1.0 : -3.0) << x;
  }
  // Seen from port, the same panels face away: nothing to project.
  EXPECT_EQ(error_of([&] { project_mesh(t, options(HullSide::port), "two"); }),
            "two: no facet faces the port side (check --axes and --side)");
}

/// The file-frame triangles that `axes` maps onto the ship-frame `ship` (outward winding in the
/// file, as a real mesh has it).
std::vector<MeshTriangle> to_file(const std::vector<MeshTriangle>& ship, const AxisMap& axes,
                                  double scale) {
  std::vector<MeshTriangle> out;
  for (const MeshTriangle& t : ship) {
    MeshTriangle f;
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t i = 0; i < 3; ++i) {
        f.v[k][static_cast<std::size_t>(axes.axis[i])] = t.v[k][i] / (axes.sign[i] * scale);
      }
    }
    if (axes.determinant() < 0) std::swap(f.v[1], f.v[2]);
    out.push_back(f);
  }
  return out;
}

TEST(MeshProjection, AxesAndScaleMapTheFileToTheShipFrame) {
  std::vector<MeshTriangle> ship = box(0, 5, -2, 2, 0, 3);
  quad(ship, {1, -2.5, 1}, {2, -2.5, 1}, {2, -2.5, 2}, {1, -2.5, 2});  // a plate standing out
  const MeshImport reference = project_mesh(ship, options(), "ship");
  for (const char* text : {"x,-z,y", "y,x,z", "-x,y,z", "z,-x,-y", "-y,-z,x"}) {
    MeshImportOptions o = options();
    o.axes = AxisMap::parse(text);
    o.scale = 2;
    const MeshImport r = project_mesh(to_file(ship, o.axes, o.scale), o, "ship");
    EXPECT_EQ(r.hull.mask(), reference.hull.mask()) << text;
    const HullGeometry& a = *reference.hull.geometry();
    const HullGeometry& b = *r.hull.geometry();
    EXPECT_NEAR(b.x0, a.x0, 1e-9) << text;
    EXPECT_NEAR(b.side_plane_y, a.side_plane_y, 1e-9) << text;
    for (int i = 0; i < a.depth.size(); ++i) {
      EXPECT_NEAR(b.depth[i], a.depth[i], 1e-5) << text;
      EXPECT_EQ(b.normal[i], a.normal[i]) << text;
    }
  }
}

TEST(MeshProjection, WaterlineCutsTheGrid) {
  MeshImportOptions o = options();
  o.waterline = 0.5;
  const MeshImport r = project_mesh(box(0, 2, -1, 1, 0, 2), o, "box");
  EXPECT_EQ(r.hull.height(), 3);
  EXPECT_EQ(r.hull.cell_count(), 12);
  EXPECT_DOUBLE_EQ(r.hull.geometry()->z0, 0.5);
  EXPECT_EQ(r.hull.geometry()->waterline, 0.5);
  o.waterline = 2.5;
  EXPECT_EQ(error_of([&] { project_mesh(box(0, 2, -1, 1, 0, 2), o, "box"); }),
            "box: no facet faces the starboard side above the waterline (check --axes and --side)");
}

TEST(MeshProjection, MinCoverageDecidesPartialCells) {
  // x in [0, 1.1]: the third column is 1/7 covered (1 of 7 sample columns).
  std::vector<MeshTriangle> t;
  starboard_panel(t, 0, 0, 1.1, 0, 1);
  MeshImportOptions o = options();
  const MeshImport half = project_mesh(t, o, "p");
  EXPECT_EQ(half.hull.width(), 3);
  EXPECT_EQ(half.hull.cell_count(), 4);
  EXPECT_NEAR(half.hull.geometry()->coverage(2, 0), 1.0 / 7, 1e-6);
  o.min_coverage = 0.1;
  EXPECT_EQ(project_mesh(t, o, "p").hull.cell_count(), 6);
  o.min_coverage = 0;
  EXPECT_EQ(error_of([&] { project_mesh(t, o, "p"); }),
            "min-coverage: expected a fraction in (0, 1]");
  // A sliver thinner than half a cell everywhere is no hull at all.
  std::vector<MeshTriangle> sliver;
  starboard_panel(sliver, 0, 0, 3, 0, 0.2);
  EXPECT_EQ(error_of([&] { project_mesh(sliver, options(), "s"); }),
            "s: no cell is at least 0.5 covered (check --min-coverage and --cell-size)");
}

TEST(MeshProjection, SeparatePartsAreAnErrorOrTheLargestIsKept) {
  std::vector<MeshTriangle> t;
  starboard_panel(t, 0, 0, 2, 0, 1);
  starboard_panel(t, 0, 3, 3.5, 0, 1);
  EXPECT_EQ(error_of([&] { project_mesh(t, options(), "parts.stl"); }),
            "parts.stl: the projection is not 4-connected: 2 components (8 cells from (0, 0); 2 "
            "cells from (6, 0)); use --keep-largest to keep the largest");
  MeshImportOptions o = options();
  o.keep_largest = true;
  const MeshImport r = project_mesh(t, o, "parts.stl");
  EXPECT_EQ(r.hull.cell_count(), 8);
  EXPECT_FALSE(r.hull.is_hull(6, 0));
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0],
            "parts.stl: the projection is not 4-connected: 2 components (8 cells from (0, 0); 2 "
            "cells from (6, 0)); kept the largest");
}

TEST(MeshProjection, BadOptionsAndGrids) {
  MeshImportOptions o = options();
  o.cell_size = 0.001;
  EXPECT_EQ(error_of([&] { project_mesh(box(0, 5, -1, 1, 0, 1), o, "b"); }),
            "b: the projection is 5000 × 1000 cells of 0.001 m; each side must be within 1..4096 "
            "(check --scale and --cell-size)");
  o = options();
  o.scale = -1;
  EXPECT_EQ(error_of([&] { project_mesh(box(0, 5, -1, 1, 0, 1), o, "b"); }),
            "scale: expected a number > 0");
  std::vector<MeshTriangle> t = box(0, 1, 0, 1, 0, 1);
  t[0].v[0][0] = std::nan("");
  EXPECT_EQ(error_of([&] { project_mesh(t, options(), "b"); }),
            "b: a vertex is not a finite number");
}

}  // namespace
}  // namespace hullinspect::world
