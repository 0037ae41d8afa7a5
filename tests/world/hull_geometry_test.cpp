#include "hullinspect/world/hull_geometry.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::world {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

/// A 3 × 2 mask (bottom row full, top row one cell) with a simple geometry.
HullMask small_hull() {
  grid::Grid<std::uint8_t> m(3, 2, 0);
  m(0, 0) = m(1, 0) = m(2, 0) = m(1, 1) = 1;
  HullMask hull(std::move(m), "small");
  HullGeometry g;
  g.cell_size = 0.5;
  g.x0 = -1.25;
  g.z0 = 2.0;
  g.side_plane_y = 3.0;
  g.side = HullSide::port;
  g.axes = AxisMap::parse("x,-z,y");
  g.scale = 2;
  g.waterline = 2.0;
  g.mesh = "box.stl";
  g.depth = grid::Grid<float>(3, 2, 0.0f);
  g.depth(1, 0) = 0.75f;
  g.coverage = grid::Grid<float>(3, 2, 1.0f);
  g.coverage(0, 1) = 0.25f;
  g.normal = grid::Grid<Normal>(3, 2, Normal{0, 1, 0});
  g.normal(2, 0) = Normal{0.6f, 0.8f, 0};
  hull.attach_geometry(std::move(g));
  return hull;
}

TEST(AxisMap, ParsesSignedPermutations) {
  const AxisMap m = AxisMap::parse("x,-z,y");
  EXPECT_EQ(m.axis, (std::array<int, 3>{0, 2, 1}));
  EXPECT_EQ(m.sign, (std::array<int, 3>{1, -1, 1}));
  EXPECT_EQ(m.to_string(), "x,-z,y");
  EXPECT_EQ(m.determinant(), 1);  // a swap (−1) times one sign flip (−1)
  EXPECT_EQ(AxisMap::parse("x,y,z").determinant(), 1);
  EXPECT_EQ(AxisMap::parse("y,x,z").determinant(), -1);
  EXPECT_EQ(AxisMap::parse("-x,y,z").determinant(), -1);
  EXPECT_EQ(AxisMap::parse("+x,y,z").to_string(), "x,y,z");
  const std::string expected = "axes: expected a signed permutation of x,y,z like x,-z,y, got ";
  EXPECT_EQ(error_of([] { AxisMap::parse("x,x,z"); }), expected + "'x,x,z'");
  EXPECT_EQ(error_of([] { AxisMap::parse("x,y"); }), expected + "'x,y'");
  EXPECT_EQ(error_of([] { AxisMap::parse("x,y,z,"); }), expected + "'x,y,z,'");
  EXPECT_EQ(error_of([] { AxisMap::parse("x,w,z"); }), expected + "'x,w,z'");
  EXPECT_EQ(error_of([] { parse_hull_side("aft"); }),
            "side: expected port, starboard or both, got 'aft'");
}

TEST(HullGeometry, FramesFollowTheModel) {
  const HullMask hull = small_hull();
  const HullGeometry& g = *hull.geometry();
  EXPECT_DOUBLE_EQ(g.centre_x(0), -1.0);
  EXPECT_DOUBLE_EQ(g.centre_z(1), 2.75);
  EXPECT_DOUBLE_EQ(g.surface_y(1, 0), 3.75);  // port: outward is +y
  EXPECT_DOUBLE_EQ(g.uav_y(1, 0, 2.0), 5.75);
  HullGeometry starboard = g;
  starboard.side = HullSide::starboard;
  EXPECT_DOUBLE_EQ(starboard.uav_y(1, 0, 2.0), 0.25);
}

TEST(HullGeometry, JsonRoundTrips) {
  const HullMask hull = small_hull();
  const std::string text = to_hull_json(hull);
  const HullMask back = parse_hull_json(text, "back.json");
  EXPECT_EQ(back.mask(), hull.mask());
  ASSERT_NE(back.geometry(), nullptr);
  const HullGeometry& a = *hull.geometry();
  const HullGeometry& b = *back.geometry();
  EXPECT_EQ(b.cell_size, a.cell_size);
  EXPECT_EQ(b.x0, a.x0);
  EXPECT_EQ(b.z0, a.z0);
  EXPECT_EQ(b.side_plane_y, a.side_plane_y);
  EXPECT_EQ(b.side, a.side);
  EXPECT_EQ(b.axes, a.axes);
  EXPECT_EQ(b.scale, a.scale);
  EXPECT_EQ(b.waterline, a.waterline);
  EXPECT_EQ(b.mesh, a.mesh);
  EXPECT_EQ(b.depth, a.depth);
  EXPECT_EQ(b.coverage, a.coverage);
  EXPECT_EQ(b.normal, a.normal);
  EXPECT_EQ(to_hull_json(back), text);
}

