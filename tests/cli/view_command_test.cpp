// `hullinspect view` and `run --html` end to end: the built CLI (HULLINSPECT_CLI) on real files.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int status = -1;
  std::string out;
  std::string err;
};

class ViewCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* cli = std::getenv("HULLINSPECT_CLI");
    ASSERT_NE(cli, nullptr) << "set HULLINSPECT_CLI to the hullinspect binary (CTest does)";
    cli_ = cli;
    dir_ = fs::temp_directory_path() /
           ("hullinspect-view-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  Outcome run(const std::string& args) const {
    const auto out = dir_ / "stdout.txt";
    const auto err = dir_ / "stderr.txt";
    const std::string command =
        "'" + cli_ + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
    const int raw = std::system(command.c_str());
    Outcome o;
    o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    o.out = slurp(out);
    o.err = slurp(err);
    fs::remove(out);
    fs::remove(err);
    return o;
  }

  // Files in the test folder, to see that a failed command left nothing behind.
  std::size_t files() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}));
  }

  std::string cli_;
  fs::path dir_;
};

TEST_F(ViewCommand, WritesTheSamePageAsRunHtml) {
  const auto trace = dir_ / "m.json";
  const auto direct = dir_ / "direct.html";
  auto r = run("run -n 3 --seed 4 --trace '" + trace.string() + "' --html '" + direct.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  r = run("view '" + trace.string() + "' --out '" + (dir_ / "v.html").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out.rfind("wrote " + (dir_ / "v.html").string() + " (", 0), 0u) << r.out;
  const std::string html = slurp(dir_ / "v.html");
  EXPECT_EQ(html, slurp(direct));
  EXPECT_NE(html.find(R"("format":"hullinspect-trace")"), std::string::npos);
  // Without --out the page goes beside the trace.
  r = run("view '" + trace.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "m.html"), html);
}

TEST_F(ViewCommand, MissingTraceIsOneLineAndExit2) {
  const auto missing = dir_ / "missing.json";
  const auto r = run("view '" + missing.string() + "' --out '" + (dir_ / "x.html").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + missing.string() + ": cannot open the file\n");
  EXPECT_EQ(files(), 0u);
}

TEST_F(ViewCommand, MalformedTraceIsOneLineAndWritesNothing) {
  const auto bad = dir_ / "bad.json";
  std::ofstream(bad) << "{\"format\": \"hullinspect-trace\", \"version\": 1}\n";
  auto r = run("view '" + bad.string() + "' --out '" + (dir_ / "x.html").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + bad.string() + ": parameters: missing\n");

  std::ofstream(bad) << "[1, 2,";
  r = run("view '" + bad.string() + "' --out '" + (dir_ / "x.html").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + bad.string() +
                       ":1: not a JSON trace: syntax error while parsing value - unexpected end of "
                       "input; expected '[', '{', or a literal\n");
  EXPECT_EQ(files(), 1u);  // only bad.json: no page, no temporary file
}

TEST_F(ViewCommand, UnwritableOutputIsOneLineAndExit2) {
  const auto trace = dir_ / "m.json";
  ASSERT_EQ(run("run -n 2 --trace '" + trace.string() + "'").status, 0);
  const auto out = dir_ / "no-such-folder" / "x.html";
  const auto r = run("view '" + trace.string() + "' --out '" + out.string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("hullinspect: " + out.string() + ": cannot write", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}

}  // namespace
