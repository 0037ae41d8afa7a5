// `hullinspect view` and `run --html` end to end: the built CLI on real files.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using hullinspect::testing::make_temp_dir;
using hullinspect::testing::run_cli;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t files_in(const fs::path& dir) {
  return static_cast<std::size_t>(
      std::distance(fs::directory_iterator(dir), fs::directory_iterator{}));
}

TEST(ViewCommand, WritesTheSamePageAsRunHtml) {
  const fs::path dir = make_temp_dir("view-same");
  const auto trace = (dir / "m.json").string();
  const auto direct = (dir / "direct.html").string();
  const auto viewed = (dir / "v.html").string();
  auto r = run_cli({"run", "-n", "3", "--seed", "4", "--trace", trace, "--html", direct});
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_cli({"view", trace, "--out", viewed});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out.rfind("wrote " + viewed + " (", 0), 0u) << r.out;
  const std::string html = slurp(viewed);
  EXPECT_EQ(html, slurp(direct));
  EXPECT_NE(html.find(R"("format":"hullinspect-trace")"), std::string::npos);
  // Without --out the page goes beside the trace.
  r = run_cli({"view", trace});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(dir / "m.html"), html);
  fs::remove_all(dir);
}

TEST(ViewCommand, MissingTraceIsOneLineAndExit2) {
  const fs::path dir = make_temp_dir("view-missing");
  const auto missing = (dir / "missing.json").string();
  const auto r = run_cli({"view", missing, "--out", (dir / "x.html").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + missing + ": cannot open the file\n");
  EXPECT_EQ(files_in(dir), 0u);
  fs::remove_all(dir);
}

TEST(ViewCommand, MalformedTraceIsOneLineAndWritesNothing) {
  const fs::path dir = make_temp_dir("view-malformed");
  const auto bad = (dir / "bad.json").string();
  const auto out = (dir / "x.html").string();
  std::ofstream(bad) << "{\"format\": \"hullinspect-trace\", \"version\": 1}\n";
  auto r = run_cli({"view", bad, "--out", out});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + bad + ": parameters: missing\n");

  std::ofstream(bad) << "[1, 2,";
  r = run_cli({"view", bad, "--out", out});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: " + bad +
                       ":1: not a JSON trace: syntax error while parsing value - unexpected end of "
                       "input; expected '[', '{', or a literal\n");
  EXPECT_EQ(files_in(dir), 1u);  // only bad.json: no page, no temporary file
  fs::remove_all(dir);
}

TEST(ViewCommand, UnwritableOutputIsOneLineAndExit2) {
  const fs::path dir = make_temp_dir("view-unwritable");
  const auto trace = (dir / "m.json").string();
  ASSERT_EQ(run_cli({"run", "-n", "2", "--trace", trace}).status, 0);
  const auto out = (dir / "no-such-folder" / "x.html").string();
  const auto r = run_cli({"view", trace, "--out", out});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: --out: cannot write '" + out + "': directory '" +
                       (dir / "no-such-folder").string() + "' does not exist\n");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  fs::remove_all(dir);
}

TEST(ViewCommand, RefusesToOverwriteTheTrace) {
  const fs::path dir = make_temp_dir("view-overwrite");
  const auto trace = (dir / "m.html").string();
  ASSERT_EQ(run_cli({"run", "-n", "2", "--trace", trace}).status, 0);
  const std::string before = slurp(trace);
  const auto r = run_cli({"view", trace});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "hullinspect: --out: '" + trace + "' is the same file as the trace '" + trace +
                       "'; it would be overwritten\n");
  EXPECT_EQ(slurp(trace), before);
  fs::remove_all(dir);
}

}  // namespace
