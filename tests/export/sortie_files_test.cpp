// The flight files of a battery-limited mission (docs/export.md "Sorties, launch sites and
// waypoint caps"): one set of files per UAV and sortie, each a flight from its launch site back to
// it, together the path the planned mission flies; split by a waypoint cap into parts that resume
// where the last one ended; listed per sortie by the pre-flight report; written the same by
// `export` of the mission's trace; photographing only on the legs at work.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/io/export.hpp"
#include "hullinspect/io/export_readers.hpp"
#include "hullinspect/io/geo_reference.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "support/cli_runner.hpp"
#include "support/text_fields.hpp"
#include "support/zip_entries.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

const io::GeoPoint kOrigin{53.5461, 9.9665, 3.0};
constexpr double kHeading = 117;
const grid::Cell kSite{0, 0};

// A grid position on a plane.
struct Position {
  int x = 0, y = 0, z = 2;
  friend bool operator==(const Position&, const Position&) = default;
};

void push_new(std::vector<Position>& path, Position p) {
  if (path.empty() || !(path.back() == p)) path.push_back(p);
}

// The positions a csv file's flight passes, in order: every cell of every leg (a leg is one
// straight line of moves, a plane change stays on its cell).
std::vector<Position> csv_path(const std::string& text) {
  const auto rows = lines_of(text);
  const auto header = split(rows.at(0), ',');
  const auto column = [&header](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const auto cx = column("cell_x"), cy = column("cell_y"), plane = column("plane");
  std::vector<Position> path;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto f = split(rows[i], ',');
    const Position to{std::stoi(f.at(cx)), std::stoi(f.at(cy)), std::stoi(f.at(plane))};
    if (!path.empty() && path.back().z == to.z) {
      Position at = path.back();
      while (at.x != to.x || at.y != to.y) {
        at.x += (to.x > at.x) - (to.x < at.x);
        at.y += (to.y > at.y) - (to.y < at.y);
        push_new(path, at);
      }
    }
    push_new(path, to);
  }
  return path;
}

// The positions the trace's UAV k passes between frames `begin` and `end` (on a plane only).
std::vector<Position> trace_path(const nlohmann::json& trace, std::size_t k, int begin, int end) {
  const auto states = io::trace_states(trace);
  std::vector<Position> path;
  for (int t = begin; t <= end; ++t) {
    const auto& s = states.at(k).at(static_cast<std::size_t>(t));
    if (s.in_transit) continue;  // between planes
    push_new(path, {s.pos.x, s.pos.y, s.z});
  }
  return path;
}

// The battery-limited mission of every test: two UAVs from one launch site, each flying several
// sorties.
class SortieFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = make_temp_dir("sortie-files");
    const auto r = run_cli({"plan",
                            "-a",
                            "lawnmower",
                            "-n",
                            "2",
                            "--launch",
                            "0,0",
                            "--endurance",
                            "700",
                            "--json",
                            "--trace",
                            dir_ + "/trace.json",
                            "--export",
                            dir_ + "/files",
                            "--format",
                            "all",
                            "--origin",
                            "53.5461,9.9665,3",
                            "--heading",
                            "117",
                            "--max-waypoints",
                            "1000",
                            "--report",
                            dir_ + "/report"});
    ASSERT_EQ(r.status, 0) << r.err;
    result_ = nlohmann::json::parse(r.out);
    trace_ = io::read_trace(dir_ + "/trace.json");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static std::string file(const std::string& name) {
    return io::read_file(dir_ + "/files/" + name);
  }
  static const nlohmann::json& sorties(std::size_t k) { return result_["launch"][k]["sorties"]; }
  // The take-off and landing point below the launch site.
  static io::GeoPoint home() {
    const auto plan = io::export_plan(trace_);
    const auto p = plan.frame.pose(kSite, 2);
    return io::GeoReference(kOrigin, kHeading).to_wgs84(p.x, p.y, plan.frame.spec().z0);
  }

  static std::string dir_;
  static nlohmann::json result_;
  static nlohmann::json trace_;
};
std::string SortieFiles::dir_;
nlohmann::json SortieFiles::result_;
nlohmann::json SortieFiles::trace_;

