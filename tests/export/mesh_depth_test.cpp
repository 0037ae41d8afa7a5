// Exports of a hull imported from a mesh stand off from the surface at each cell, not from the
// side plane: Y = Ys ± (ζ_z + depth(x, y)), with the camera along −normal (docs/model.md "Frames
// and exports"). The depth and normals travel in the trace's `ship_frame`; hulls without a mesh
// export exactly what they exported before the trace carried it.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hullinspect/experiment/hash.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/io/export.hpp"
#include "hullinspect/io/export_readers.hpp"
#include "hullinspect/io/geo_reference.hpp"
#include "hullinspect/io/ship_frame.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

class MeshDepthExport : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = make_temp_dir("export-mesh-depth"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string dir_;
};

// Every exported csv waypoint of a Wigley hull (port and starboard) is the surface
// point of its cell plus the plane's stand-off along the side's outward direction, and looks
// along −normal, in what `run --export` flew and in what `plan --export` planned.
TEST_F(MeshDepthExport, WaypointsStandOffFromTheSurfaceAtTheirCell) {
  for (const std::string side : {"port", "starboard"}) {
    SCOPED_TRACE(side);
    const auto stl = wigley_stl(WigleyHull{});
    world::MeshImportOptions o;
    o.cell_size = 1.0;
    o.side = world::parse_hull_side(side);
    const world::HullMask hull = world::import_mesh_file(stl, o).hull;
    const world::HullGeometry& g = *hull.geometry();
    const std::string trace_path = dir_ + "/" + side + ".json";
    const std::string out = dir_ + "/" + side;
    auto r = run_cli({"run", "--hull", stl.string(), "--cell-size", "1", "--side", side, "-a",
                      "coop-frontier", "-n", "2", "--seed", "4", "--trace", trace_path, "--export",
                      out, "--format", "csv"});
    ASSERT_EQ(r.status, 0) << r.err;
    // The plan before take-off (`plan --export`) stands off from the surface the same way.
    r = run_cli({"plan", "--hull", stl.string(), "--cell-size", "1", "--side", side, "-a",
                 "part-tsp", "-n", "2", "--seed", "4", "--export", out + "-plan", "--format",
                 "csv"});
    ASSERT_EQ(r.status, 0) << r.err;
    const auto trace = io::read_trace(trace_path);
    ASSERT_TRUE(trace.contains("ship_frame"));
    const io::ShipFrameSpec spec = io::ship_frame_spec(trace);
    const io::ShipFrame frame(spec);
    // The trace places the grid as the hull's geometry does.
    EXPECT_EQ(spec.cell_m, g.cell_size);
    EXPECT_EQ(spec.x0, g.x0);
    EXPECT_EQ(spec.z0, g.z0);
    EXPECT_EQ(spec.ys, g.side_plane_y);
    EXPECT_EQ(spec.side == io::HullSide::kPort, side == "port");
    const double sign = side == "port" ? 1.0 : -1.0;
    int deep = 0;
    for (const std::string& name :
         {out + "/uav0.csv", out + "/uav1.csv", out + "-plan/uav0.csv", out + "-plan/uav1.csv"}) {
      SCOPED_TRACE(name);
      const auto plan = io::read_export_csv(io::read_file(name), name);
      ASSERT_GT(plan.waypoints.size(), 2u);
      for (const auto& w : plan.waypoints) {
        const grid::Cell c{static_cast<int>(std::floor((w.x - g.x0) / g.cell_size)),
                           static_cast<int>(std::floor((w.z - g.z0) / g.cell_size))};
        ASSERT_TRUE(hull.mask().contains(c)) << w.x << ", " << w.z;
        EXPECT_NEAR(w.x, g.centre_x(c.x), 1e-4);
        EXPECT_NEAR(w.z, g.centre_z(c.y), 1e-4);
        const double depth = g.depth(c.x, c.y);
        deep += depth > 0.5 ? 1 : 0;
        const double expected_y = g.side_plane_y + sign * (frame.standoff_m(w.plane) + depth);
        EXPECT_NEAR(w.y, expected_y, 2e-4)
            << "cell (" << c.x << ", " << c.y << ") plane " << w.plane << " depth " << depth;
        const world::Normal n = g.normal(c.x, c.y);
        if (std::hypot(n.x, n.y) > 1e-6) {
          const double yaw = std::atan2(-n.y, -n.x) * 180 / M_PI;
          EXPECT_NEAR(std::remainder(w.yaw_deg - yaw, 360.0), 0, 1e-2) << c.x << ", " << c.y;
        }
      }
    }
    EXPECT_GT(deep, 0) << "no waypoint over a cell deeper than 0.5 m: the test proves nothing";
  }
}

