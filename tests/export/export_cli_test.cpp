// `hullinspect export`, `run --export` and `plan` end to end: bad inputs get one exact line, exit
// status 2 and leave no file behind; `plan` flies the prior (docs/export.md).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/io/geo_reference.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

// One small mission's trace, shared by the tests of this file.
class ExportCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = make_temp_dir("export-cli");
    trace_ = dir_ + "/trace.json";
    const auto r = run_cli({"run", "-n", "2", "--seed", "3", "--trace", trace_});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string dir_;
  static std::string trace_;
};
std::string ExportCli::dir_;
std::string ExportCli::trace_;

struct BadExport {
  std::vector<std::string> args;  // after `export TRACE --out DIR`
  std::string message;            // the whole stderr
};

class ExportBadInput : public ExportCli, public ::testing::WithParamInterface<BadExport> {};

TEST_P(ExportBadInput, OneLineExitTwoNothingWritten) {
  const std::string out = dir_ + "/out";
  std::vector<std::string> args = {"export", trace_, "--out", out};
  args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
  const auto r = run_cli(args);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, GetParam().message + "\n");
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Table, ExportBadInput,
    ::testing::Values(
        BadExport{{"--format", "kmz"},
                  "hullinspect: --format: 'kmz' is not a format (expected csv, qgc, wpl, path, "
                  "litchi, dji-kmz, kml or all)"},
        BadExport{{"--format", "csv", "--format", "litchi"},
                  "hullinspect: --origin: the litchi format needs a geo-reference: give --origin "
                  "LAT,LON,ALT and --heading DEG (or --geo FILE)"},
        BadExport{{"--max-waypoints", "1"},
                  "hullinspect: --max-waypoints: 1 is below the 2 waypoints a mission file needs "
                  "(the point it starts from and one to fly to)"},
        BadExport{{"--launch", "3"}, "hullinspect: --launch: expects X,Y (got '3')"},
        BadExport{{"--launch", "3,x"},
                  "hullinspect: --launch: expects X,Y with integers X and Y in [0, 4095] (got "
                  "'3,x')"},
        BadExport{{"--launch", "500,0"},
                  "hullinspect: --launch: site (500, 0) is outside the 230 × 30 grid"},
        BadExport{{"--launch", "100,15"},
                  "hullinspect: --launch: site (100, 15) is a hull cell inside the grid (a site "
                  "is a non-hull cell or on the grid's edge)"},
        BadExport{{"--firmware", "apm"},
                  "hullinspect: --firmware: 'apm' is not a firmware (expected px4 or ardupilot)"},
        BadExport{{"--format", "qgc"},
                  "hullinspect: --origin: the qgc format needs a geo-reference: give --origin "
                  "LAT,LON,ALT and --heading DEG (or --geo FILE)"},
        BadExport{{"--format", "wpl", "--heading", "10"},
                  "hullinspect: --origin: --heading needs --origin LAT,LON,ALT too"},
        BadExport{{"--format", "wpl", "--origin", "1,2,3"},
                  "hullinspect: --heading: --origin needs --heading DEG too"},
        BadExport{{"--origin", "53.5;9.9;0", "--heading", "0"},
                  "hullinspect: --origin: expects LAT,LON,ALT in degrees, degrees, metres (got "
                  "'53.5;9.9;0')"},
        BadExport{
            {"--origin", "95,9.9,0", "--heading", "0"},
            "hullinspect: --origin: expects LAT,LON,ALT in degrees, degrees, metres: LAT must "
            "be a number in [-90, 90] (got '95')"},
        BadExport{{"--origin", "1,2,3", "--heading", "x"},
                  "hullinspect: --heading: must be a number in [-360, 360] (got 'x') (see --help)"},
        BadExport{{"--geo", "/nonexistent/geo.yaml"},
                  "hullinspect: /nonexistent/geo.yaml: cannot open the geo-reference file"},
        BadExport{
            {"--geo", "/dev/null", "--origin", "1,2,3"},
            "hullinspect: --geo: give either --geo FILE or --origin and --heading, not both"}));