TEST_F(SortieFiles, EverySortieHasItsOwnFileInEveryFormat) {
  int total = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_GT(sorties(k).size(), 1u) << "the battery makes every UAV land and take off again";
    for (std::size_t n = 1; n <= sorties(k).size(); ++n, ++total) {
      for (const char* ext : {"csv", "plan", "waypoints", "path.yaml", "litchi.csv", "kmz"}) {
        EXPECT_TRUE(fs::exists(fmt::format("{}/files/uav{}_sortie{}.{}", dir_, k, n, ext)))
            << k << " " << n << " " << ext;
      }
    }
    EXPECT_FALSE(fs::exists(fmt::format("{}/files/uav{}.csv", dir_, k)));
    EXPECT_FALSE(
        fs::exists(fmt::format("{}/files/uav{}_sortie{}.csv", dir_, k, sorties(k).size() + 1)));
  }
  EXPECT_EQ(total, result_["sorties"].get<int>());
  // The kml preview: one line per UAV and sortie.
  pugi::xml_document kml;
  ASSERT_TRUE(kml.load_string(file("mission.kml").c_str()));
  int lines = 0;
  for (const auto& node : kml.select_nodes("//Placemark[LineString]")) {
    const std::string name = node.node().child_value("name");
    EXPECT_EQ(name.find("UAV "), 0u) << name;
    ++lines;
  }
  EXPECT_EQ(lines, total);
}

TEST_F(SortieFiles, TheSortiesTogetherFlyThePlannedPath) {
  for (std::size_t k = 0; k < 2; ++k) {
    int previous_landing = -1;
    for (std::size_t n = 0; n < sorties(k).size(); ++n) {
      const int takeoff = sorties(k)[n]["takeoff"].get<int>();
      ASSERT_FALSE(sorties(k)[n]["landing"].is_null());
      const int landing = sorties(k)[n]["landing"].get<int>();
      const auto flown = csv_path(file(fmt::format("uav{}_sortie{}.csv", k, n + 1)));
      EXPECT_EQ(flown, trace_path(trace_, k, takeoff, landing)) << "UAV " << k << " sortie " << n;
      ASSERT_FALSE(flown.empty());
      EXPECT_EQ(flown.front(), (Position{kSite.x, kSite.y, 2})) << k << " " << n;
      EXPECT_EQ(flown.back(), (Position{kSite.x, kSite.y, 2})) << k << " " << n;
      // Between two sorties the UAV is on the ground at its site: no flight is left out.
      if (previous_landing >= 0) {
        EXPECT_EQ(trace_path(trace_, k, previous_landing, takeoff),
                  (std::vector<Position>{{kSite.x, kSite.y, 2}}));
      }
      previous_landing = landing;
    }
  }
}

TEST_F(SortieFiles, EveryMissionTakesOffAndLandsAtItsSite) {
  const auto h = home();
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t n = 1; n <= sorties(k).size(); ++n) {
      const auto stem = fmt::format("uav{}_sortie{}", k, n);
      for (const auto& read : {io::read_qgc_plan(file(stem + ".plan"), stem),
                               io::read_wpl(file(stem + ".waypoints"), stem)}) {
        ASSERT_GE(read.items.size(), 3u) << stem;
        EXPECT_NEAR(read.home.lat, h.lat, 1e-8) << stem;
        EXPECT_NEAR(read.home.lon, h.lon, 1e-8) << stem;
        const auto nav = [](const io::ReadItem& i) { return i.command == 16 || i.command >= 20; };
        const auto first = std::find_if(read.items.begin(), read.items.end(), nav);
        EXPECT_EQ(first->command, 22) << stem;             // NAV_TAKEOFF
        EXPECT_EQ(read.items.back().command, 21) << stem;  // NAV_LAND (--finish land)
        const auto& last = read.waypoints.back().geo;      // the last waypoint is above the site
        EXPECT_NEAR(last.lat, h.lat, 1e-8) << stem;
        EXPECT_NEAR(last.lon, h.lon, 1e-8) << stem;
      }
      // Litchi has no take-off item: its first and last waypoints are above the site.
      const auto litchi = lines_of(file(stem + ".litchi.csv"));
      ASSERT_GE(litchi.size(), 3u) << stem;
      for (const auto& row : {litchi[1], litchi.back()}) {
        const auto f = split(row, ',');
        EXPECT_NEAR(std::stod(f.at(0)), h.lat, 1e-8) << stem << ": " << row;
        EXPECT_NEAR(std::stod(f.at(1)), h.lon, 1e-8) << stem << ": " << row;
      }
    }
  }
}

