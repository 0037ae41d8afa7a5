// Output defects that do not fit the bad-input table: standard output that cannot be written,
// fleet sizes whose default starts used to collide, rows edited by hand before a merge.

#include <gtest/gtest.h>
#include "source_dir.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(OutputSafety, AFullStandardOutputIsAnError) {
  const fs::path dir = make_temp_dir("stdout-full");
  const std::string err = (dir / "err").string();
  for (const char* command : {"run --json", "run", "tsp bench/tsp_instances/g005_00.json"}) {
    SCOPED_TRACE(command);
    const std::string line = "cd '" + std::string(std::getenv("HULLINSPECT_SOURCE_DIR") != nullptr
                                                      ? std::getenv("HULLINSPECT_SOURCE_DIR")
                                                      : HULLINSPECT_SOURCE_DIR) +
                             "' && '" + cli_path() + "' " + command + " > /dev/full 2> '" + err + "'";
    const int status = std::system(line.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 1);
    EXPECT_EQ(slurp(err), "hullinspect: cannot write to standard output: No space left on device\n");
  }
  fs::remove_all(dir);
}

TEST(OutputSafety, EveryFleetSizeThatUsedToShareAStartNowRuns) {
  // 27 … 62 UAVs on the default hull failed with "UAVs 25 and 26 both start on cell (217, 15)".
  for (const char* n : {"27", "62", "200"}) {
    const auto r = run_cli({"run", "-n", n, "--json", "--time-limit", "50"});
    EXPECT_TRUE(r.status == 0 || r.status == 3) << n << ": " << r.err;
    EXPECT_EQ(r.err, "") << n;
  }
}

TEST(OutputSafety, MergeRefusesARowEditedByHand) {
  const fs::path dir = make_temp_dir("merge-edited");
  std::ofstream(dir / "hull.txt") << "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n";
  std::ofstream(dir / "c.yaml") << "hull: hull.txt\nuavs: 2\ninstances: 2\ncurve: {step: 10, end: 100}\n";
  auto r = run_cli({"experiment", "--config", (dir / "c.yaml").string(), "--out",
                    (dir / "a").string(), "--jobs", "1"});
  ASSERT_EQ(r.status, 0) << r.err;
  // Set p_tp (field 20) of the first row to 9.
  std::string runs = slurp(dir / "a" / "runs.csv");
  const std::size_t row = runs.find('\n') + 1;
  std::size_t at = row;
  for (int comma = 0; comma < 19; ++comma) at = runs.find(',', at) + 1;
  const std::size_t end = runs.find(',', at);
  const std::string run_id = runs.substr(row, runs.find(',', row) - row);
  runs.replace(at, end - at, "9");
  std::ofstream(dir / "a" / "runs.csv", std::ios::binary) << runs;
  r = run_cli({"merge", (dir / "a").string(), "--out", (dir / "m").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + (dir / "a" / "runs.csv").string() + ":2: p_tp is '9' but run " +
                       run_id + " of this experiment has '1'\n");
  EXPECT_FALSE(fs::exists(dir / "m"));
  // --resume reads the same rows the same way.
  r = run_cli({"experiment", "--config", (dir / "c.yaml").string(), "--out", (dir / "a").string(),
               "--resume"});
  EXPECT_EQ(r.status, 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
