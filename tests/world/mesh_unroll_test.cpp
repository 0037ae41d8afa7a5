// The unrolled hull (--sides both): a box whose unrolled grid is known exactly, a closed Wigley
// hull against its analytic surface area, neighbourhoods, defects on the unrolled grid, the JSON
// round trip and the meshes it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/defect_map.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::world {
namespace {

std::vector<MeshTriangle> box(double x0, double x1, double y0, double y1, double z0, double z1) {
  return testing::box_mesh(x0, x1, y0, y1, z0, z1);
}

MeshImportOptions both(double cell = 0.5) {
  MeshImportOptions o;
  o.side = HullSide::both;
  o.cell_size = cell;
  return o;
}

std::string error_of(const std::vector<MeshTriangle>& t, const MeshImportOptions& o) {
  try {
    project_mesh(t, o, "hull.stl");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

std::vector<MeshTriangle> wigley_triangles(const testing::WigleyHull& w) {
  const auto path = testing::wigley_stl(w);
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  return read_mesh(bytes, "stl", path.string());
}

TEST(MeshUnroll, BoxUnrollsPortBowStarboardWithoutTheTransom) {
  // 20 m long, 4 m wide, 3 m high: port 20 m + half the bow 2 m, the same to starboard.
  const MeshImport m = project_mesh(box(0, 20, -2, 2, 0, 3), both(), "box");
  const HullMask& h = m.hull;
  const HullGeometry& g = *h.geometry();
  ASSERT_TRUE(g.unrolled());
  EXPECT_EQ(h.width(), 88);
  EXPECT_EQ(h.height(), 6);
  EXPECT_EQ(h.cell_count(), 88 * 6);
  EXPECT_DOUBLE_EQ(g.x0, -22.0);  // the bow is the edge between columns 43 and 44
  EXPECT_NEAR(m.surface_area, 2 * 22 * 3, 1e-6);
  EXPECT_NEAR(m.worst_area_error, 0, 1e-9);
  // Column 0 is at the stern on port, column 87 at the stern on starboard.
  EXPECT_NEAR(g.surface(0, 0).x, 0.25, 1e-5);
  EXPECT_NEAR(g.surface(0, 0).y, 2, 1e-5);
  EXPECT_NEAR(g.surface(87, 0).x, 0.25, 1e-5);
  EXPECT_NEAR(g.surface(87, 0).y, -2, 1e-5);
  EXPECT_NEAR(g.surface(43, 5).x, 20, 1e-5);  // on the bow, port of the centre line
  EXPECT_NEAR(g.surface(43, 5).y, 0.25, 1e-5);
  EXPECT_NEAR(g.surface(43, 5).z, 2.75, 1e-5);
  EXPECT_NEAR(g.normal(43, 5).x, 1, 1e-6);
  EXPECT_NEAR(g.normal(10, 2).y, 1, 1e-6);   // port faces +y
  EXPECT_NEAR(g.normal(70, 2).y, -1, 1e-6);  // starboard faces −y
}

TEST(MeshUnroll, TheTransomClosesTheGridAroundTheStern) {
  MeshImportOptions o = both();
  o.include_transom = true;
  const MeshImport m = project_mesh(box(0, 20, -2, 2, 0, 3), o, "box");
  EXPECT_EQ(m.hull.width(), 96);  // the whole 48 m girth
  EXPECT_NEAR(m.surface_area, 48 * 3, 1e-6);
  // The seam: both ends of the grid are on the transom, either side of the centre line.
  const HullGeometry& g = *m.hull.geometry();
  EXPECT_NEAR(g.surface(0, 0).x, 0, 1e-5);
  EXPECT_NEAR(g.surface(0, 0).y, 0.25, 1e-5);
  EXPECT_NEAR(g.surface(95, 0).y, -0.25, 1e-5);
  EXPECT_NEAR(g.normal(0, 0).x, -1, 1e-6);
  // Closed on itself: the hull records that its two ends are neighbours across the seam, and
  // its file keeps it.
  EXPECT_TRUE(g.seam);
  EXPECT_FALSE(project_mesh(box(0, 20, -2, 2, 0, 3), both(), "box").hull.geometry()->seam);
  EXPECT_TRUE(parse_hull_json(to_hull_json(m.hull), "box.json").geometry()->seam);
}

TEST(MeshUnroll, TheSeamFieldIsOptionalAndOnlyForAClosedUnrolledHull) {
  MeshImportOptions o = both();
  o.include_transom = true;
  const std::string text = to_hull_json(project_mesh(box(0, 20, -2, 2, 0, 3), o, "box").hull);
  // A hull file without the field: not linked.
  auto doc = nlohmann::json::parse(text);
  doc.erase("seam");
  EXPECT_FALSE(parse_hull_json(doc.dump(), "old.json").geometry()->seam);
  doc["seam"] = "yes";
  EXPECT_THROW(
      {
        try {
          parse_hull_json(doc.dump(), "bad.json");
        } catch (const InputError& e) {
          EXPECT_STREQ(e.what(), "bad.json: seam: expected true or false");
          throw;
        }
      },
      InputError);
  // A side's hull has no seam to link.
  MeshImportOptions side;
  side.cell_size = 0.5;
  auto one_side =
      nlohmann::json::parse(to_hull_json(project_mesh(box(0, 20, -2, 2, 0, 3), side, "box").hull));
  one_side["seam"] = true;
  try {
    parse_hull_json(one_side.dump(), "side.json");
    ADD_FAILURE() << "accepted a seam on one side's hull";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "side.json: seam: is only for an unrolled hull (side both)");
  }
}

TEST(MeshUnroll, WigleyHullKeepsItsAnalyticSurfaceArea) {
  const testing::WigleyHull w;  // 100 m × 10 m × 8 m, closed by a deck
  const MeshImport m = project_mesh(wigley_triangles(w), both(), "wigley");
  // Both sides: 2 ∫∫ √(1 + f_x² + f_z²) dx dz over [−L/2, L/2] × [−T, 0].
  double analytic = 0;
  const int nx = 2000, nz = 800;
  const double dx = w.length / nx, dz = w.draft / nz;
  for (int i = 0; i < nx; ++i) {
    for (int k = 0; k < nz; ++k) {
      const double u = 2 * (-w.length / 2 + (i + 0.5) * dx) / w.length;
      const double v = (-w.draft + (k + 0.5) * dz) / w.draft;
      const double fx = 0.5 * w.beam * (-4 * u / w.length) * (1 - v * v);
      const double fz = 0.5 * w.beam * (1 - u * u) * (-2 * v / w.draft);
      analytic += 2 * std::sqrt(1 + fx * fx + fz * fz) * dx * dz;
    }
  }
  EXPECT_NEAR(m.surface_area, analytic, 0.02 * analytic);
  // At 2 m cells a cut passes exactly through a row of the mesh's vertices (z = −7 m): the pieces
  // there have no length and still chain into one outline.
  const MeshImport coarse = project_mesh(wigley_triangles(w), both(2.0), "wigley");
  EXPECT_NEAR(coarse.surface_area, analytic, 0.02 * analytic);
  // Rows are heights, so the grid holds the side's projection on arc length × z: the slope toward
  // the keel is the cell-area error, reported rather than hidden.
  const double c = 0.5;
  EXPECT_NEAR(m.hull.cell_count() * c * c * (1 + m.mean_area_error), analytic, 0.02 * analytic);
  EXPECT_GT(m.worst_area_error, 0.3);
  // Every surface point is on the analytic hull, port left of the bow and starboard right.
  const HullGeometry& g = *m.hull.geometry();
  for (int i : m.hull.cells()) {
    const grid::Cell cell = m.hull.mask().cell(i);
    const Point3 p = g.surface[i];
    const double f = testing::wigley_half_breadth(w, p.x, p.z);
    EXPECT_NEAR(std::abs(p.y), f, 0.02) << cell.x << "," << cell.y;
    if (f > 0.05) {
      EXPECT_EQ(p.y > 0, g.centre_x(cell.x) < 0) << cell.x << "," << cell.y;
    }
  }
}

TEST(MeshUnroll, FourNeighboursAreNeighboursOnTheSurface) {
  // Columns are arc lengths along the same cut, so a row's neighbours are at most a cell apart on
  // the surface (a chord is never longer than its arc); a column's neighbours are a cell apart in
  // height and move along the surface only as far as its slope. Nothing joins the two sterns.
  const testing::WigleyHull w;
  const MeshImport m = project_mesh(wigley_triangles(w), both(), "wigley");
  const HullMask& h = m.hull;
  const HullGeometry& g = *h.geometry();
  const double c = g.cell_size;
  const auto distance = [&](int x0, int y0, int x1, int y1) {
    const Point3 a = g.surface(x0, y0), b = g.surface(x1, y1);
    return std::sqrt(double(a.x - b.x) * (a.x - b.x) + double(a.y - b.y) * (a.y - b.y) +
                     double(a.z - b.z) * (a.z - b.z));
  };
  int pairs = 0;
  for (int y = 0; y < h.height(); ++y) {
    for (int x = 0; x < h.width(); ++x) {
      if (!h.is_hull(x, y)) continue;
      if (x + 1 < h.width() && h.is_hull(x + 1, y)) {
        const double d = distance(x, y, x + 1, y);
        EXPECT_LE(d, c + 1e-4) << x << "," << y;
        // A partly covered cell keeps the point of its sample nearest the centre, not the centre;
        // across the stem the chord is shorter than the arc (the two sides meet at an angle).
        const bool across_bow = g.centre_x(x) < 0 && g.centre_x(x + 1) > 0;
        if (across_bow) {
          EXPECT_GT(g.surface(x, y).y, 0.0f);
          EXPECT_LT(g.surface(x + 1, y).y, 0.0f);
        } else if (g.coverage(x, y) == 1 && g.coverage(x + 1, y) == 1) {
          EXPECT_GE(d, 0.9 * c) << x << "," << y;
        }
        ++pairs;
      }
      if (y + 1 < h.height() && h.is_hull(x, y + 1)) {
        const double d = distance(x, y, x, y + 1);
        if (g.coverage(x, y) == 1 && g.coverage(x, y + 1) == 1) {
          EXPECT_GE(d, c - 1e-4) << x << "," << y;
        }
        EXPECT_LE(d, c * (1 + m.worst_area_error) + 1e-3) << x << "," << y;
        ++pairs;
      }
    }
  }
  EXPECT_GT(pairs, 2 * h.cell_count() * 9 / 10);
  // The two ends of the grid are the two sides of the stern, a whole girth apart on the grid.
  EXPECT_NEAR(g.surface(0, h.height() - 1).x, -w.length / 2, c);
  EXPECT_NEAR(g.surface(h.width() - 1, h.height() - 1).x, -w.length / 2, c);
}

TEST(MeshUnroll, HullJsonRoundTripsTheSurfacePoints) {
  const HullMask h = project_mesh(box(0, 20, -2, 2, 0, 3), both(), "box").hull;
  const HullMask back = parse_hull_json(to_hull_json(h), "box.json");
  const HullGeometry& a = *h.geometry();
  const HullGeometry& b = *back.geometry();
  ASSERT_TRUE(b.unrolled());
  ASSERT_EQ(b.surface.width(), a.surface.width());
  for (int i = 0; i < a.surface.size(); ++i) {
    EXPECT_NEAR(a.surface[i].x, b.surface[i].x, 1e-4);
    EXPECT_NEAR(a.surface[i].y, b.surface[i].y, 1e-4);
    EXPECT_NEAR(a.surface[i].z, b.surface[i].z, 1e-4);
  }
  EXPECT_DOUBLE_EQ(b.x0, a.x0);
}

TEST(MeshUnroll, DefectsLandOnTheirSidesCells) {
  const HullMask h = project_mesh(box(0, 20, -2, 2, 0, 3), both(), "box").hull;
  const HullGeometry& g = *h.geometry();
  Defect port;
  port.x_m = 10, port.z_m = 1.5, port.w_m = 2, port.h_m = 1, port.side = HullSide::port;
  Defect stbd = port;
  stbd.side = HullSide::starboard;
  stbd.x_m = 5;
  const CorrosionMap map = rasterise_defects({port, stbd}, "defects.csv", h);
  int port_cells = 0, stbd_cells = 0;
  for (int i : h.cells()) {
    if (map.cells[i] != 1) continue;
    const grid::Cell cell = h.mask().cell(i);
    const Point3 p = g.surface[i];
    EXPECT_GE(p.z, 1.0f);
    EXPECT_LE(p.z, 2.0f);
    if (g.centre_x(cell.x) < 0) {
      ++port_cells;
      EXPECT_GE(p.x, 9.0f);
      EXPECT_LT(p.x, 11.0f);
    } else {
      ++stbd_cells;
      EXPECT_GE(p.x, 4.0f);
      EXPECT_LT(p.x, 6.0f);
    }
  }
  EXPECT_EQ(port_cells, 4 * 2);  // 2 m × 1 m of 0.5 m cells
  EXPECT_EQ(stbd_cells, 4 * 2);
  Defect off = port;
  off.z_m = 10;
  off.line = 3;
  try {
    rasterise_defects({off}, "defects.csv", h);
    ADD_FAILURE() << "a defect above the hull was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("defects.csv:3"), std::string::npos) << e.what();
  }
}

TEST(MeshUnroll, RefusesMeshesThatAreNotOneClosedBody) {
  // Open: the Wigley hull's starboard half alone.
  std::vector<MeshTriangle> half;
  for (const MeshTriangle& t : wigley_triangles(testing::WigleyHull{})) {
    if (t.v[0][1] <= 0 && t.v[1][1] <= 0 && t.v[2][1] <= 0) half.push_back(t);
  }
  EXPECT_NE(error_of(half, both()).find("the mesh is not closed"), std::string::npos)
      << error_of(half, both());
  // Two bodies side by side.
  std::vector<MeshTriangle> two = box(0, 20, -2, 2, 0, 3);
  const auto other = box(0, 20, 6, 10, 0, 3);
  two.insert(two.end(), other.begin(), other.end());
  EXPECT_NE(error_of(two, both()).find("the mesh is not one body"), std::string::npos)
      << error_of(two, both());
}

TEST(MeshUnroll, OptionsAreChecked) {
  MeshImportOptions o = both();
  o.include_bottom = true;
  EXPECT_NE(error_of(box(0, 20, -2, 2, 0, 3), o).find("cannot see the flat bottom"),
            std::string::npos);
  o = MeshImportOptions{};
  o.include_transom = true;
  EXPECT_NE(error_of(box(0, 20, -2, 2, 0, 3), o).find("transom needs --sides both"),
            std::string::npos);
  o = both();
  o.max_area_error = 0.1;  // the Wigley hull's keel is steeper than that
  EXPECT_NE(error_of(wigley_triangles(testing::WigleyHull{}), o).find("above --max-area-error 0.1"),
            std::string::npos);
  o.max_area_error = 1e-9;  // the box has none (up to rounding)
  EXPECT_EQ(error_of(box(0, 20, -2, 2, 0, 3), o), "no error");
}

}  // namespace
}  // namespace hullinspect::world
