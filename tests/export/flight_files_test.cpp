// The flight files a crew loads (docs/export.md "Flight files"): every format read back and
// checked against the trace's waypoints — DJI KMZ unzipped and parsed, Litchi column by column,
// QGC/WPL item by item, KML with an XML parser — plus launch sites, sorties and waypoint caps.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/io/export.hpp"
#include "hullinspect/io/export_readers.hpp"
#include "hullinspect/io/geo_reference.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "source_dir.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_fixtures.hpp"
#include "support/text_fields.hpp"
#include "support/zip_entries.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

const io::GeoPoint kOrigin{53.5461, 9.9665, 3.0};
constexpr double kHeading = 117;
const std::vector<std::string> kGeo = {"--origin", "53.5461,9.9665,3", "--heading", "117"};

// One planned mission with a no-fly box, shared by the tests of this file.
class FlightFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = make_temp_dir("flight-files");
    trace_ = dir_ + "/trace.json";
    const auto r = run_cli({"plan", "-a", "part-tsp", "-n", "3", "--seed", "2", "--no-fly-box",
                            "60,3,64,9", "--trace", trace_});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // `export` of the shared trace into DIR/name with the geo-reference and `extra` options.
  static std::string export_to(const std::string& name, std::vector<std::string> extra) {
    const std::string out = dir_ + "/" + name;
    std::vector<std::string> args = {"export", trace_, "--out", out};
    args.insert(args.end(), kGeo.begin(), kGeo.end());
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_cli(args);
    EXPECT_EQ(r.status, 0) << r.err;
    return out;
  }
  static io::ExportPlan plan() { return io::export_plan(io::read_trace(trace_)); }

  static std::string dir_;
  static std::string trace_;
};
std::string FlightFiles::dir_;
std::string FlightFiles::trace_;

// A point of a file back in the ship frame: WGS-84 position and a height above `home`.
io::ShipPose ship_point(double lat, double lon, double height, const io::GeoPoint& home) {
  const io::GeoReference geo(kOrigin, kHeading);
  io::ShipPose p;
  geo.from_wgs84({lat, lon, home.alt + height}, p.x, p.y, p.z);
  return p;
}

// The home point of a sortie without --launch: below the UAV's start on plane 2, at the grid's
// bottom edge.
io::GeoPoint home_of(const io::ExportPlan& plan, int uav) {
  const io::GeoReference geo(kOrigin, kHeading);
  const auto p = plan.frame.pose(plan.uavs[static_cast<std::size_t>(uav)].front().grid.cell, 2);
  return geo.to_wgs84(p.x, p.y, plan.frame.spec().z0);
}

void expect_at(const io::ShipPose& got, const io::ExportWaypoint& want, const std::string& what) {
  EXPECT_LT(std::hypot(got.x - want.pose.x, got.y - want.pose.y, got.z - want.pose.z), 0.01)
      << what << ": (" << got.x << ", " << got.y << ", " << got.z << ") vs (" << want.pose.x << ", "
      << want.pose.y << ", " << want.pose.z << ")";
}

double compass_of(const io::ExportWaypoint& w) {
  return io::GeoReference(kOrigin, kHeading).compass_deg(w.pose.yaw);
}

