// `hullinspect partition` end to end: runs the built CLI (HULLINSPECT_CLI, set by ctest) and checks
// its summary, JSON, region mask, exit statuses and one-line errors.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/hull_geometry.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "support/seam_hull.hpp"

namespace hullinspect {
namespace {

namespace fs = std::filesystem;

std::string cli_path() {
  if (const char* cli = std::getenv("HULLINSPECT_CLI")) return cli;
  // Run directly from the build tree: the CLI sits one level above the tests folder.
  const fs::path beside =
      fs::read_symlink("/proc/self/exe").parent_path().parent_path() / "hullinspect";
  return fs::exists(beside) ? beside.string() : std::string();
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class PartitionCli : public ::testing::Test {
 protected:
  void SetUp() override {
    cli_ = cli_path();
    if (cli_.empty()) GTEST_SKIP() << "HULLINSPECT_CLI is not set (run through ctest)";
    dir_ = fs::temp_directory_path() /
           fmt::format("hullinspect_partition_cli_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  struct Result {
    int status;
    std::string out;
    std::string err;
  };
  Result run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt";
    const fs::path err = dir_ / "stderr.txt";
    const std::string command =
        fmt::format("'{}' partition {} >'{}' 2>'{}'", cli_, args, out.string(), err.string());
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(out), read_text(err)};
  }
  fs::path path(const std::string& name) const { return dir_ / name; }

  std::string cli_;
  fs::path dir_;
};

// Rows of a written region mask (comment lines skipped), top row first.
std::vector<std::string> mask_rows(const std::string& text) {
  std::vector<std::string> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != ';') rows.push_back(line);
  }
  return rows;
}

