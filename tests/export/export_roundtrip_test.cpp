// Every export read back: the waypoints, turned back into grid cells, reproduce the trace's
// positions at every waypoint and along every leg, agree with it on T_m, and the geo-referenced
// formats come back to the ship frame within a millimetre (docs/export.md), on plain masks, on a
// hull imported from a mesh (whose waypoints stand off from the surface at each cell) and on an
// unrolled hull (both sides in one grid).

#include <gtest/gtest.h>
#include "source_dir.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/io/export.hpp"
#include "hullinspect/io/export_readers.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;
using io::GridState;

const io::GeoPoint kOrigin{53.5461, 9.9665, 3.0};  // a berth in Hamburg
constexpr double kHeading = 117.0;

// A waypoint turned back into the grid: time, cell, plane.
struct CellWaypoint {
  double t;
  grid::Cell cell;
  int z;
};

// Checks a waypoint list against the trace's states: each waypoint is the UAV's state at its
// time, and between two waypoints the UAV moves one cell per step along the straight leg (or
// stays), so every intermediate state is reproduced too. The last waypoint is at T_m.
// `tolerance` bounds the error of times rebuilt from distances (qgc, wpl: 0.1 mm over 0.5 m/s).
void expect_reproduces(const std::vector<CellWaypoint>& w, const std::vector<GridState>& states,
                       const std::string& what, double tolerance) {
  ASSERT_FALSE(w.empty()) << what;
  const int last = static_cast<int>(states.size()) - 1;
  EXPECT_NEAR(w.back().t, last, tolerance) << what << ": the last waypoint is not at T_m";
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double rt = std::round(w[i].t);
    ASSERT_NEAR(w[i].t, rt, tolerance) << what << " waypoint " << i;
    const int t = static_cast<int>(rt);
    ASSERT_LE(t, last);
    const auto& s = states[static_cast<std::size_t>(t)];
    EXPECT_EQ(w[i].cell, s.pos) << what << " waypoint " << i << " t = " << t;
    EXPECT_EQ(w[i].z, s.z) << what << " waypoint " << i << " t = " << t;
    EXPECT_FALSE(s.in_transit) << what << " waypoint " << i;
    if (i == 0) {
      EXPECT_EQ(t, 0);
      continue;
    }
    const int t0 = static_cast<int>(std::round(w[i - 1].t));
    const grid::Cell a = w[i - 1].cell;
    const grid::Cell b = w[i].cell;
    ASSERT_TRUE(a.x == b.x || a.y == b.y) << what << ": leg " << i << " is not straight";
    const grid::Cell step{(b.x > a.x) - (b.x < a.x), (b.y > a.y) - (b.y < a.y)};
    const int cells = std::abs(b.x - a.x) + std::abs(b.y - a.y);
    if (cells > 0) {
      EXPECT_EQ(t - t0, cells) << what << ": leg " << i << " takes one step per cell";
      EXPECT_EQ(w[i].z, w[i - 1].z) << what << ": a leg stays on its plane";
    }
    for (int u = t0; u <= t; ++u) {
      const grid::Cell expected{a.x + step.x * (u - t0), a.y + step.y * (u - t0)};
      EXPECT_EQ(states[static_cast<std::size_t>(u)].pos, expected)
          << what << " leg " << i << " t = " << u;
    }
  }
}