// An unrolled hull (both sides and the bow in one grid): every exported waypoint is its cell's
// surface point plus the plane's stand-off along the cell's normal, with the camera's yaw and
// gimbal pitch along −normal, and one mission flies on both sides of the ship. The expected points
// come from the hull's import, not from the trace.
TEST_F(MeshDepthExport, UnrolledWaypointsStandOffAlongTheNormalOnBothSides) {
  const auto stl = wigley_stl(WigleyHull{});
  world::MeshImportOptions o;
  o.cell_size = 1.0;
  o.side = world::HullSide::both;
  const world::HullMask hull = world::import_mesh_file(stl, o).hull;
  const world::HullGeometry& g = *hull.geometry();
  const std::string trace_path = dir_ + "/both.json";
  const std::string out = dir_ + "/both";
  const auto r = run_cli(
      {"run",      "--hull",           stl.string(), "--cell-size", "1",      "--sides",  "both",
       "-a",       "coop-frontier",    "-n",         "4",           "--seed", "4",        "--trace",
       trace_path, "--export",         out,          "--format",    "csv",    "--format", "litchi",
       "--origin", "53.5461,9.9665,3", "--heading",  "117"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto trace = io::read_trace(trace_path);
  ASSERT_TRUE(trace.contains("ship_frame"));
  const io::ShipFrame frame(io::ship_frame_spec(trace));
  ASSERT_TRUE(frame.unrolled());
  int port = 0, starboard = 0, sloped = 0;
  for (int k = 0; k < 4; ++k) {
    const std::string name = out + "/uav" + std::to_string(k) + ".csv";
    SCOPED_TRACE(name);
    const auto plan = io::read_export_csv(io::read_file(name), name);
    ASSERT_GT(plan.waypoints.size(), 2u);
    for (const auto& w : plan.waypoints) {
      const auto found = frame.locate(w.x, w.y, w.z, 1e-3);
      ASSERT_EQ(found.plane, w.plane) << w.x << ", " << w.y << ", " << w.z;
      const grid::Cell c = found.cell;
      if (g.coverage(c.x, c.y) == 0) continue;  // a position without surface of its own
      const world::Point3 s = g.surface(c.x, c.y);
      const world::Normal n = g.normal(c.x, c.y);
      const double d = frame.standoff_m(w.plane);
      EXPECT_NEAR(w.x, s.x + d * n.x, 2e-4) << "cell (" << c.x << ", " << c.y << ")";
      EXPECT_NEAR(w.y, s.y + d * n.y, 2e-4) << "cell (" << c.x << ", " << c.y << ")";
      EXPECT_NEAR(w.z, s.z + d * n.z, 2e-4) << "cell (" << c.x << ", " << c.y << ")";
      const double yaw = std::atan2(-n.y, -n.x) * 180 / M_PI;
      EXPECT_NEAR(std::remainder(w.yaw_deg - yaw, 360.0), 0, 1e-2) << c.x << ", " << c.y;
      (s.y > g.side_plane_y ? port : starboard) += 1;
      sloped += std::abs(n.z) > 0.05 ? 1 : 0;
    }
  }
  EXPECT_GT(port, 0) << "no waypoint on port";
  EXPECT_GT(starboard, 0) << "no waypoint on starboard";
  EXPECT_GT(sloped, 0) << "no waypoint over a sloped cell: the gimbal check proves nothing";
  // The Litchi files carry the gimbal pitch: the camera's elevation along −normal.
  const io::ExportPlan plan = io::export_plan(trace);
  for (int k = 0; k < 4; ++k) {
    for (int part = 1;; ++part) {
      const std::string name =
          out + "/uav" + std::to_string(k) + "-part" + std::to_string(part) + ".litchi.csv";
      if (!fs::exists(name)) {
        EXPECT_GT(part, 1) << name;
        break;
      }
      std::istringstream rows(io::read_file(name));
      std::string row;
      std::getline(rows, row);  // the header
      while (std::getline(rows, row)) {
        std::vector<std::string> f;
        std::istringstream fields(row);
        for (std::string v; std::getline(fields, v, ',');) f.push_back(v);
        ASSERT_GT(f.size(), 7u);
        // The row's position back in the ship frame names its cell; its pitch is that normal's.
        const io::GeoReference geo({53.5461, 9.9665, 3.0}, 117);
        double x = 0, y = 0, z = 0;
        geo.from_wgs84({std::stod(f[0]), std::stod(f[1]), 0.0}, x, y, z);
        (void)z;
        bool matched = false;
        for (const auto& w : plan.uavs[static_cast<std::size_t>(k)]) {
          if (std::hypot(w.pose.x - x, w.pose.y - y) > 1e-2) continue;
          const world::Normal n = g.normal(w.grid.cell.x, w.grid.cell.y);
          if (g.coverage(w.grid.cell.x, w.grid.cell.y) == 0) {
            matched = true;
            break;
          }
          EXPECT_NEAR(std::stod(f[7]), std::asin(-n.z) * 180 / M_PI, 2e-3) << name << ": " << row;
          matched = true;
          break;
        }
        EXPECT_TRUE(matched) << name << ": " << row;
      }
    }
  }
}

// A mask without a mesh has no ship_frame in its trace, and its exports are pinned byte for byte
// (FNV-1a ids of each file), so any change to them is a deliberate one.
TEST_F(MeshDepthExport, HullsWithoutAMeshExportExactlyAsBefore) {
  const std::string trace_path = dir_ + "/default.json";
  auto r = run_cli({"run", "-a", "lawnmower", "-n", "2", "--seed", "4", "--trace", trace_path});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(io::read_trace(trace_path).contains("ship_frame"));
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"csv/uav0.csv", "3657cb8da892d77f"},        {"csv/uav1.csv", "c96492f4e57d7bcd"},
      {"qgc/uav0.plan", "9f0b563f2682c3e4"},       {"wpl/uav1.waypoints", "76df82f568cab696"},
      {"path/uav0.path.yaml", "3d19953c6e9735d1"}, {"path/hull_to_map.yaml", "7fb9569bdd72790e"}};
  for (const std::string format : {"csv", "qgc", "wpl", "path"}) {
    r = run_cli({"export", trace_path, "--format", format, "--out", dir_ + "/" + format, "--origin",
                 "53.5461,9.9665,3", "--heading", "117"});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  for (const auto& [file, id] : expected) {
    EXPECT_EQ(experiment::stable_id(io::read_file(dir_ + "/" + file)), id) << file;
  }
}

}  // namespace
}  // namespace hullinspect::testing