TEST_F(FlightFiles, DjiKmzFollowsWpmlAndTheTrace) {
  const auto out = export_to("dji", {"--format", "dji-kmz", "--drone", "m30t", "--finish", "rtl",
                                     "--max-waypoints", "1000"});
  const auto p = plan();
  for (int k = 0; k < 3; ++k) {
    const auto entries = unzip(out + "/uav" + std::to_string(k) + ".kmz");
    ASSERT_EQ(entries.size(), 2u);
    ASSERT_TRUE(entries.count("wpmz/template.kml"));
    ASSERT_TRUE(entries.count("wpmz/waylines.wpml"));
    const auto& want = p.uavs[static_cast<std::size_t>(k)];
    const auto home = home_of(p, k);
    for (const auto& [name, content] : entries) {
      const bool waylines = name == "wpmz/waylines.wpml";
      pugi::xml_document doc;
      ASSERT_TRUE(doc.load_string(content.c_str())) << name;
      const auto kml = doc.child("kml");
      EXPECT_STREQ(kml.attribute("xmlns:wpml").value(), "http://www.dji.com/wpmz/1.0.2");
      const auto config = kml.child("Document").child("wpml:missionConfig");
      for (const char* field : {"wpml:flyToWaylineMode", "wpml:finishAction", "wpml:exitOnRCLost",
                                "wpml:takeOffSecurityHeight", "wpml:globalTransitionalSpeed"}) {
        EXPECT_FALSE(config.child(field).empty()) << name << " " << field;
      }
      EXPECT_STREQ(config.child_value("wpml:finishAction"), "goHome");
      EXPECT_STREQ(config.child("wpml:droneInfo").child_value("wpml:droneEnumValue"), "67");
      EXPECT_STREQ(config.child("wpml:droneInfo").child_value("wpml:droneSubEnumValue"), "1");
      EXPECT_STREQ(config.child("wpml:payloadInfo").child_value("wpml:payloadEnumValue"), "53");
      const auto folder = kml.child("Document").child("Folder");
      std::size_t i = 0;
      int photo_groups = 0;
      for (const auto pm : folder.children("Placemark")) {
        ASSERT_LT(i, want.size()) << name;
        EXPECT_EQ(pm.child("wpml:index").text().as_int(), static_cast<int>(i));
        const auto lonlat = split(pm.child("Point").child_value("coordinates"), ',');
        ASSERT_EQ(lonlat.size(), 2u);
        const double height =
            pm.child(waylines ? "wpml:executeHeight" : "wpml:height").text().as_double();
        expect_at(ship_point(std::stod(lonlat[1]), std::stod(lonlat[0]), height, home), want[i],
                  name + " placemark " + std::to_string(i));
        const double heading = pm.child("wpml:waypointHeadingParam")
                                   .child("wpml:waypointHeadingAngle")
                                   .text()
                                   .as_double();
        EXPECT_NEAR(std::remainder(heading - compass_of(want[i]), 360), 0, 1e-3);
        for (const auto g : pm.children("wpml:actionGroup")) {
          const auto trigger = g.child("wpml:actionTrigger");
          if (std::string(trigger.child_value("wpml:actionTriggerType")) == "multipleDistance") {
            ++photo_groups;
            EXPECT_DOUBLE_EQ(trigger.child("wpml:actionTriggerParam").text().as_double(),
                             p.frame.spec().cell_m);
            EXPECT_STREQ(g.child("wpml:action").child_value("wpml:actionActuatorFunc"),
                         "takePhoto");
            EXPECT_EQ(g.child("wpml:actionGroupEndIndex").text().as_int(),
                      static_cast<int>(want.size()) - 1);
          }
        }
        ++i;
      }
      EXPECT_EQ(i, want.size()) << name;
      EXPECT_EQ(photo_groups, 1) << name;
    }
  }
}

// Heights (docs/export.md "Altitudes: which frame each file is in"): every file says which
// frame its heights are in, and the absolute heights are the home point's ellipsoidal height. The
// launch site 0,0 lies at the grid's bottom edge (Z0 = 0 for a mask hull), at the origin's height
// of 3 m.
TEST_F(FlightFiles, EveryFileDeclaresTheFrameOfItsHeights) {
  const auto out =
      export_to("heights", {"--format", "all", "--launch", "0,0", "--max-waypoints", "100000"});
  constexpr double kHomeHeight = 3.0;
  const auto qgc = nlohmann::json::parse(io::read_file(out + "/uav0.plan"));
  EXPECT_NEAR(qgc["mission"]["plannedHomePosition"][2].get<double>(), kHomeHeight, 1e-3);
  int positioned = 0;
  for (const auto& item : qgc["mission"]["items"]) {
    const int frame = item["frame"].get<int>();
    EXPECT_TRUE(frame == 2 || frame == 3) << item.dump();  // no command, or above home
    if (frame != 3) continue;
    ++positioned;
    EXPECT_EQ(item["AltitudeMode"], 1) << item.dump();  // relative to home
    EXPECT_EQ(item["Altitude"], item["params"][6]) << item.dump();
  }
  EXPECT_GT(positioned, 10);
  const auto wpl = lines_of(io::read_file(out + "/uav0.waypoints"));
  ASSERT_GT(wpl.size(), 3u);
  const auto home = split(wpl[1], '\t');
  EXPECT_EQ(home[2], "0");  // the home line: an absolute height
  EXPECT_NEAR(std::stod(home[10]), kHomeHeight, 1e-3);
  for (std::size_t i = 2; i < wpl.size(); ++i) {
    const auto f = split(wpl[i], '\t');
    EXPECT_TRUE(f[2] == "2" || f[2] == "3") << wpl[i];
  }
  const auto litchi = lines_of(io::read_file(out + "/uav0.litchi.csv"));
  for (std::size_t i = 1; i < litchi.size(); ++i) {
    EXPECT_EQ(split(litchi[i], ',')[38], "0") << litchi[i];  // above the take-off point
  }
  const auto kmz = unzip(out + "/uav0.kmz");
  for (const char* entry : {"wpmz/template.kml", "wpmz/waylines.wpml"}) {
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(kmz.at(entry).c_str())) << entry;
    const auto folder = doc.child("kml").child("Document").child("Folder");
    const bool waylines = std::string(entry) == "wpmz/waylines.wpml";
    const auto mode = waylines
                          ? folder.child("wpml:executeHeightMode")
                          : folder.child("wpml:waylineCoordinateSysParam").child("wpml:heightMode");
    EXPECT_STREQ(mode.text().as_string(), "relativeToStartPoint") << entry;
    if (!waylines) {
      const auto ref = split(doc.child("kml")
                                 .child("Document")
                                 .child("wpml:missionConfig")
                                 .child("wpml:takeOffRefPoint")
                                 .text()
                                 .as_string(),
                             ',');
      ASSERT_EQ(ref.size(), 3u);
      EXPECT_NEAR(std::stod(ref[2]), kHomeHeight, 1e-3);
    }
  }
  pugi::xml_document kml;
  ASSERT_TRUE(kml.load_file((out + "/mission.kml").c_str()));
  int modes = 0;
  for (const auto& node : kml.select_nodes("//altitudeMode")) {
    EXPECT_STREQ(node.node().text().as_string(), "relativeToGround");
    ++modes;
  }
  EXPECT_GT(modes, 0);
}