TEST(HullGeometry, BadFilesNameTheField) {
  const nlohmann::json good = nlohmann::json::parse(to_hull_json(small_hull()));
  const auto with = [&](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json doc = good;
    edit(doc);
    return error_of([&] { parse_hull_json(doc.dump(), "h.json"); });
  };
  EXPECT_EQ(error_of([] { parse_hull_json("{", "h.json"); }),
            "h.json:1: not valid JSON: syntax error while parsing object key - unexpected end of "
            "input; expected string literal");
  // Found by the whole-CLI mutation test: a number no double holds was nlohmann's exception.
  EXPECT_EQ(
      error_of([] { parse_hull_json("{\"format\": 1,\n\"depth\": [[0.1e4000]]}", "h.json"); }),
      "h.json:2: not valid JSON: number overflow parsing '0.1e4000' (in depth[0][0])");
  EXPECT_EQ(with([](auto& d) { d["format"] = "x"; }),
            "h.json: format: expected \"hullinspect-hull\"");
  EXPECT_EQ(with([](auto& d) { d["version"] = 2; }), "h.json: version: expected 1");
  EXPECT_EQ(with([](auto& d) { d.erase("cell_size"); }), "h.json: cell_size: missing");
  EXPECT_EQ(with([](auto& d) { d["cell_size"] = -1; }),
            "h.json: cell_size: must be metres in [0.001, 1000] (got -1)");
  // The ship frame's bounds (world/ship_frame_bounds.hpp): exports stay finite.
  EXPECT_EQ(with([](auto& d) { d["cell_size"] = 1e-320; }),
            "h.json: cell_size: must be metres in [0.001, 1000] (got 1e-320)");
  EXPECT_EQ(with([](auto& d) { d["origin"] = {1e308, 0}; }),
            "h.json: origin: must be metres in [-100000, 100000] (got [1e+308, 0])");
  EXPECT_EQ(with([](auto& d) { d["side_plane_y"] = -2e5; }),
            "h.json: side_plane_y: must be metres in [-100000, 100000] (got -200000)");
  EXPECT_EQ(with([](auto& d) { d["width"] = 0; }), "h.json: width: expected an integer in 1..4096");
  EXPECT_EQ(with([](auto& d) { d["mask"][0].push_back(1); }),
            "h.json: mask: row 0 must have 3 values");
  EXPECT_EQ(with([](auto& d) { d["mask"][1][0] = 2; }), "h.json: mask: cell (0, 1) is not 0 or 1");
  EXPECT_EQ(with([](auto& d) { d["side"] = "aft"; }),
            "h.json: side: expected port, starboard or both, got 'aft'");
  EXPECT_EQ(with([](auto& d) { d["depth"][0][1] = -0.5; }),
            "h.json: depth: cell (1, 0) is -0.5; expected metres >= 0");
  EXPECT_EQ(with([](auto& d) {
              d["normal"][1][2] = {0, 2, 0};
            }),
            "h.json: normal: cell (2, 1) has length 2.0000; expected a unit vector");
  EXPECT_EQ(with([](auto& d) { d["coverage"].erase(1); }), "h.json: coverage: expected 2 rows");
  EXPECT_EQ(with([](auto& d) { d["origin"] = {1}; }),
            "h.json: origin: expected [X0, Z0] in metres");
  EXPECT_EQ(with([](auto& d) { d["mask"][0][1] = 0; }),
            "h.json: the hull is not 4-connected: 3 components (1 cells from (0, 0); 1 cells from "
            "(2, 0); 1 cells from (1, 1))");
}

}  // namespace
}  // namespace hullinspect::world
