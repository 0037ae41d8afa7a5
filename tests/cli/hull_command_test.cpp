// `hullinspect hull import` and mesh hulls / user maps through `run`, end to end.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "support/cli_runner.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// `run` on the imported file and on the mesh itself (with `mesh_options`) flies the same mission.
void expect_same_mission(const std::string& hull_json, const std::string& mesh,
                         const std::vector<std::string>& mesh_options,
                         const std::vector<std::string>& mission) {
  auto from_json = mission, from_mesh = mission;
  from_json.insert(from_json.begin(), {"run", "--hull", hull_json});
  from_mesh.insert(from_mesh.begin(), mesh_options.begin(), mesh_options.end());
  from_mesh.insert(from_mesh.begin(), {"run", "--hull", mesh});
  const auto a = run_cli(from_json), b = run_cli(from_mesh);
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  ja.erase("planner_seconds");
  jb.erase("planner_seconds");
  EXPECT_EQ(ja, jb);
}

TEST(HullImport, WritesAHullThatRunAccepts) {
  const auto dir = make_temp_dir("hull-import");
  const std::string stl = wigley_stl(WigleyHull{}).string();
  const auto r = run_cli({"hull", "import", stl, "--out", dir + "/wigley"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, stl +
                       ": 32398 facets, 16000 facing starboard\n"
                       "  grid 200 × 16 cells of 0.5 m, 3200 hull cells (800.0 m²)\n"
                       "  origin X0 = -50.000 m, Z0 = -8.000 m; side plane Y = -0.002 m; depth "
                       "up to 4.992 m\n"
                       "  wrote " +
                       dir + "/wigley.json\n");
  ASSERT_TRUE(fs::exists(dir + "/wigley.json"));
  const auto json = nlohmann::json::parse(std::ifstream(dir + "/wigley.json"));
  EXPECT_EQ(json["format"], "hullinspect-hull");
  EXPECT_EQ(json["width"], 200);
  // The imported hull and the mesh itself run the same mission.
  expect_same_mission(dir + "/wigley.json", stl, {},
                      {"--uavs", "2", "--s2", "9", "--seed", "3", "--json"});
  const auto run = run_cli({"run", "--hull", dir + "/wigley.json", "--uavs", "2", "--json"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(nlohmann::json::parse(run.out)["hull_cells"], 3200);
  fs::remove_all(dir);
}

// The unrolled hull (--sides both) is written too, and runs the mission the mesh runs.
TEST(HullImport, WritesAnUnrolledHullThatRunAccepts) {
  const auto dir = make_temp_dir("hull-import-both");
  const std::string stl = wigley_stl(WigleyHull{}).string();
  const auto r = run_cli({"hull", "import", stl, "--sides", "both", "--out", dir + "/both"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.ends_with("  wrote " + dir + "/both.json\n")) << r.out;
  ASSERT_TRUE(fs::exists(dir + "/both.json"));
  const auto json = nlohmann::json::parse(std::ifstream(dir + "/both.json"));
  EXPECT_EQ(json["side"], "both");
  expect_same_mission(dir + "/both.json", stl, {"--sides", "both"},
                      {"--uavs", "3", "--seed", "2", "--json"});
  fs::remove_all(dir);
}

// With the transom the grid closes at a seam that a flight links: the import says so, and the
// hull file records it (a hull without the transom has no seam).
TEST(HullImport, SaysTheTransomSeamIsLinked) {
  const auto dir = make_temp_dir("hull-import-transom");
  const std::string stl = wigley_stl(WigleyHull{}).string();
  const auto both = run_cli({"hull", "import", stl, "--sides", "both", "--out", dir + "/both"});
  ASSERT_EQ(both.status, 0) << both.err;
  EXPECT_EQ(both.out.find("seam"), std::string::npos) << both.out;
  const auto r = run_cli(
      {"hull", "import", stl, "--sides", "both", "--include", "transom", "--out", dir + "/closed"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto json = nlohmann::json::parse(std::ifstream(dir + "/closed.json"));
  const int last = json["width"].get<int>() - 1;
  EXPECT_NE(r.out.find("  seam: columns 0 and " + std::to_string(last) +
                       " meet at the transom, linked by a flight at stand-off\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(json["seam"], true);
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(dir + "/both.json"))["seam"], false);
  fs::remove_all(dir);
}

struct BadImport {
  std::vector<std::string> args;
  std::string message;  // stderr after "hullinspect: "
};

class HullImportBadInput : public ::testing::TestWithParam<BadImport> {};

TEST_P(HullImportBadInput, OneLineExitTwoNothingWritten) {
  const auto dir = make_temp_dir("hull-import-bad");
  const std::string stl = wigley_stl(WigleyHull{}).string();
  std::vector<std::string> args = {"hull", "import"};
  for (std::string a : GetParam().args) {
    if (a == "MESH") a = stl;
    args.push_back(a);
  }
  args.insert(args.end(), {"--out", dir + "/out"});
  const auto r = run_cli(args);
  std::string expected = GetParam().message;
  if (auto at = expected.find("MESH"); at != std::string::npos) expected.replace(at, 4, stl);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + expected + "\n");
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Table, HullImportBadInput,
    ::testing::Values(
        BadImport{{"MESH", "--side", "aft"}, "--side: expected port, starboard or both, got 'aft'"},
        BadImport{{"MESH", "--axes", "x,y"},
                  "--axes: expected a signed permutation of x,y,z like x,-z,y, got 'x,y'"},
        BadImport{{"MESH", "--cell-size", "0"},
                  "--cell-size: expected a positive number of metres"},
        BadImport{{"MESH", "--scale", "-2"}, "--scale: expected a number > 0"},
        BadImport{{"MESH", "--min-coverage", "1.5"},
                  "--min-coverage: expected a fraction in (0, 1]"},
        BadImport{{"MESH", "--waterline", "1"},
                  "MESH: no facet faces the starboard side above the waterline (check --axes and "
                  "--side)"},
        BadImport{{"MESH", "--cell-size", "0.01"},
                  "MESH: the projection is 10000 × 800 cells of 0.01 m; each side must be within "
                  "1..4096 (check --scale and --cell-size)"},
        BadImport{{"/nonexistent/hull.stl"}, "/nonexistent/hull.stl: cannot open the file"}));

TEST(RunUserMaps, ReplaceTheGeneratedPriorAndTruth) {
  const auto dir = make_temp_dir("user-maps");
  // A 6 × 3 hull; the truth has two corroded cells, the prior points at one of them.
  write(dir + "/hull.txt", "XXXXXX\nXXXXXX\nXXXXXX\n");
  write(dir + "/truth.txt", "......\n.X....\n....X.\n");
  write(dir + "/prior.txt", "......\n.X....\n......\n");
  const auto r = run_cli({"run", "--hull", dir + "/hull.txt", "--uavs", "1", "--s1", "1", "--s2",
                          "3", "--truth", dir + "/truth.txt", "--prior", dir + "/prior.txt",
                          "--json", "--trace", dir + "/trace.json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto result = nlohmann::json::parse(r.out);
  EXPECT_EQ(result["corroded_cells"], 2);
  const auto trace = nlohmann::json::parse(std::ifstream(dir + "/trace.json"));
  // Trace rows are y = 0 first; the text maps are top row first.
  EXPECT_EQ(trace["truth"], nlohmann::json::parse(R"(["000010", "010000", "000000"])"));
  EXPECT_EQ(trace["prior"], nlohmann::json::parse(R"(["000000", "010000", "000000"])"));
  EXPECT_EQ(trace["parameters"]["truth_file"], dir + "/truth.txt");
  EXPECT_EQ(trace["parameters"]["prior_file"], dir + "/prior.txt");

  const auto mismatch = run_cli({"run", "--hull", dir + "/hull.txt", "--truth", dir + "/prior.txt",
                                 "--prior", dir + "/hull.txt", "--uavs", "1"});
  EXPECT_EQ(mismatch.status, 0) << mismatch.err;  // a prior of all hull cells is allowed
  write(dir + "/small.txt", "XX\n");
  const auto small = run_cli({"run", "--hull", dir + "/hull.txt", "--prior", dir + "/small.txt"});
  EXPECT_EQ(small.status, 2);
  EXPECT_EQ(small.err, "hullinspect: " + dir + "/small.txt: the map is 2 × 1 but the hull (" + dir +
                           "/hull.txt) is 6 × 3\n");
  write(dir + "/notch.txt", "XXXXX.\nXXXXXX\nXXXXXX\n");
  const auto outside = run_cli({"run", "--hull", dir + "/notch.txt", "--truth", dir + "/hull.txt"});
  EXPECT_EQ(outside.status, 2);
  EXPECT_EQ(outside.err, "hullinspect: " + dir +
                             "/hull.txt: cell (5, 2) is corroded but not part "
                             "of the hull\n");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