TEST_F(FlightFiles, LitchiColumnByColumn) {
  const auto out = export_to("litchi", {"--format", "litchi", "--max-waypoints", "1000"});
  const auto p = plan();
  for (int k = 0; k < 3; ++k) {
    const auto rows = lines_of(io::read_file(out + "/uav" + std::to_string(k) + ".litchi.csv"));
    const auto header = split(rows.at(0), ',');
    ASSERT_EQ(header.size(), 8u + 30u + 8u);
    EXPECT_EQ(header[0], "latitude");
    EXPECT_EQ(header[2], "altitude(m)");
    EXPECT_EQ(header[3], "heading(deg)");
    EXPECT_EQ(header[7], "gimbalpitchangle");
    EXPECT_EQ(header[8], "actiontype1");
    EXPECT_EQ(header[37], "actionparam15");
    EXPECT_EQ(header[38], "altitudemode");
    EXPECT_EQ(header[39], "speed(m/s)");
    EXPECT_EQ(header[45], "photo_distinterval");
    const auto& want = p.uavs[static_cast<std::size_t>(k)];
    ASSERT_EQ(rows.size(), want.size() + 1);
    const auto home = home_of(p, k);
    for (std::size_t i = 0; i < want.size(); ++i) {
      const auto f = split(rows[i + 1], ',');
      ASSERT_EQ(f.size(), header.size());
      const std::string what = "uav" + std::to_string(k) + " row " + std::to_string(i + 1);
      expect_at(ship_point(std::stod(f[0]), std::stod(f[1]), std::stod(f[2]), home), want[i], what);
      EXPECT_NEAR(std::stod(f[3]), compass_of(want[i]), 1e-3) << what;
      EXPECT_EQ(f[6], "2") << what;      // gimbal interpolated
      EXPECT_EQ(f[7], "0.000") << what;  // a vertical side: a level camera
      EXPECT_EQ(f[38], "0") << what;     // above the take-off point
      EXPECT_EQ(std::stod(f[39]), p.frame.spec().cell_m) << what;
      // A hold is a "stay" action of its milliseconds; the legs of the plan photograph.
      const auto& w = want[i];
      if (w.grid.action == io::WaypointAction::kHold) {
        EXPECT_EQ(f[8], "0") << what;
        EXPECT_EQ(std::stoi(f[9]), w.grid.duration * 1000) << what;
      } else if (w.grid.action != io::WaypointAction::kPlaneChange) {
        EXPECT_EQ(f[8], "-1") << what;
      }
      EXPECT_EQ(f[45], i + 1 < want.size() ? "0.5000" : "-1") << what;
    }
  }
}