TEST_F(SortieFiles, ACapSplitsASortieIntoPartsThatResume) {
  const std::string out = dir_ + "/capped";
  const auto r = run_cli({"plan", "-a", "lawnmower", "-n", "2", "--launch", "0,0", "--endurance",
                          "700", "--export", out, "--format", "csv", "--max-waypoints", "5",
                          "--origin", "53.5461,9.9665,3", "--heading", "117"});
  ASSERT_EQ(r.status, 0) << r.err;
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t n = 1; n <= sorties(k).size(); ++n) {
      const auto whole = lines_of(file(fmt::format("uav{}_sortie{}.csv", k, n)));
      ASSERT_GT(whole.size(), 6u) << "a sortie longer than the cap";
      // The parts, each but the first starting with the last waypoint of the one before.
      std::vector<std::string> joined;
      int parts = 0;
      for (int p = 1;; ++p, ++parts) {
        const auto path = fmt::format("{}/uav{}_sortie{}-part{}.csv", out, k, n, p);
        if (!fs::exists(path)) break;
        const auto rows = lines_of(io::read_file(path));
        EXPECT_LE(rows.size(), 6u) << path;  // header + at most 5 waypoints
        const auto body = [](const std::string& row) {
          return row.substr(row.find(','));  // without the index column
        };
        for (std::size_t i = 1; i < rows.size(); ++i) {
          if (p > 1 && i == 1) {
            EXPECT_EQ(body(rows[i]), body(joined.back())) << path;
            continue;
          }
          joined.push_back(rows[i]);
        }
      }
      EXPECT_GT(parts, 1) << k << " " << n;
      ASSERT_EQ(joined.size() + 1, whole.size()) << k << " " << n;
      for (std::size_t i = 0; i < joined.size(); ++i) {
        EXPECT_EQ(joined[i].substr(joined[i].find(',')),
                  whole[i + 1].substr(whole[i + 1].find(',')));
      }
    }
  }
  EXPECT_FALSE(fs::exists(out + "/uav0_sortie1.csv"));
}

TEST_F(SortieFiles, ThePreflightReportListsTheFilesOfEverySortie) {
  const auto report = nlohmann::json::parse(io::read_file(dir_ + "/report/preflight.json"));
  std::size_t row = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t n = 1; n <= sorties(k).size(); ++n, ++row) {
      const auto& s = report["sorties"].at(row);
      EXPECT_EQ(s["uav"], k);
      EXPECT_EQ(s["sortie"], n);
      EXPECT_EQ(s["file_names"]["qgc"],
                nlohmann::json::array({fmt::format("uav{}_sortie{}.plan", k, n)}));
      EXPECT_EQ(s["file_names"]["csv"],
                nlohmann::json::array({fmt::format("uav{}_sortie{}.csv", k, n)}));
      EXPECT_EQ(s["waypoints"].get<std::size_t>() + 1,
                lines_of(file(fmt::format("uav{}_sortie{}.csv", k, n))).size());
    }
  }
  EXPECT_EQ(row, report["sorties"].size());
  const auto warnings = report["warnings"].dump();
  EXPECT_EQ(warnings.find("as one flight"), std::string::npos) << warnings;
  const auto md = io::read_file(dir_ + "/report/preflight.md");
  EXPECT_NE(md.find("uav1_sortie2.plan"), std::string::npos) << md;
}

// The names and contents of the files in `dir`.
std::map<std::string, std::string> files_in(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    out[e.path().filename().string()] = io::read_file(e.path().string());
  }
  return out;
}