// The export's outputs go through io::OutputSet like every command's (docs/reliability.md): the
// directory is created with its missing parents, and a directory that is a file, an output that
// is not a regular file, or one that is the trace itself is refused before anything is written.
TEST_F(ExportCli, RefusesAnOutDirectoryThatIsAFile) {
  auto r = run_cli({"export", trace_, "--out", trace_});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "hullinspect: --out: '" + trace_ + "' is a regular file, expected a directory\n");
  r = run_cli({"export", trace_, "--out", trace_ + "/sub"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: --out: cannot use '" + trace_ + "/sub': Not a directory\n");
  // A missing parent is created, as for every output directory.
  r = run_cli({"export", trace_, "--out", dir_ + "/new/deep/dir"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ + "/new/deep/dir/uav1.csv"));
  fs::remove_all(dir_ + "/new");
}

TEST_F(ExportCli, RefusesAnOutputThatIsADirectoryWritingNothing) {
  const std::string out = dir_ + "/blocked";
  fs::create_directories(out + "/uav1.csv");
  const auto r = run_cli({"export", trace_, "--out", out, "--force"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: --out: '" + out +
                       "/uav1.csv' is a directory; an output must be a regular file or a new "
                       "path\n");
  EXPECT_FALSE(fs::exists(out + "/uav0.csv"));  // all or nothing
  fs::remove_all(out);
}

TEST_F(ExportCli, RefusesToOverwriteTheTrace) {
  const std::string out = dir_ + "/clash";
  fs::create_directories(out);
  fs::create_hard_link(trace_, out + "/uav0.csv");
  const auto r = run_cli({"export", trace_, "--out", out, "--force"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: --out: '" + out + "/uav0.csv' is the same file as the trace '" +
                       trace_ + "'; it would be overwritten\n");
  EXPECT_NO_THROW(io::read_trace(trace_));  // untouched
  EXPECT_FALSE(fs::exists(out + "/uav1.csv"));
  fs::remove_all(out);
}

// A directory holding an earlier export is refused unless --force: the new export's files would
// otherwise sit beside uav2 … uav7 of the old one.
TEST_F(ExportCli, RefusesANonEmptyDirectoryUnlessForced) {
  const std::string out = dir_ + "/earlier";
  fs::create_directories(out);
  for (int k = 0; k < 8; ++k)
    io::write_file_atomic(out + "/uav" + std::to_string(k) + ".csv", "old\n");
  auto r = run_cli({"export", trace_, "--out", out});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: --out: '" + out +
                       "' is not empty (it holds 'uav0.csv'); give a new or empty directory, or "
                       "--force to write into it\n");
  EXPECT_EQ(io::read_file(out + "/uav0.csv"), "old\n");
  r = run_cli({"export", trace_, "--out", out, "--force"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(io::read_file(out + "/uav0.csv"), "old\n");
  EXPECT_EQ(io::read_file(out + "/uav7.csv"), "old\n");  // --force replaces only its own names
  fs::remove_all(out);
}

TEST_F(ExportCli, RejectsAMalformedTrace) {
  const std::string bad = dir_ + "/bad.json";
  io::write_file_atomic(bad, "{\"format\": \"hullinspect-trace\", \"version\": 1}");
  const auto r = run_cli({"export", bad, "--out", dir_ + "/never"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + bad + ": parameters: missing\n");
  EXPECT_FALSE(fs::exists(dir_ + "/never"));
}

TEST_F(ExportCli, RejectsATraceThatCannotBePlacedInMetres) {
  const auto good = io::read_trace(trace_);
  auto bad = good;
  bad["grid"]["cell_size_m"] = 0;
  const std::string path = dir_ + "/cell.json";
  io::write_file_atomic(path, bad.dump());
  auto r = run_cli({"export", path, "--out", dir_ + "/never"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "hullinspect: " + path + ": grid.cell_size_m: expected metres in [0.001, 1000]\n");
  bad = good;
  bad["camera"]["theta_deg"] = 180;
  io::write_file_atomic(path, bad.dump());
  r = run_cli({"export", path, "--out", dir_ + "/never"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + path + ": camera.theta_deg: expected degrees in (0, 180)\n");
  EXPECT_FALSE(fs::exists(dir_ + "/never"));
}

TEST_F(ExportCli, NoFlyPositionsAreNeverAFenceAndTheKmlDrawsThemAsBoxes) {
  auto trace = io::read_trace(trace_);
  const int width = trace["grid"]["width"].get<int>();
  std::vector<std::string> rows(trace["grid"]["height"].get<std::size_t>(),
                                std::string(width, '.'));
  // Two cells no UAV of the flown mission was ever on (the reader refuses a UAV on a no-fly cell).
  std::set<std::pair<int, int>> visited;
  for (const auto& f : trace["frames"]) {
    const auto& u = f["u"];
    for (std::size_t k = 0; k < u.size(); k += 5)
      visited.insert({u[k].get<int>(), u[k + 1].get<int>()});
  }
  std::vector<std::pair<int, int>> cells;
  for (const auto& [x, y] : {std::pair{10, 4}, std::pair{200, 7}}) {
    int free_x = x;
    while (visited.contains({free_x, y})) ++free_x;
    cells.push_back({free_x, y});
    rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(free_x)] = '#';
  }
  trace["no_fly"] = rows;
  const std::string path = dir_ + "/nofly.json";
  io::write_file_atomic(path, trace.dump());
  const auto r = run_cli({"export", path, "--format", "qgc", "--format", "kml", "--origin",
                          "10,20,0", "--heading", "30", "--out", dir_ + "/fence"});
  ASSERT_EQ(r.status, 0) << r.err;
  // A horizontal fence polygon would also forbid the flight above and below the obstacle: none,
  // and the command says so.
  const auto plan = nlohmann::json::parse(io::read_file(dir_ + "/fence/uav0.plan"));
  EXPECT_TRUE(plan["geoFence"]["polygons"].empty());
  EXPECT_NE(r.out.find("note: the no-fly positions are not in the qgc files"), std::string::npos)
      << r.out;
  // The KML preview draws each as a box: back in the ship frame, the cell's extent along the hull
  // and in height, the band from half a cell inside the close-up plane to half a cell beyond the
  // detection plane (starboard: y < 0).
  pugi::xml_document kml;
  ASSERT_TRUE(kml.load_file((dir_ + "/fence/mission.kml").c_str()));
  const io::GeoReference geo({10, 20, 0}, 30);
  std::size_t i = 0;
  for (const auto folder : kml.child("kml").child("Document").children("Folder")) {
    if (std::string(folder.child_value("name")) != "No-fly zones") continue;
    for (const auto box : folder.children("Placemark")) {
      ASSERT_LT(i, cells.size());
      double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
      for (const auto face : box.child("MultiGeometry").children("Polygon")) {
        std::istringstream corners(
            face.child("outerBoundaryIs").child("LinearRing").child_value("coordinates"));
        for (std::string corner; corners >> corner;) {
          double lon = 0, lat = 0, height = 0;
          char c1 = 0, c2 = 0;
          std::istringstream(corner) >> lon >> c1 >> lat >> c2 >> height;
          double x = 0, y = 0, z = 0;
          geo.from_wgs84({lat, lon, 0}, x, y, z);
          xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y),
          ymax = std::max(ymax, y);
        }
      }
      const double x0 = cells[i].first * 0.5;
      EXPECT_NEAR(xmin, x0, 1e-3);
      EXPECT_NEAR(xmax, x0 + 0.5, 1e-3);
      EXPECT_NEAR(ymax, -1.25 + 0.25, 1e-3);
      EXPECT_NEAR(ymin, -1.75 - 0.25, 1e-3);
      ++i;
    }
  }
  EXPECT_EQ(i, cells.size());
}

TEST_F(ExportCli, WritesOneFilePerUavAndSaysSo) {
  const std::string out = dir_ + "/csv";
  const auto r = run_cli({"export", trace_, "--out", out});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "wrote 2 csv files to " + out + ": uav0.csv, uav1.csv\n");
  const std::string geo = dir_ + "/geo.yaml";
  io::write_file_atomic(geo, "origin: [53.5461, 9.9665, 3]\nheading: 117\n");
  const auto p =
      run_cli({"export", trace_, "--format", "path", "--geo", geo, "--out", dir_ + "/path"});
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_EQ(p.out, "wrote 3 path files to " + dir_ +
                       "/path: uav0.path.yaml, uav1.path.yaml, hull_to_map.yaml\n");
  // --geo and --origin/--heading give the same files.
  const auto q = run_cli({"export", trace_, "--format", "path", "--origin", "53.5461,9.9665,3",
                          "--heading", "117", "--out", dir_ + "/path2"});
  ASSERT_EQ(q.status, 0) << q.err;
  for (const char* f : {"uav0.path.yaml", "hull_to_map.yaml"}) {
    EXPECT_EQ(io::read_file(dir_ + "/path/" + f), io::read_file(dir_ + "/path2/" + f)) << f;
  }
}

TEST_F(ExportCli, RunExportWritesWhatExportOfItsTraceWrites) {
  const std::string out = dir_ + "/run-export";
  const auto r = run_cli({"run", "-n", "2", "--seed", "3", "--export", out, "--format", "wpl",
                          "--origin", "-33.86,151.21,0", "--heading", "45"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto e = run_cli({"export", trace_, "--format", "wpl", "--origin", "-33.86,151.21,0",
                          "--heading", "45", "--out", dir_ + "/export"});
  ASSERT_EQ(e.status, 0) << e.err;
  for (const char* f : {"uav0.waypoints", "uav1.waypoints"}) {
    EXPECT_EQ(io::read_file(out + "/" + f), io::read_file(dir_ + "/export/" + f)) << f;
  }
  // A bad export option is refused before the mission runs.
  const auto bad = run_cli({"run", "-n", "2", "--export", dir_ + "/x", "--format", "qgc"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.out, "");
  EXPECT_FALSE(fs::exists(dir_ + "/x"));
  const auto stray = run_cli({"run", "-n", "2", "--origin", "1,2,3"});
  EXPECT_EQ(stray.status, 2);
  EXPECT_EQ(stray.err, "hullinspect: --origin: has no effect without --export DIR\n");
}

TEST_F(ExportCli, PlanRefusesBadExportOptionsBeforePlanning) {
  const auto r = run_cli({"plan", "-n", "2", "--export", dir_ + "/p", "--format", "wpl", "--geo",
                          "/nonexistent.yaml"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: /nonexistent.yaml: cannot open the geo-reference file\n");
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(dir_ + "/p"));
}

TEST_F(ExportCli, PlanFliesThePriorAndExportsItsWaypoints) {
  // With an imperfect prior the plan (truth = prior) and the flight (the real truth) differ.
  const std::vector<std::string> mission = {"-a",         "part-tsp", "-n",     "3",
                                            "--scenario", "combined", "--seed", "7"};
  auto plan_args =
      std::vector<std::string>{"plan",     "--json",       "--trace",  dir_ + "/plan.json",
                               "--export", dir_ + "/plan", "--format", "csv"};
  plan_args.insert(plan_args.end(), mission.begin(), mission.end());
  const auto p = run_cli(plan_args);
  ASSERT_EQ(p.status, 0) << p.err;
  const auto planned = nlohmann::json::parse(p.out);
  EXPECT_EQ(planned["planned_on"], "prior");
  const auto trace = io::read_trace(dir_ + "/plan.json");
  EXPECT_EQ(trace["truth"], trace["prior"]);
  EXPECT_EQ(planned["T_m"], trace["result"]["T_m"]);
  EXPECT_EQ(planned["T_c"], trace["result"]["T_c"]);
  // Its waypoints end at the planned T_m.
  for (int k = 0; k < 3; ++k) {
    const auto csv = io::read_file(dir_ + "/plan/uav" + std::to_string(k) + ".csv");
    const auto last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
    EXPECT_EQ(
        last.substr(last.find(',') + 1, last.find(',', last.find(',') + 1) - last.find(',') - 1),
        std::to_string(planned["T_m"].get<int>()))
        << last;
  }
  auto run_args = std::vector<std::string>{"run", "--json"};
  run_args.insert(run_args.end(), mission.begin(), mission.end());
  const auto flown = nlohmann::json::parse(run_cli(run_args).out);
  EXPECT_NE(flown["corroded_cells"], planned["corroded_cells"]);
  // With a perfect prior the plan is the flight.
  const auto perfect_plan = nlohmann::json::parse(
      run_cli({"plan", "--json", "-n", "2", "--seed", "3", "--scenario", "perfect"}).out);
  const auto perfect_run =
      nlohmann::json::parse(run_cli({"run", "--json", "-n", "2", "--seed", "3"}).out);
  EXPECT_EQ(perfect_plan["T_m"], perfect_run["T_m"]);
  EXPECT_EQ(perfect_plan["T_c"], perfect_run["T_c"]);
  // The text summary names the expected times.
  const auto text = run_cli({"plan", "-n", "2", "--seed", "3", "--scenario", "perfect"});
  EXPECT_NE(text.out.find("planned on a synthetic prior (scenario perfect)"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("expected T_c = " + std::to_string(perfect_run["T_c"].get<int>()) + " s"),
            std::string::npos)
      << text.out;
}

}  // namespace
}  // namespace hullinspect::testing
