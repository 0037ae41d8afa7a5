// `experiment`, `merge` and `report` print their summary only once their files are in place: a
// write that fails (a file size limit, as a full disk) exits 1 with nothing on standard output;
// a standard output that cannot be written (`> /dev/full`) exits 1 with the results written and
// whole, since they were committed before the summary was printed (docs/reliability.md).

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"
#include "support/dir_snapshot.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

struct ShellResult {
  int status = -1;
  std::string out;
  std::string err;
};

// Runs `hullinspect ARGS` in `dir` with `limit` in front (a ulimit) and stdout to `stdout_to`
// ("" for a file that is read back).
ShellResult run_shell(const fs::path& dir, const std::string& limit, const std::string& args,
                      const std::string& stdout_to = "") {
  const fs::path logs = dir.parent_path() / (dir.filename().string() + "-logs");
  fs::create_directories(logs);
  const std::string out = stdout_to.empty() ? (logs / "out.txt").string() : stdout_to;
  const std::string line = "cd '" + dir.string() + "' && trap '' XFSZ && " + limit + " exec '" +
                           cli_path() + "' " + args + " > '" + out + "' 2> '" +
                           (logs / "err.txt").string() + "'";
  const int status = std::system(("sh -c \"" + line + "\"").c_str());
  ShellResult r;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (stdout_to.empty()) r.out = slurp(out);
  r.err = slurp(logs / "err.txt");
  fs::remove_all(logs);
  return r;
}

void write_config(const fs::path& dir) {
  std::ofstream(dir / "small.yaml") << "name: small\nhull: rectangle\ngrid: {width: 6, height: 2}\n"
                                       "s1: 1\ns2: 3\nuavs: 1\ninstances: 200\n";
}

TEST(SummaryAfterWrite, AFailedWritePrintsNoSummary) {
  const fs::path dir = fs::absolute(make_temp_dir("summary-failed-write"));
  write_config(dir);
  // 1 block of 512 bytes: the journals' first lines fit, runs.csv and samples.csv do not.
  auto r = run_shell(dir, "ulimit -f 1;", "experiment --config small.yaml --out R --jobs 1");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.out, "");
  ASSERT_EQ(run_cli({"experiment", "--config", (dir / "small.yaml").string(), "--out",
                     (dir / "G").string(), "--jobs", "1"})
                .status,
            0);
  for (const std::string command : {"merge G --out M", "report G --out M --no-figures"}) {
    SCOPED_TRACE(command);
    r = run_shell(dir, "ulimit -f 1;", command);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(dir / "M"));
  }
  fs::remove_all(dir);
}

TEST(SummaryAfterWrite, AFullStandardOutputExitsOneWithTheResultsWhole) {
  const fs::path dir = fs::absolute(make_temp_dir("summary-full-stdout"));
  write_config(dir);
  const std::string full = "cannot write to standard output: No space left on device\n";
  auto r = run_shell(dir, "", "experiment --config small.yaml --out R --jobs 1", "/dev/full");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(full), std::string::npos) << r.err;
  // Whole: --resume has nothing left to run, and the results are the same as a fresh run's.
  ASSERT_EQ(run_cli({"experiment", "--config", (dir / "small.yaml").string(), "--out",
                     (dir / "G").string(), "--jobs", "1"})
                .status,
            0);
  EXPECT_EQ(slurp(dir / "R" / "runs.csv"), slurp(dir / "G" / "runs.csv"));
  EXPECT_EQ(slurp(dir / "R" / "curves.csv"), slurp(dir / "G" / "curves.csv"));
  r = run_shell(dir, "", "merge G --out M", "/dev/full");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(full), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir / "M" / "runs.csv"), slurp(dir / "G" / "runs.csv"));
  r = run_shell(dir, "", "report G --out P --no-figures", "/dev/full");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(full), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "P" / "report.md"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