// `export` of `trace` into `out` with the fixture's formats and options: the files `plan
// --export` wrote, byte for byte.
void expect_export_writes_the_planned_files(const std::string& trace, const std::string& out,
                                            const std::string& planned_dir) {
  const auto r = run_cli({"export", trace, "--out", out, "--format", "all", "--origin",
                          "53.5461,9.9665,3", "--heading", "117", "--max-waypoints", "1000"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto planned = files_in(planned_dir);
  const auto exported = files_in(out);
  ASSERT_TRUE(planned.contains("uav1_sortie2.plan"));
  ASSERT_EQ(planned.size(), exported.size());
  for (const auto& [name, content] : planned) {
    ASSERT_TRUE(exported.contains(name)) << name;
    EXPECT_TRUE(exported.at(name) == content) << name;
  }
}

TEST_F(SortieFiles, ExportOfTheTraceCutsTheSameSortiesAsPlan) {
  // `export` cuts the trace at the take-offs and landings its airborne flags record: the same
  // files as `plan --export` cut at the mission's own sorties.
  expect_export_writes_the_planned_files(dir_ + "/trace.json", dir_ + "/from-trace",
                                         dir_ + "/files");
}

TEST_F(SortieFiles, ExportOfARunTraceEqualsThePlannedFiles) {
  // Lawnmower's route does not depend on what it senses: the mission `run` flies is the one
  // `plan` plans, and the export of its trace is the plan's files.
  const auto r = run_cli({"run", "-a", "lawnmower", "-n", "2", "--launch", "0,0", "--endurance",
                          "700", "--trace", dir_ + "/run-trace.json"});
  ASSERT_EQ(r.status, 0) << r.err;
  expect_export_writes_the_planned_files(dir_ + "/run-trace.json", dir_ + "/from-run",
                                         dir_ + "/files");
}

TEST_F(SortieFiles, ATraceWithLaunchSitesKeepsThem) {
  const auto r =
      run_cli({"export", dir_ + "/trace.json", "--out", dir_ + "/moved", "--launch", "5,0"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "hullinspect: --launch: the trace's mission has its own launch sites (0,0): its "
            "flights start and end there\n");
  EXPECT_FALSE(fs::exists(dir_ + "/moved"));
}

// Per leg of a file (the leg leaving its waypoint i), whether the camera photographs on it.
std::vector<bool> litchi_photos(const std::string& text) {
  std::vector<bool> out;
  const auto rows = lines_of(text);
  // The last row leaves no leg (and photographs nothing).
  for (std::size_t i = 1; i + 1 < rows.size(); ++i) {
    out.push_back(split(rows[i], ',').at(45) != "-1");
  }
  return out;
}
std::vector<bool> mavlink_photos(const io::ReadPlan& plan) {
  // The trigger's state on reaching each NAV_WAYPOINT: the leg before it photographed.
  std::vector<bool> on_arrival;
  bool on = false;
  for (const auto& item : plan.items) {
    if (item.command == 206) on = item.params[0] > 0;  // DO_SET_CAM_TRIGG_DIST
    if (item.command == 16) on_arrival.push_back(on);
  }
  return std::vector<bool>(on_arrival.begin() + 1, on_arrival.end());
}
std::vector<bool> dji_photos(const std::string& kmz_path, std::size_t waypoints) {
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_string(unzip(kmz_path)["wpmz/waylines.wpml"].c_str())) << kmz_path;
  std::vector<bool> out(waypoints - 1, false);
  for (const auto& node : doc.select_nodes("//*[local-name()='actionGroup']")) {
    const auto g = node.node();
    if (std::string(g.child("wpml:actionTrigger").child_value("wpml:actionTriggerType")) !=
        "multipleDistance") {
      continue;
    }
    const auto begin = std::stoul(g.child_value("wpml:actionGroupStartIndex"));
    const auto end = std::stoul(g.child_value("wpml:actionGroupEndIndex"));
    for (auto i = begin; i < end; ++i) out.at(i) = true;
  }
  return out;
}

// The frame in which the mission's last cell became known: the first with the last `known`.
std::size_t homing_frame(const nlohmann::json& trace) {
  const auto& known = trace["series"]["known"];
  std::size_t t = 0;
  while (known[t] != known.back()) ++t;
  return t;
}

// Whether UAV k senses in frame t (docs/model.md §12): at work, and in the frame in which the
// mission's last cell became known when it moved into it (that step ends with every UAV turned
// home after it sensed). A UAV sent home for its battery senses nothing from the step it is sent.
bool senses(const std::vector<io::GridState>& states, std::size_t t, std::size_t homing) {
  if (!states[t].away) return true;
  if (t != homing || t == 0 || states[t - 1].away || !states[t].airborne || states[t].in_transit)
    return false;
  return states[t].pos != states[t - 1].pos || states[t].z != states[t - 1].z;
}

TEST_F(SortieFiles, OnlyTheLegsAtWorkTakePhotos) {
  // The flight out from the site and home senses nothing (docs/model.md §12): no format takes
  // photos there, and every leg at work does.
  const auto states = io::trace_states(trace_);
  const std::size_t homing = homing_frame(trace_);
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t n = 1; n <= sorties(k).size(); ++n) {
      const auto stem = fmt::format("uav{}_sortie{}", k, n);
      const auto rows = io::read_export_csv(file(stem + ".csv"), stem);
      std::vector<bool> want;
      for (std::size_t i = 0; i + 1 < rows.waypoints.size(); ++i) {
        bool work = true;
        for (auto t = static_cast<std::size_t>(rows.waypoints[i].t);
             t <= static_cast<std::size_t>(rows.waypoints[i + 1].t); ++t) {
          work = work && senses(states[k], t, homing);
        }
        want.push_back(work);
      }
      ASSERT_GT(std::count(want.begin(), want.end(), true), 0) << stem;
      ASSERT_GT(std::count(want.begin(), want.end(), false), 0) << stem;
      EXPECT_EQ(litchi_photos(file(stem + ".litchi.csv")), want) << stem;
      EXPECT_EQ(mavlink_photos(io::read_qgc_plan(file(stem + ".plan"), stem)), want) << stem;
      EXPECT_EQ(mavlink_photos(io::read_wpl(file(stem + ".waypoints"), stem)), want) << stem;
      EXPECT_EQ(dji_photos(dir_ + "/files/" + stem + ".kmz", rows.waypoints.size()), want) << stem;
    }
  }
}

TEST(SortieFilesUnlimited, WithoutAnEnduranceEachUavFliesOneFile) {
  const auto dir = make_temp_dir("sortie-files-unlimited");
  const auto r = run_cli({"plan", "-a", "lawnmower", "-n", "2", "--launch", "0,0", "--export",
                          dir + "/files", "--format", "csv"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/files/uav0.csv"));
  EXPECT_TRUE(fs::exists(dir + "/files/uav1.csv"));
  EXPECT_FALSE(fs::exists(dir + "/files/uav0_sortie1.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
