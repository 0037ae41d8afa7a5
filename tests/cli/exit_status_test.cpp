// What a command leaves behind when its environment fails: a standard output that cannot be written
// (`> /dev/full`) leaves none of the command's files and exits 1; --help and --version to a full
// standard output exit 1; a full disk under an output exits 1 (the input was fine); SIGINT and
// SIGTERM while outputs are written leave no temporary.

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

std::string quoted(const std::string& s) {
  return "'" + s + "'";
}

struct ShellResult {
  int status = -1;
  std::string err;
};

// Runs `hullinspect ARGS > /dev/full` in `dir`.
ShellResult run_to_full_stdout(const fs::path& dir, const std::string& args) {
  const std::string err = (dir / "stderr.txt").string();
  const std::string line = "cd " + quoted(dir.string()) + " && " + quoted(cli_path()) + " " + args +
                           " > /dev/full 2> " + quoted(err);
  const int status = std::system(line.c_str());
  ShellResult r;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(err);
  fs::remove(err);
  return r;
}

// Every entry of `dir`, recursively, relative to it.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    out.push_back(fs::relative(e.path(), dir).string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

constexpr const char* kFullStdout =
    "hullinspect: cannot write to standard output: No space left on device\n";

TEST(FullStandardOutput, LeavesNoFilesOfTheCommand) {
  const fs::path dir = make_temp_dir("stdout-full-files");
  std::ofstream(dir / "hull.txt") << "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n";
  ASSERT_EQ(run_cli({"run", "--hull", (dir / "hull.txt").string(), "-n", "2", "--trace",
                     (dir / "trace.json").string()})
                .status,
            0);
  const auto before = entries(dir);
  for (const char* args :
       {"run --hull hull.txt -n 2 --trace t.json", "run --hull hull.txt -n 2 --html t.html",
        "run --hull hull.txt -n 2 --export plans", "plan --hull hull.txt -n 2 --trace t.json",
        "plan --hull hull.txt -n 2 --export plans --json", "export trace.json --out plans",
        "view trace.json --out t.html", "partition --hull hull.txt -n 2 --out regions.txt"}) {
    SCOPED_TRACE(args);
    const auto r = run_to_full_stdout(dir, args);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err, kFullStdout);
    EXPECT_EQ(entries(dir), before) << "a file was left behind";
  }
  fs::remove_all(dir);
}

TEST(FullStandardOutput, HullImportWritesNoHull) {
  const fs::path dir = make_temp_dir("stdout-full-import");
  // A box 4 m long and 2 m high, seen from the side (two triangles per face).
  std::ofstream(dir / "box.obj") << "v 0 0 0\nv 4 0 0\nv 4 0 2\nv 0 0 2\n"
                                    "v 0 1 0\nv 4 1 0\nv 4 1 2\nv 0 1 2\n"
                                    "f 1 2 3\nf 1 3 4\nf 5 7 6\nf 5 8 7\n"
                                    "f 1 5 6\nf 1 6 2\nf 4 3 7\nf 4 7 8\n"
                                    "f 1 4 8\nf 1 8 5\nf 2 6 7\nf 2 7 3\n";
  ASSERT_EQ(
      run_cli({"hull", "import", (dir / "box.obj").string(), "--out", (dir / "check").string()})
          .status,
      0);
  fs::remove(dir / "check.json");
  const auto r = run_to_full_stdout(dir, "hull import box.obj --out box");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, kFullStdout);
  EXPECT_FALSE(fs::exists(dir / "box.json"));
  EXPECT_EQ(entries(dir), std::vector<std::string>{"box.obj"});
  fs::remove_all(dir);
}

TEST(FullStandardOutput, HelpAndVersionFail) {
  const fs::path dir = make_temp_dir("stdout-full-help");
  for (const char* args : {"--help", "--version", "run --help", "export --help"}) {
    SCOPED_TRACE(args);
    const auto r = run_to_full_stdout(dir, args);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err, kFullStdout);
  }
  fs::remove_all(dir);
}

// A full disk is the environment's failure, not the input's: exit 1. RLIMIT_FSIZE = 0 (with
// SIGXFSZ ignored) makes every write of an output fail with EFBIG, on the same path as ENOSPC.
TEST(FullDisk, AFailedWriteExitsOneAndLeavesNothing) {
  const fs::path dir = make_temp_dir("full-disk");
  std::ofstream(dir / "hull.txt") << "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n";
  for (const char* args :
       {"run --hull hull.txt -n 2 --trace t.json", "run --hull hull.txt -n 2 --export plans",
        "partition --hull hull.txt -n 2 --out regions.txt"}) {
    SCOPED_TRACE(args);
    const std::string line = "cd " + quoted(dir.string()) +
                             " && { (trap '' XFSZ; ulimit -f 0; exec " + quoted(cli_path()) + " " +
                             args + ") 2>&1 > /dev/null; echo $? > ../" + dir.filename().string() +
                             ".status; } | cat > ../" + dir.filename().string() + ".err";
    ASSERT_EQ(std::system(line.c_str()), 0);
    const fs::path status = dir.parent_path() / (dir.filename().string() + ".status");
    const fs::path err = dir.parent_path() / (dir.filename().string() + ".err");
    EXPECT_EQ(slurp(status), "1\n");
    const std::string message = slurp(err);
    EXPECT_NE(message.find("write failed: File too large\n"), std::string::npos) << message;
    EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
    EXPECT_EQ(entries(dir), std::vector<std::string>{"hull.txt"});
    fs::remove(status);
    fs::remove(err);
  }
  fs::remove_all(dir);
}

// SIGINT or SIGTERM while a command holds written temporaries: none remains. `partition --json`
// with 62 UAVs prints more than a one-page pipe holds, so with standard output on such a pipe that
// nobody reads, the command stops in its final flush — after writing its output's temporary,
// before committing it — and waits there until the signal comes.
TEST(Signals, AnInterruptedCommandLeavesNoTemporary) {
  for (int signal : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signal);
    const fs::path dir = make_temp_dir("signals");
    int pipe_fds[2];
    ASSERT_EQ(::pipe(pipe_fds), 0);
    ASSERT_EQ(::fcntl(pipe_fds[1], F_SETPIPE_SZ, 4096), 4096);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::dup2(pipe_fds[1], STDOUT_FILENO);
      ::close(pipe_fds[0]);
      ::close(pipe_fds[1]);
      if (::chdir(dir.c_str()) != 0) ::_exit(126);
      const std::string cli = cli_path();
      ::execl(cli.c_str(), cli.c_str(), "partition", "-n", "62", "--partitioner", "stripes",
              "--json", "--out", "regions.txt", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(pipe_fds[1]);
    // Wait (without a time bound of its own: CTest's applies) until the temporary (or, were the
    // output committed before the flush, the output) exists.
    const auto temporary = [&] {
      for (const auto& e : entries(dir)) {
        if (e.find(".tmp-") != std::string::npos) return true;
      }
      return false;
    };
    while (!temporary() && !fs::exists(dir / "regions.txt")) {
      int status = 0;
      ASSERT_EQ(::waitpid(pid, &status, WNOHANG), 0) << "the command ended before writing";
      ::usleep(10000);
    }
    ::kill(pid, signal);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ::close(pipe_fds[0]);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << status;
    EXPECT_EQ(entries(dir), std::vector<std::string>{}) << "a temporary or the output remained";
    fs::remove_all(dir);
  }
}

}  // namespace
}  // namespace hullinspect::testing