TEST_F(FlightFiles, ArduPilotMissionTakesOffFromTheLaunchSiteAndReturns) {
  const auto out = export_to("ardupilot", {"--format", "qgc", "--format", "wpl", "--firmware",
                                           "ardupilot", "--finish", "rtl", "--launch", "0,0"});
  const auto p = plan();
  const io::GeoReference geo(kOrigin, kHeading);
  const auto site = p.frame.pose({0, 0}, 2);
  const auto home = geo.to_wgs84(site.x, site.y, p.frame.spec().z0);
  for (int k = 0; k < 3; ++k) {
    const auto name = out + "/uav" + std::to_string(k);
    const auto qgc = io::read_qgc_plan(io::read_file(name + ".plan"), name);
    const auto wpl = io::read_wpl(io::read_file(name + ".waypoints"), name);
    EXPECT_EQ(qgc.firmware, 3);  // MAV_AUTOPILOT_ARDUPILOTMEGA
    for (const auto* m : {&qgc, &wpl}) {
      EXPECT_NEAR(m->home.lat, home.lat, 1e-9);
      EXPECT_NEAR(m->home.lon, home.lon, 1e-9);
      ASSERT_EQ(m->items.size(), qgc.items.size());
      EXPECT_EQ(m->items.front().command, 22);
      EXPECT_EQ(m->items[1].command, 178);
      EXPECT_EQ(m->items[2].command, 205);  // the gimbal, level
      EXPECT_EQ(m->items[2].params[0], 0);
      EXPECT_EQ(m->items.back().command, 20);
      // Every waypoint's heading is set by a CONDITION_YAW before it.
      double yaw = -1;
      int triggers = 0;
      for (const auto& item : m->items) {
        if (item.command == 115) yaw = item.params[0];
        if (item.command == 16) {
          EXPECT_EQ(item.params[3], yaw);
        }
        if (item.command == 206) ++triggers;
      }
      EXPECT_EQ(triggers, 2);  // on at the plan's start, off at its end
      // The first and last waypoints are the site's plane-2 position; the plan lies between.
      const auto first = ship_point(m->waypoints.front().geo.lat, m->waypoints.front().geo.lon,
                                    m->waypoints.front().geo.alt, m->home);
      const auto last = ship_point(m->waypoints.back().geo.lat, m->waypoints.back().geo.lon,
                                   m->waypoints.back().geo.alt, m->home);
      EXPECT_LT(std::hypot(first.x - site.x, first.y - site.y, first.z - site.z), 0.01);
      EXPECT_LT(std::hypot(last.x - site.x, last.y - site.y, last.z - site.z), 0.01);
      // No leg of the flight passes a no-fly position: every waypoint's cell is allowed and legs
      // are straight along a row or column.
      for (const auto& w : m->waypoints) {
        const auto s = ship_point(w.geo.lat, w.geo.lon, w.geo.alt, m->home);
        const auto c = p.frame.cell_at(s.x, s.z);
        EXPECT_EQ(std::count(p.no_fly.begin(), p.no_fly.end(), c), 0);
      }
    }
    // No geofence: a horizontal polygon would also forbid the legal flight past the box.
    const auto doc = nlohmann::json::parse(io::read_file(name + ".plan"));
    EXPECT_TRUE(doc["geoFence"]["polygons"].empty());
  }
  std::string command = "/usr/bin/python3 " HULLINSPECT_SOURCE_DIR "/tests/export/validate_plan.py";
  for (int k = 0; k < 3; ++k) command += " " + out + "/uav" + std::to_string(k) + ".plan";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

TEST_F(FlightFiles, ALaunchHeightPutsHomeOnTheQuay) {
  // A quay 3 m above the grid's bottom edge beside row 6 (plane-2 position at Z = 3.25 m): the
  // sortie takes off from and lands on the quay, and every height above home counts from it.
  constexpr double kQuayZ = 3.0;
  const auto out =
      export_to("quay", {"--format", "qgc", "--format", "wpl", "--format", "litchi", "--launch",
                         "0,6", "--launch-height", "3", "--max-waypoints", "100000"});
  const auto p = plan();
  const io::GeoReference geo(kOrigin, kHeading);
  const auto site = p.frame.pose({0, 6}, 2);
  const auto quay = geo.to_wgs84(site.x, site.y, kQuayZ);
  for (int k = 0; k < 3; ++k) {
    const auto name = out + "/uav" + std::to_string(k);
    const auto qgc = io::read_qgc_plan(io::read_file(name + ".plan"), name);
    const auto wpl = io::read_wpl(io::read_file(name + ".waypoints"), name);
    for (const auto* m : {&qgc, &wpl}) {
      EXPECT_NEAR(m->home.alt, quay.alt, 1e-4) << name;
      EXPECT_NEAR(m->home.lat, quay.lat, 1e-9) << name;
      ASSERT_EQ(m->items.front().command, 22) << name;  // NAV_TAKEOFF
      EXPECT_NEAR(m->items.front().params[6], site.z - kQuayZ, 1e-4) << name;
      // The first waypoint, read back with its height above the quay, is the site's position.
      const auto first = ship_point(m->waypoints.front().geo.lat, m->waypoints.front().geo.lon,
                                    m->waypoints.front().geo.alt, m->home);
      EXPECT_LT(std::hypot(first.x - site.x, first.y - site.y, first.z - site.z), 0.01) << name;
    }
    const auto litchi = lines_of(io::read_file(name + ".litchi.csv"));
    EXPECT_NEAR(std::stod(split(litchi.at(1), ',').at(2)), site.z - kQuayZ, 1e-4) << name;
  }
  // A quay above the site's plane-2 position: the take-off would have to climb down.
  const auto r =
      run_cli({"export", trace_, "--out", dir_ + "/high-quay", "--format", "qgc", "--origin",
               "53.5461,9.9665,3", "--heading", "117", "--launch", "0,0", "--launch-height", "3"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--launch-height: the ground at 3 m lies above UAV 0's first waypoint"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir_ + "/high-quay"));
}

TEST_F(FlightFiles, AGeoidHeightWritesTheHomeAboveSeaLevel) {
  // With the geoid's height N given, the absolute heights MAVLink means above mean sea level are
  // h − N; the heights above home do not change.
  const auto plain = export_to("ellipsoidal", {"--format", "qgc", "--format", "wpl"});
  const auto msl =
      export_to("sea-level", {"--format", "qgc", "--format", "wpl", "--geoid-height", "40.5"});
  for (const char* file : {"/uav0.plan", "/uav0.waypoints"}) {
    const std::string a = plain + file, b = msl + file;
    const bool qgc = std::string(file).ends_with(".plan");
    const auto read = [qgc](const std::string& path) {
      return qgc ? io::read_qgc_plan(io::read_file(path), path)
                 : io::read_wpl(io::read_file(path), path);
    };
    const auto e = read(a), m = read(b);
    EXPECT_NEAR(m.home.alt, e.home.alt - 40.5, 1e-4) << file;
    ASSERT_EQ(m.items.size(), e.items.size());
    for (std::size_t i = 0; i < m.items.size(); ++i) {
      EXPECT_EQ(m.items[i].params[6], e.items[i].params[6]) << file << " item " << i;
    }
  }
}

TEST_F(FlightFiles, WplWritesZeroForUnsetParametersAndLandsFacingTheLastHeading) {
  // PX4's gimbal command leaves its rates unset (null in the .plan): the WPL file writes the
  // format's unused value, 0, never nan; the landing's yaw is the last waypoint's heading.
  const auto out =
      export_to("wpl-unset", {"--format", "wpl", "--format", "qgc", "--launch", "0,0"});
  for (int k = 0; k < 3; ++k) {
    const auto name = out + "/uav" + std::to_string(k);
    const auto text = io::read_file(name + ".waypoints");
    EXPECT_EQ(text.find("nan"), std::string::npos) << name;
    const auto wpl = io::read_wpl(text, name);
    const auto qgc = io::read_qgc_plan(io::read_file(name + ".plan"), name);
    ASSERT_EQ(wpl.items.size(), qgc.items.size());
    int gimbals = 0;
    for (std::size_t i = 0; i < wpl.items.size(); ++i) {
      for (std::size_t j = 0; j < 7; ++j) {
        const double q = qgc.items[i].params[j];
        EXPECT_NEAR(wpl.items[i].params[j], std::isnan(q) ? 0.0 : q, 1e-9) << name << " item " << i;
      }
      if (wpl.items[i].command == 1000) {  // DO_GIMBAL_MANAGER_PITCHYAW
        ++gimbals;
        EXPECT_TRUE(std::isnan(qgc.items[i].params[2]));
        EXPECT_EQ(wpl.items[i].params[2], 0.0);
        EXPECT_EQ(wpl.items[i].params[3], 0.0);
      }
    }
    EXPECT_GT(gimbals, 0) << name;
    const auto& land = wpl.items.back();
    ASSERT_EQ(land.command, 21) << name;
    EXPECT_EQ(land.params[3], wpl.waypoints.back().yaw_deg) << name;
    EXPECT_EQ(qgc.items.back().params[3], qgc.waypoints.back().yaw_deg) << name;
  }
}

TEST_F(FlightFiles, CapSplitsASortieIntoFilesThatResumeWhereTheLastEnded) {
  const auto whole = export_to("whole", {"--format", "litchi", "--max-waypoints", "1000"});
  const auto split_dir = export_to("split", {"--format", "litchi", "--max-waypoints", "7"});
  for (int k = 0; k < 3; ++k) {
    const auto rows = lines_of(io::read_file(whole + "/uav" + std::to_string(k) + ".litchi.csv"));
    std::vector<std::string> joined = {rows.front()};
    int parts = 0;
    for (int part = 1;; ++part) {
      const auto name =
          split_dir + "/uav" + std::to_string(k) + "-part" + std::to_string(part) + ".litchi.csv";
      if (!fs::exists(name)) break;
      ++parts;
      const auto r = lines_of(io::read_file(name));
      EXPECT_EQ(r.front(), rows.front());
      ASSERT_GE(r.size(), 3u);
      EXPECT_LE(r.size() - 1, 7u) << name;
      // A part starts at the last waypoint of the one before (its photo and stay columns aside).
      std::size_t from = 1;
      if (part > 1) {
        EXPECT_EQ(split(r[1], ',')[0], split(joined.back(), ',')[0]) << name;
        EXPECT_EQ(split(r[1], ',')[1], split(joined.back(), ',')[1]) << name;
        from = 2;
      }
      joined.insert(joined.end(), r.begin() + static_cast<long>(from), r.end());
    }
    EXPECT_EQ(parts, static_cast<int>((rows.size() - 2 + 5) / 6)) << "uav" << k;
    ASSERT_EQ(joined.size(), rows.size());
    for (std::size_t i = 1; i < rows.size(); ++i) {
      EXPECT_EQ(split(joined[i], ',')[0], split(rows[i], ',')[0]);
      EXPECT_EQ(split(joined[i], ',')[3], split(rows[i], ',')[3]);
    }
  }
}

TEST_F(FlightFiles, KmlDrawsEachSortieTheSitesAndTheNoFlyBoxes) {
  const auto out = export_to("kml", {"--format", "kml", "--launch", "0,0", "--launch", "229,0"});
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((out + "/mission.kml").c_str()));
  const auto document = doc.child("kml").child("Document");
  std::map<std::string, int> folders;
  int faces = 0;
  for (const auto folder : document.children("Folder")) {
    int n = 0;
    for (auto pm = folder.child("Placemark"); pm; pm = pm.next_sibling("Placemark")) ++n;
    folders[folder.child_value("name")] = n;
    if (std::string(folder.child_value("name")) == "No-fly zones") {
      const auto box = folder.child("Placemark").child("MultiGeometry");
      for (auto f = box.child("Polygon"); f; f = f.next_sibling("Polygon")) ++faces;
    }
  }
  EXPECT_EQ(folders["Flights"], 3);
  EXPECT_EQ(folders["Launch sites"], 2);
  // The 5 × 7 box: one box per row of it, six faces each.
  EXPECT_EQ(folders["No-fly zones"], 7);
  EXPECT_EQ(faces, 6);
}

// An unrolled hull (both sides and the bow in one grid) in DJI's and Google Earth's formats: every
// DJI placemark comes back to its waypoint's stand-off pose around the ship, and each no-fly cell
// is a KML box of its own (a row of cells curves around the hull).
TEST(UnrolledFlightFiles, DjiKmzAndKmlPlaceTheWaypointsAroundTheShip) {
  const std::string dir = make_temp_dir("flight-files-unrolled");
  const std::string trace = dir + "/trace.json";
  auto r = run_cli({"plan", "--hull", wigley_stl(WigleyHull{}).string(), "--sides", "both",
                    "--cell-size", "1", "-a", "part-tsp", "-n", "2", "--seed", "3", "--no-fly-box",
                    "99,7,101,7", "--trace", trace});
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> args = {"export",   trace,     "--out",           dir + "/out",
                                   "--format", "dji-kmz", "--format",        "kml",
                                   "--drone",  "m3e",     "--max-waypoints", "1000"};
  args.insert(args.end(), kGeo.begin(), kGeo.end());
  r = run_cli(args);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto p = io::export_plan(io::read_trace(trace));
  ASSERT_TRUE(p.frame.unrolled());
  int port = 0, starboard = 0;
  for (int k = 0; k < 2; ++k) {
    const auto entries = unzip(dir + "/out/uav" + std::to_string(k) + ".kmz");
    ASSERT_TRUE(entries.count("wpmz/waylines.wpml"));
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(entries.at("wpmz/waylines.wpml").c_str()));
    const auto& want = p.uavs[static_cast<std::size_t>(k)];
    const auto home = home_of(p, k);
    std::size_t i = 0;
    for (const auto pm : doc.child("kml").child("Document").child("Folder").children("Placemark")) {
      ASSERT_LT(i, want.size());
      const auto lonlat = split(pm.child("Point").child_value("coordinates"), ',');
      ASSERT_EQ(lonlat.size(), 2u);
      const auto got = ship_point(std::stod(lonlat[1]), std::stod(lonlat[0]),
                                  pm.child("wpml:executeHeight").text().as_double(), home);
      expect_at(got, want[i], "uav" + std::to_string(k) + " placemark " + std::to_string(i));
      (got.y > p.frame.spec().ys ? port : starboard) += 1;
      ++i;
    }
    EXPECT_EQ(i, want.size());
  }
  // One mission on both sides of the ship.
  EXPECT_GT(port, 0);
  EXPECT_GT(starboard, 0);
  pugi::xml_document kml;
  ASSERT_TRUE(kml.load_file((dir + "/out/mission.kml").c_str()));
  std::map<std::string, int> folders;
  for (const auto folder : kml.child("kml").child("Document").children("Folder")) {
    int n = 0;
    for (auto pm = folder.child("Placemark"); pm; pm = pm.next_sibling("Placemark")) ++n;
    folders[folder.child_value("name")] = n;
  }
  EXPECT_EQ(folders["Flights"], 2);
  EXPECT_EQ(folders["No-fly zones"], 3);
  fs::remove_all(dir);
}

TEST_F(FlightFiles, AllFormatsInOneCommandStayUnderTheirCaps) {
  const auto out = export_to("all", {"--format", "all", "--launch", "0,0", "--launch", "229,0"});
  int kmz = 0, litchi = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    const auto name = entry.path().filename().string();
    if (name.ends_with(".litchi.csv")) {
      ++litchi;
      EXPECT_LE(lines_of(io::read_file(entry.path().string())).size() - 1, 99u) << name;
    }
    if (name.ends_with(".kmz")) {
      ++kmz;
      pugi::xml_document doc;
      ASSERT_TRUE(doc.load_string(unzip(entry.path().string())["wpmz/waylines.wpml"].c_str()));
      int placemarks = 0;
      for (auto pm = doc.child("kml").child("Document").child("Folder").child("Placemark"); pm;
           pm = pm.next_sibling("Placemark")) {
        ++placemarks;
      }
      EXPECT_LE(placemarks, 200) << name;
    }
  }
  EXPECT_GE(litchi, 3);
  EXPECT_GE(kmz, 3);
  for (const char* name : {"uav0.csv", "uav0.plan", "uav0.waypoints", "uav0.path.yaml",
                           "hull_to_map.yaml", "mission.kml"}) {
    EXPECT_TRUE(fs::exists(out + "/" + name)) << name;
  }
}

