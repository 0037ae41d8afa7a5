// SIGINT and SIGTERM stop `experiment`, `merge` and `report` at once, whatever they are doing,
// and leave nothing half-written: no temporary, no staging directory, no partial --out of a merge
// or report; an interrupted experiment's directory resumes to the complete result. The bound on
// the time from the signal to the end is generous (the machine may be loaded): it catches a
// command that carries on with its work, not a slow one.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/dir_snapshot.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr auto kGenerousBound = std::chrono::seconds(10);

// Starts the CLI in `cwd` with its output streams sent to /dev/null.
pid_t start(const fs::path& cwd, const std::vector<std::string>& args) {
  const std::string cli = cli_path();
  std::vector<char*> argv{const_cast<char*>(cli.c_str())};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(cwd.c_str()) != 0) ::_exit(126);
    std::FILE* null = std::fopen("/dev/null", "w");
    if (null) {
      ::dup2(::fileno(null), STDOUT_FILENO);
      ::dup2(::fileno(null), STDERR_FILENO);
    }
    ::execv(cli.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

// True when `dir` holds an entry whose name contains `part`, at any depth.
bool holds(const fs::path& dir, const std::string& part) {
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().filename().string().find(part) != std::string::npos) return true;
  }
  return false;
}

struct Ended {
  int status = 0;
  Clock::duration after_signal{};
};

// Sends `signal` to `pid` and waits for it.
Ended interrupt(pid_t pid, int signal) {
  const auto sent = Clock::now();
  ::kill(pid, signal);
  Ended e;
  while (::waitpid(pid, &e.status, 0) < 0 && errno == EINTR) {
  }
  e.after_signal = Clock::now() - sent;
  return e;
}

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

// An experiment of `instances` one-UAV missions on a 6 × 2 rectangle (about 0.3 ms each).
fs::path write_config(const fs::path& dir, int instances) {
  const fs::path config = dir / "big.yaml";
  std::ofstream(config) << "name: big\nhull: rectangle\ngrid: {width: 6, height: 2}\ns1: 1\n"
                           "s2: 3\nuavs: 1\ninstances: "
                        << instances << "\n";
  return config;
}

TEST(Interrupts, AnExperimentStopsAtOnceAndResumesToTheWholeResult) {
  for (const int signal : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signal);
    const fs::path dir = fs::absolute(make_temp_dir("interrupt-experiment"));
    write_config(dir, 6000);
    const pid_t pid =
        start(dir, {"experiment", "--config", "big.yaml", "--out", "R", "--jobs", "2"});
    // Interrupted once some runs are in the journal.
    while (lines_of(dir / "R" / "runs.csv").size() < 50) {
      int status = 0;
      ASSERT_EQ(::waitpid(pid, &status, WNOHANG), 0) << "the experiment ended before the signal";
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    const Ended e = interrupt(pid, signal);
    EXPECT_TRUE(WIFSIGNALED(e.status) && WTERMSIG(e.status) == signal) << e.status;
    EXPECT_LT(e.after_signal, kGenerousBound);
    EXPECT_FALSE(holds(dir, ".tmp-")) << "a temporary remained";
    const auto done = lines_of(dir / "R" / "runs.csv").size();
    EXPECT_LT(done, 6001u) << "the experiment finished before the signal";
    const CliResult r = run_cli({"experiment", "--config", (dir / "big.yaml").string(), "--out",
                                 (dir / "R").string(), "--resume", "--jobs", "2"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(lines_of(dir / "R" / "runs.csv").size(), 6001u);
    const CliResult report = run_cli(
        {"report", (dir / "R").string(), "--out", (dir / "report").string(), "--no-figures"});
    EXPECT_EQ(report.status, 0) << report.err;
    fs::remove_all(dir);
  }
}

// merge and report are interrupted while their staging directory exists (it is polled for) and,
// for report, also while it reads its input, before it has written anything.
TEST(Interrupts, MergeAndReportStopAtOnceAndLeaveNothing) {
  const fs::path dir = fs::absolute(make_temp_dir("interrupt-merge-report"));
  write_config(dir, 4000);
  const CliResult made = run_cli({"experiment", "--config", (dir / "big.yaml").string(), "--out",
                                  (dir / "R").string(), "--jobs", "2"});
  ASSERT_EQ(made.status, 0) << made.err;
  const auto results = snapshot(dir / "R");
  const struct {
    std::vector<std::string> args;
    bool wait_for_staging;
  } commands[] = {{{"merge", "R", "--out", "M"}, true},
                  {{"report", "R", "--out", "M", "--no-figures"}, true},
                  {{"report", "R", "--out", "M", "--no-figures"}, false}};
  int caught_staging = 0;
  for (const auto& c : commands) {
    for (const int signal : {SIGINT, SIGTERM}) {
      SCOPED_TRACE(c.args[0] + " " + std::to_string(signal) +
                   (c.wait_for_staging ? " while staging" : " while reading"));
      // On a loaded machine the signal may come after the staging directory is gone: try again.
      for (int attempt = 0; attempt < 5; ++attempt) {
        const pid_t pid = start(dir, c.args);
        if (c.wait_for_staging) {
          // Polled without a pause: the staging directory lives for a fraction of a second.
          int status = 0;
          while (!holds(dir, ".M.staging-") && ::waitpid(pid, &status, WNOHANG) == 0) {
          }
        }
        const bool staging_seen = holds(dir, ".M.staging-");
        const Ended e = interrupt(pid, signal);
        if (WIFEXITED(e.status)) {
          // Finished before the signal came: then it must be whole.
          EXPECT_EQ(WEXITSTATUS(e.status), 0);
          fs::remove_all(dir / "M");
          continue;
        }
        EXPECT_TRUE(WIFSIGNALED(e.status) && WTERMSIG(e.status) == signal) << e.status;
        EXPECT_LT(e.after_signal, kGenerousBound);
        if (fs::exists(dir / "M") && !holds(dir, ".M.staging-")) {
          // The signal came between the commit (the staging directory renamed to M, so M is
          // whole) and the exit: nothing partial, but not the case this test is after.
          EXPECT_FALSE(holds(dir, ".tmp-")) << "a temporary remained";
          fs::remove_all(dir / "M");
          continue;
        }
        EXPECT_FALSE(fs::exists(dir / "M")) << "a partial --out remained";
        EXPECT_FALSE(holds(dir, ".staging-")) << "a staging directory remained";
        EXPECT_FALSE(holds(dir, ".tmp-")) << "a temporary remained";
        EXPECT_TRUE(snapshot(dir / "R") == results) << "the input changed";
        caught_staging += staging_seen ? 1 : 0;
        if (staging_seen || !c.wait_for_staging) break;
      }
    }
  }
  EXPECT_GT(caught_staging, 0) << "no signal arrived while a staging directory existed";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