TEST_F(PartitionCli, JsonSummaryOfTheDefaultHull) {
  const auto r = run("--uavs 4 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["partitioner"], "darp");
  EXPECT_EQ(j["hull"], "builtin:default");
  EXPECT_EQ(j["uavs"], 4);
  EXPECT_EQ(j["converged"], true);
  EXPECT_EQ(j["tolerance"], 1.0);
  EXPECT_GT(j["iterations"].get<int>(), 0);
  EXPECT_TRUE(j["warnings"].empty());
  ASSERT_EQ(j["regions"].size(), 4u);
  int total = 0;
  for (const auto& region : j["regions"]) {
    EXPECT_EQ(region["connected"], true);
    EXPECT_LE(std::abs(region["cells"].get<int>() - region["desired"].get<double>()), 1.0);
    total += region["cells"].get<int>();
  }
  EXPECT_EQ(total, j["hull_cells"].get<int>());
}

// A hull file whose grid closes on itself (`"seam": true`): UAV 0, a column east of the seam,
// holds the columns just west of it, and its region counts as connected across the seam.
TEST_F(PartitionCli, ARegionAcrossTheSeamIsConnected) {
  std::string rows;
  for (int y = 0; y < 4; ++y) rows += std::string(40, 'X') + "\n";
  const fs::path hull = path("ring.json");
  std::ofstream(hull) << world::to_hull_json(testing::seam_cylinder_hull(rows));
  const auto r = run(fmt::format("--hull '{}' --uavs 2 --start 1,1 --start 20,1 --json --out '{}'",
                                 hull.string(), path("a.txt").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["converged"], true);
  for (const auto& region : j["regions"]) EXPECT_EQ(region["connected"], true);
  for (const std::string& row : mask_rows(read_text(path("a.txt")))) {
    EXPECT_EQ(row.front(), '0');
    EXPECT_EQ(row.back(), '0');
  }
}

TEST_F(PartitionCli, OutWritesTheAssignmentMatrixAsATextMask) {
  const auto r = run(fmt::format("--uavs 6 --seed 3 --json --out '{}'", path("a.txt").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto rows = mask_rows(read_text(path("a.txt")));
  const auto& hull = world::default_hull();
  ASSERT_EQ(static_cast<int>(rows.size()), hull.height());
  std::vector<int> counts(6, 0);
  grid::Grid<std::int16_t> owner(hull.width(), hull.height(), -1);
  for (int row = 0; row < hull.height(); ++row) {
    const int y = hull.height() - 1 - row;
    ASSERT_EQ(static_cast<int>(rows[static_cast<std::size_t>(row)].size()), hull.width());
    for (int x = 0; x < hull.width(); ++x) {
      const char c = rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(x)];
      ASSERT_EQ(c == '.', !hull.is_hull(x, y)) << "at (" << x << ", " << y << ")";
      if (c == '.') continue;
      ASSERT_TRUE(c >= '0' && c <= '5') << c;
      ++counts[static_cast<std::size_t>(c - '0')];
      owner(x, y) = static_cast<std::int16_t>(c - '0');
    }
  }
  for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(counts[k], j["regions"][k]["cells"].get<int>());
  // The same request through the library gives the same matrix (deterministic across processes).
  world::MissionParams params;
  params.uavs = 6;
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = world::start_cells(params, hull);
  request.seed = 3;
  EXPECT_EQ(partition::DarpPartitioner().partition(request).owner, owner);
}

TEST_F(PartitionCli, TextSummaryWithExplicitStarts) {
  const auto r = run("--uavs 2 --start 40,15 --start 150,12");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("darp: 2 UAVs on builtin:default (6361 hull cells), seed 0\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("converged after"), std::string::npos);
  EXPECT_NE(r.out.find("(40, 15)"), std::string::npos);
  EXPECT_NE(r.out.find("(150, 12)"), std::string::npos);
  EXPECT_EQ(r.out.find("NO"), std::string::npos);  // every region connected
}

// A no-fly wall across the hull at x = 100 cuts the flight space in two: each part's cells go to
// the UAVs starting in it (docs/model.md §8), three on the left, one on the right.
TEST_F(PartitionCli, AWallThatCutsTheFlightSpaceIsPartitionedPerPart) {
  const std::string args =
      "--uavs 4 --no-fly-box 100,0,100,29 --start 20,15 --start 60,15 --start 90,15 "
      "--start 180,15";
  const auto r = run(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("  the no-fly zones cut the flight space into 2 parts; each part's cells "
                       "go to its own UAVs:\n"
                       "    part 0: UAVs 0, 1, 2; 2889 hull cells seen from it\n"
                       "    part 1: UAVs 3; 3472 hull cells seen from it\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  UAV  start        cells     desired  connected  part\n"
                       "    0  (20, 15)       963      963.00  yes        0\n"
                       "    1  (60, 15)       963      963.00  yes        0\n"
                       "    2  (90, 15)       963      963.00  yes        0\n"
                       "    3  (180, 15)     3472     3472.00  yes        1\n"),
            std::string::npos)
      << r.out;
  const auto j = run(args + fmt::format(" --json --out '{}'", path("a.txt").string()));
  ASSERT_EQ(j.status, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["flight_components"], 2);
  EXPECT_EQ(doc["unreachable_cells"], 0);
  std::vector<int> parts;
  for (const auto& region : doc["regions"]) {
    parts.push_back(region["flight_component"].get<int>());
    EXPECT_EQ(region["connected"], true);
  }
  EXPECT_EQ(parts, (std::vector<int>{0, 0, 0, 1}));
  // The mask: UAVs 0-2 left of the wall (x <= 100, the wall's own column is seen from the left),
  // UAV 3 right of it.
  const auto rows = mask_rows(read_text(path("a.txt")));
  for (const std::string& row : rows) {
    for (std::size_t x = 0; x < row.size(); ++x) {
      if (row[x] == '.') continue;
      EXPECT_EQ(row[x] == '3', x > 100) << "column " << x << ": " << row[x];
    }
  }
}

// Without a UAV on the right the right side cannot be seen: reported, and not balanced.
TEST_F(PartitionCli, APartWithoutUavsIsReportedUnreachable) {
  const auto r = run("--uavs 2 --no-fly-box 100,0,100,29 --start 20,15 --start 60,15 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["flight_components"], 1);
  EXPECT_EQ(doc["unreachable_cells"], 3442);
  EXPECT_EQ(doc["unreachable_z2_cells"], 3412);
  EXPECT_EQ(doc["converged"], true);
}

TEST_F(PartitionCli, StripesCanBeShownToo) {
  const auto r = run("--uavs 3 --partitioner stripes --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["partitioner"], "stripes");
  EXPECT_EQ(j["iterations"], 0);
  EXPECT_EQ(j["regions"].size(), 3u);
}

TEST_F(PartitionCli, FallbackExitsWithThreeAndStillWritesTheMask) {
  // UAV 1 is walled into a dead end by UAV 0: no balance is reachable.
  std::ofstream(path("walled.txt")) << "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXX....\nX.......\n";
  const auto r = run(fmt::format(
      "--hull '{}' --uavs 3 --start 0,1 --start 0,0 --start 6,3 -O iteration-limit=40 --out '{}'",
      path("walled.txt").string(), path("m.txt").string()));
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.out.find("NOT converged after 60 iterations"), std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("hullinspect: warning: darp did not balance the regions", 0), 0u) << r.err;
  const auto rows = mask_rows(read_text(path("m.txt")));
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[4], "1.......");  // the walled-in UAV keeps just its start
}

TEST_F(PartitionCli, UsesTheMissionsFallbackAndSaysWhichPartitionerProducedIt) {
  // Four starts 3 cells apart: DARP does not converge (docs/partition.md), transfer balances them.
  const std::string starts =
      "--uavs 4 --start 30,2 --start 33,2 --start 36,2 --start 39,2 -O iteration-limit=200";
  const auto r = run(starts + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["partitioner"], "darp");
  EXPECT_EQ(j["produced_by"], "transfer");
  EXPECT_TRUE(j["converged"]);
  const auto text = run(starts);
  EXPECT_NE(text.out.find("partition produced by transfer (darp did not converge"),
            std::string::npos)
      << text.out;

  const auto own = run(starts + " --no-fallback --json");
  EXPECT_EQ(own.status, 3);
  const auto k = nlohmann::json::parse(own.out);
  EXPECT_EQ(k["produced_by"], "darp");
  EXPECT_FALSE(k["converged"]);
}

TEST_F(PartitionCli, BadInputIsOneLineAndExitTwo) {
  const grid::Cell snapped = world::default_hull().snap({1, 1});
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--uavs 0", "hullinspect: --uavs: must be at least 1 (got 0)"},
      {"--uavs 2 --start 1,1 --start 1,1",
       fmt::format("hullinspect: --start: UAVs 0 and 1 both start on cell ({}, {}) (given (1, 1) "
                   "and (1, 1); cells off the hull snap to the nearest hull cell); every UAV needs "
                   "its own start cell",
                   snapped.x, snapped.y)},
      {"--uavs 2 --start 40:15 --start 1,1", "hullinspect: --start: expects X,Y (got '40:15')"},
      {"--uavs 2 --start 400,15 --start 1,1",
       "hullinspect: --start: start cell (400, 15) is outside the 230 × 30 grid"},
      {"--uavs 2 --start 40,15", "hullinspect: --start: gives 1 start cell for 2 UAVs"},
      {"--uavs 2 -O cc=5",
       "hullinspect: --option: darp.cc: must be a number in [0, 0.5] (got '5')"},
      {"--uavs 2 -O cc", "hullinspect: --option: expects KEY=VALUE (got 'cc')"},
      {"--uavs 2 --partitioner nope",
       "hullinspect: --partitioner: unknown partitioner 'nope' (known: darp, stripes, transfer)"},
      {"--uavs 70",  // --out (added below) has 62 symbols
       "hullinspect: --out: a region mask has symbols for at most 62 UAVs (got 70)"},
      {"--uavs 2 --hull /nonexistent/hull.txt",
       "hullinspect: /nonexistent/hull.txt: cannot open the hull file"},
  };
  for (const auto& [args, message] : cases) {
    SCOPED_TRACE(args);
    const auto r = run(fmt::format("{} --out '{}'", args, path("never.txt").string()));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, message + "\n");
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(path("never.txt")));  // no half-written file
  }
}

}  // namespace
}  // namespace hullinspect