TEST_F(FlightFiles, BothFirmwaresInOneCommandNameTheirFiles) {
  const auto out = export_to("firmwares", {"--format", "qgc", "--format", "wpl", "--firmware",
                                           "px4", "--firmware", "ardupilot", "--launch", "0,0"});
  const auto single = export_to("ardupilot-only", {"--format", "qgc", "--format", "wpl",
                                                   "--firmware", "ardupilot", "--launch", "0,0"});
  for (int k = 0; k < 3; ++k) {
    const auto stem = out + "/uav" + std::to_string(k);
    EXPECT_FALSE(fs::exists(stem + ".plan"));
    const auto px4 = io::read_qgc_plan(io::read_file(stem + ".px4.plan"), stem);
    const auto apm = io::read_qgc_plan(io::read_file(stem + ".ardupilot.plan"), stem);
    EXPECT_EQ(px4.firmware, 12);
    EXPECT_EQ(apm.firmware, 3);
    EXPECT_EQ(std::count_if(px4.items.begin(), px4.items.end(),
                            [](const io::ReadItem& i) { return i.command == 1000; }) > 0,
              true);
    EXPECT_EQ(std::count_if(apm.items.begin(), apm.items.end(),
                            [](const io::ReadItem& i) { return i.command == 205; }) > 0,
              true);
    // Each is the file a single-firmware export writes.
    const auto one = "/uav" + std::to_string(k);
    EXPECT_EQ(io::read_file(stem + ".ardupilot.plan"), io::read_file(single + one + ".plan"));
    EXPECT_EQ(io::read_file(stem + ".ardupilot.waypoints"),
              io::read_file(single + one + ".waypoints"));
    EXPECT_TRUE(fs::exists(stem + ".px4.waypoints"));
  }
}