class ExportRoundTrip : public ::testing::TestWithParam<std::vector<std::string>> {
 protected:
  void SetUp() override { dir_ = make_temp_dir("export-roundtrip"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string dir_;
};

TEST_P(ExportRoundTrip, EveryFormatReproducesTheTrace) {
  const std::string trace_path = dir_ + "/trace.json";
  std::vector<std::string> args = {"run", "--trace", trace_path};
  for (const auto& a : GetParam()) {  // "@wigley": a Wigley hull's mesh (docs/hulls.md)
    args.push_back(a == "@wigley" ? wigley_stl(WigleyHull{}).string() : a);
  }
  const auto run = run_cli(args);
  ASSERT_EQ(run.status, 0) << run.err;
  const auto trace = io::read_trace(trace_path);
  const auto states = io::trace_states(trace);
  const io::ShipFrame frame(io::ship_frame_spec(trace));
  const io::GeoReference geo(kOrigin, kHeading);
  const std::string origin = "53.5461,9.9665,3";
  const int uavs = static_cast<int>(states.size());
  const bool mesh = trace.contains("ship_frame");
  const double speed = frame.spec().cell_m;  // one cell per second
  ASSERT_EQ(trace["result"]["T_m"].get<int>() + 1, static_cast<int>(states[0].size()));

  std::vector<std::string> plans;
  for (const std::string format : {"csv", "qgc", "wpl", "path"}) {
    const std::string out = dir_ + "/" + format;
    const auto r = run_cli({"export", trace_path, "--format", format, "--out", out, "--origin",
                            origin, "--heading", "117"});
    ASSERT_EQ(r.status, 0) << r.err;
    for (int k = 0; k < uavs; ++k) {
      const std::string what = format + " uav" + std::to_string(k);
      std::vector<CellWaypoint> cells;
      const auto from_ship = [&](double t, double x, double y, double z) {
        // The position is a cell's pose on a plane to the file's precision (0.1 mm).
        const auto found = frame.locate(x, y, z, 1e-3);
        EXPECT_NE(found.plane, 0) << what << ": (" << x << ", " << y << ", " << z
                                  << ") is no cell's pose";
        if (found.plane != 0) {
          const auto pose = frame.pose(found.cell, found.plane);
          EXPECT_LT(std::hypot(x - pose.x, y - pose.y, z - pose.z), 1e-3) << what;
        }
        cells.push_back({t, found.cell, found.plane});
      };
      if (format == "csv" || format == "path") {
        const auto name =
            out + "/uav" + std::to_string(k) + (format == "csv" ? ".csv" : ".path.yaml");
        const auto text = io::read_file(name);
        const auto plan =
            format == "csv" ? io::read_export_csv(text, name) : io::read_path_yaml(text, name);
        for (const auto& w : plan.waypoints) {
          from_ship(w.t, w.x, w.y, w.z);
          const auto pose = frame.pose(cells.back().cell, cells.back().z);
          EXPECT_NEAR(w.yaw_deg, pose.yaw * 180 / M_PI, 1e-3) << what;
          if (format == "csv") {
            EXPECT_EQ(w.plane, cells.back().z) << what;
          }
        }
      } else {
        const auto name =
            out + "/uav" + std::to_string(k) + (format == "qgc" ? ".plan" : ".waypoints");
        if (format == "qgc") plans.push_back(name);
        const auto text = io::read_file(name);
        const auto plan =
            format == "qgc" ? io::read_qgc_plan(text, name) : io::read_wpl(text, name);
        // Home is below the UAV's start on plane 2, at the grid's bottom edge (no --launch).
        const auto start = frame.pose(states[static_cast<std::size_t>(k)][0].pos, 2);
        const auto home = geo.to_wgs84(start.x, start.y, frame.spec().z0);
        EXPECT_NEAR(plan.home.lat, home.lat, 1e-9);
        EXPECT_NEAR(plan.home.lon, home.lon, 1e-9);
        EXPECT_NEAR(plan.home.alt, home.alt, 1e-4);
        // A complete mission: take-off at home, the speed, ..., landing at home.
        ASSERT_GE(plan.items.size(), 4u) << what;
        EXPECT_EQ(plan.items.front().command, 22) << what;
        EXPECT_NEAR(plan.items.front().params[4], home.lat, 1e-9) << what;
        EXPECT_EQ(plan.items[1].command, 178) << what;
        EXPECT_EQ(plan.items.back().command, 21) << what;
        EXPECT_NEAR(plan.items.back().params[5], home.lon, 1e-9) << what;
        if (format == "qgc") {
          EXPECT_DOUBLE_EQ(plan.cruise_speed, speed);
        }
        // Back to the ship frame through GeographicLib: within 1 mm of the cell's pose. Times
        // follow from flying the legs at the cruise speed (one cell per second) and the holds.
        double t = 0;
        double px = 0, py = 0, pz = 0;
        for (std::size_t i = 0; i < plan.waypoints.size(); ++i) {
          const auto& w = plan.waypoints[i];
          double x = 0, y = 0, z = 0;
          geo.from_wgs84({w.geo.lat, w.geo.lon, plan.home.alt + w.geo.alt}, x, y, z);
          const double flight = i > 0 ? std::hypot(x - px, y - py, z - pz) / speed : 0.0;
          const grid::Cell c = frame.locate(x, y, z, 1e-3).cell;
          const int moved =
              i > 0 ? std::abs(c.x - cells.back().cell.x) + std::abs(c.y - cells.back().cell.y) : 0;
          if (moved > 0) {
            // A move takes one step per cell. On a mesh hull a leg between cells of different
            // depth is longer than its cells, so a vehicle at the cruise speed arrives after the
            // trace does (docs/export.md); on a flat side it arrives exactly on time.
            EXPECT_GE(flight + w.hold_s, moved - 1e-3) << what << " waypoint " << i;
            if (!mesh) {
              EXPECT_NEAR(flight + w.hold_s, moved, 1e-3) << what << " waypoint " << i;
            }
            t += moved;
          } else {
            t += flight + w.hold_s;
          }
          from_ship(t, x, y, z);
          const auto pose = frame.pose(cells.back().cell, cells.back().z);
          EXPECT_LT(std::hypot(x - pose.x, y - pose.y, z - pose.z), 1e-3)
              << what << " waypoint " << i;
          EXPECT_NEAR(std::remainder(geo.ship_yaw(w.yaw_deg) - pose.yaw, 2 * M_PI), 0, 1e-4)
              << what;
          px = x, py = y, pz = z;
        }
      }
      const bool timed = format == "csv" || format == "path";
      expect_reproduces(cells, states[static_cast<std::size_t>(k)], what, timed ? 1e-9 : 1e-3);
    }
  }
  // The QGroundControl plans validate against the schema kept in tests/export.
  std::string command = "/usr/bin/python3 " HULLINSPECT_SOURCE_DIR "/tests/export/validate_plan.py";
  for (const auto& p : plans) command += " " + p;
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

INSTANTIATE_TEST_SUITE_P(
    Missions, ExportRoundTrip,
    ::testing::Values(
        std::vector<std::string>{"-a", "lawnmower", "-n", "3", "--seed", "4"},
        std::vector<std::string>{"-a", "part-tsp", "-n", "4", "--s2", "9", "--seed", "2"},
        std::vector<std::string>{"-a", "coop-frontier", "-n", "2", "--s2", "11", "--scenario",
                                 "combined", "--seed", "5"},
        // A mesh hull: every waypoint stands off from the surface at its cell.
        std::vector<std::string>{"-a", "part-tsp", "-n", "3", "--hull", "@wigley", "--cell-size",
                                 "1", "--side", "port", "--seed", "6"},
        // The unrolled hull: both sides and the bow in one mission, each waypoint along its
        // cell's normal.
        std::vector<std::string>{"-a", "coop-frontier", "-n", "3", "--hull", "@wigley",
                                 "--cell-size", "1", "--sides", "both", "--seed", "3"}));

TEST(QgcSchema, RejectsAPlanMissingItsFileTypeOrWithABadItem) {
  const auto dir = make_temp_dir("export-schema");
  const std::string trace = dir + "/t.json";
  ASSERT_EQ(run_cli({"run", "-n", "1", "--trace", trace}).status, 0);
  ASSERT_EQ(run_cli({"export", trace, "--format", "qgc", "--out", dir + "/q", "--origin", "0,0,0",
                     "--heading", "0"})
                .status,
            0);
  auto plan = nlohmann::json::parse(io::read_file(dir + "/q/uav0.plan"));
  const std::string script =
      "/usr/bin/python3 " HULLINSPECT_SOURCE_DIR "/tests/export/validate_plan.py ";
  EXPECT_EQ(std::system((script + dir + "/q/uav0.plan > /dev/null").c_str()), 0);
  auto broken = plan;
  broken.erase("fileType");
  io::write_file_atomic(dir + "/b1.plan", broken.dump());
  EXPECT_NE(std::system((script + dir + "/b1.plan > /dev/null").c_str()), 0);
  broken = plan;
  broken["mission"]["items"][0]["params"].erase(6);
  io::write_file_atomic(dir + "/b2.plan", broken.dump());
  EXPECT_NE(std::system((script + dir + "/b2.plan > /dev/null").c_str()), 0);
  fs::remove_all(dir);
}

// Found by fuzz_export_readers: nlohmann reports a number too large for a double as out_of_range
// (406), not parse_error, and it escaped read_qgc_plan as an uncaught exception.
TEST(ExportReaders, AQgcPlanWithANumberTooLargeForADoubleIsNotJson) {
  EXPECT_THROW((void)io::read_qgc_plan(R"({"fileType": "Plan", "version": 1e999})", "x.plan"),
               InputError);
  EXPECT_THROW((void)io::read_qgc_plan("5003e5003e-eF-eF", "x.plan"), InputError);
}

// Found by fuzz_export_readers under UBSan: a plane of 5.6e56 was converted to int unchecked.
TEST(ExportReaders, ACsvPlaneOutsideTheIntRangeIsRefused) {
  const std::string header =
      "index,t_s,x_m,y_m,z_m,yaw_deg,plane,action,duration_s,cell_x,cell_y\n";
  EXPECT_THROW((void)io::read_export_csv(header + "0,0,0,0,0,0,5.6e56,a,0,0,0\n", "x.csv"),
               InputError);
  EXPECT_EQ(io::read_export_csv(header + "0,0,0,0,0,0,2,a,0,0,0\n", "x.csv").waypoints.at(0).plane,
            2);
}

}  // namespace
}  // namespace hullinspect::testing