TEST(PreflightReport, SortiesCellsAndWarningsMatchTheFiles) {
  const auto dir = make_temp_dir("preflight");
  std::vector<std::string> args = {"plan",   "-a",           "part-tsp",     "-n",
                                   "2",      "--no-fly-box", "60,3,64,9",    "--launch",
                                   "0,0",    "--export",     dir + "/files", "--format",
                                   "litchi", "--format",     "qgc",          "--max-waypoints",
                                   "9",      "--report",     dir + "/report"};
  args.insert(args.end(), kGeo.begin(), kGeo.end());
  const auto r = run_cli(args);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto report = nlohmann::json::parse(io::read_file(dir + "/report/preflight.json"));
  ASSERT_EQ(report["sorties"].size(), 2u);
  for (const auto& s : report["sorties"]) {
    const int k = s["uav"].get<int>();
    EXPECT_EQ(s["launch_site"], nlohmann::json::array({0, 0}));
    // The capped files hold the sortie's waypoints, each later part repeating the last waypoint
    // of the one before.
    const auto prefix = dir + "/files/uav" + std::to_string(k);
    const int litchi_parts = s["files"]["litchi"].get<int>();
    const int qgc_parts = s["files"]["qgc"].get<int>();
    EXPECT_EQ(litchi_parts, qgc_parts);
    ASSERT_GT(litchi_parts, 1);
    std::size_t rows = 0, items = 0;
    for (int p = 1; p <= litchi_parts; ++p) {
      const auto part = prefix + "-part" + std::to_string(p);
      rows += lines_of(io::read_file(part + ".litchi.csv")).size() - 1;
      items += io::read_qgc_plan(io::read_file(part + ".plan"), part).waypoints.size();
    }
    const auto repeated = static_cast<std::size_t>(litchi_parts - 1);
    EXPECT_EQ(rows - repeated, s["waypoints"].get<std::size_t>());
    EXPECT_EQ(items - repeated, s["waypoints"].get<std::size_t>());
    // At one cell per second a sortie takes at least its distance over the cruise speed.
    EXPECT_GE(s["flight_time_s"].get<double>(), s["distance_m"].get<double>() / 0.5 - 0.1);
  }
  EXPECT_EQ(report["cells"]["hull"], 6361);
  EXPECT_EQ(report["cells"]["unseen"], 0);
  const auto warnings = report["warnings"].dump();
  EXPECT_NE(warnings.find("exceed the litchi cap of 9"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("qgc: the planned home's altitude is its height above the WGS-84 "
                          "ellipsoid"),
            std::string::npos)
      << warnings;
  EXPECT_NE(warnings.find("35 no-fly positions are not in the litchi, qgc files"),
            std::string::npos)
      << warnings;
  const auto md = io::read_file(dir + "/report/preflight.md");
  EXPECT_NE(md.find("| UAV | sortie | launch site |"), std::string::npos);
  pugi::xml_document svg;
  EXPECT_TRUE(svg.load_file((dir + "/report/preflight.svg").c_str()));
  int lines = 0;
  for (auto l = svg.child("svg").child("polyline"); l; l = l.next_sibling("polyline")) ++lines;
  EXPECT_EQ(lines, 2);
  fs::remove_all(dir);
}

// The report's separation: the D planned with and the smallest separation the flights keep,
// recomputed here from the trace's states; with no D, a shared cell is a warning.
TEST(PreflightReport, SeparationIsTheSmallestGapOfTheTrace) {
  for (const char* d : {"0", "2"}) {
    const auto dir = make_temp_dir("preflight-separation");
    const auto r = run_cli({"plan", "-a", "lawnmower", "-n", "8", "--separation", d, "--trace",
                            dir + "/trace.json", "--export", dir + "/files", "--format", "csv",
                            "--report", dir + "/report"});
    ASSERT_EQ(r.status, 0) << r.err;
    const auto report = nlohmann::json::parse(io::read_file(dir + "/report/preflight.json"));
    const auto trace = nlohmann::json::parse(io::read_file(dir + "/trace.json"));
    int smallest = 1 << 30;
    for (const auto& f : trace["frames"]) {
      const auto& u = f["u"];
      for (std::size_t a = 0; a < u.size(); a += 5) {
        for (std::size_t b = a + 5; b < u.size(); b += 5) {
          smallest =
              std::min(smallest, std::max(std::abs(u[a].get<int>() - u[b].get<int>()),
                                          std::abs(u[a + 1].get<int>() - u[b + 1].get<int>())));
        }
      }
    }
    const auto& sep = report["separation"];
    EXPECT_EQ(sep["d"], std::stoi(d));
    EXPECT_EQ(sep["min_cells"], smallest);
    EXPECT_DOUBLE_EQ(sep["min_m"].get<double>(), smallest * 0.5);
    EXPECT_EQ(sep["conflicts"], 0);
    if (std::string(d) == "2") {
      EXPECT_GE(smallest, 2);
    }
    const bool warned = report["warnings"].dump().find("no separation") != std::string::npos;
    EXPECT_EQ(warned, smallest == 0 && std::string(d) == "0");
    for (const auto& s : report["sorties"]) EXPECT_TRUE(s["battery_margin_s"].is_null());
    const auto md = io::read_file(dir + "/report/preflight.md");
    EXPECT_NE(md.find("## Separation"), std::string::npos);
    EXPECT_NE(md.find("Battery margin: none (unlimited flight"), std::string::npos);
    EXPECT_EQ(report["battery"]["limited"], false);
    fs::remove_all(dir);
  }
}

TEST(PlanPrior, WithoutPriorThePlanIsPureCoverageWhateverTheSeed) {
  const auto one = nlohmann::json::parse(run_cli({"plan", "--json", "-n", "2", "--seed", "1"}).out);
  const auto two = nlohmann::json::parse(run_cli({"plan", "--json", "-n", "2", "--seed", "2"}).out);
  EXPECT_EQ(one["prior"], "empty");
  EXPECT_EQ(one["corroded_cells"], 0);
  EXPECT_EQ(one["T_m"], two["T_m"]);
  const auto text = run_cli({"plan", "-n", "2"});
  EXPECT_NE(text.out.find("planned on an empty prior (pure coverage"), std::string::npos)
      << text.out;
  // A synthetic scenario only when asked for.
  const auto asked =
      nlohmann::json::parse(run_cli({"plan", "--json", "-n", "2", "--scenario", "imperfect"}).out);
  EXPECT_EQ(asked["prior"], "synthetic");
  EXPECT_GT(asked["corroded_cells"].get<int>(), 0);
}

}  // namespace
}  // namespace hullinspect::testing
