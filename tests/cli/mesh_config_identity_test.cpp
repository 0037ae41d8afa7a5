// A mesh hull named by a config is identified by the mesh as the config names it: the manifest's
// fingerprint and runs.csv (run ids, hull hash) are the same however the config's own path is
// spelled, and an experiment started with one spelling resumes with another from elsewhere.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"
#include "support/dir_snapshot.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

// Runs the CLI with `cwd` as the working directory.
CliResult run_in(const fs::path& cwd, const std::vector<std::string>& args) {
  const fs::path before = fs::current_path();
  fs::current_path(cwd);
  const CliResult r = run_cli(args);
  fs::current_path(before);
  return r;
}

TEST(MeshConfigIdentity, TheConfigPathsSpellingChangesNoIdAndResumeWorksFromElsewhere) {
  const fs::path dir = fs::absolute(make_temp_dir("mesh-config-identity"));
  fs::create_directories(dir / "k");
  std::ofstream(dir / "k" / "k3.stl")
      << "solid t\n facet normal 0 -1 0\n  outer loop\n   vertex 0 0 0\n   vertex 2 0 0\n"
         "   vertex 0 0 2\n  endloop\n endfacet\nendsolid t\n";
  std::ofstream(dir / "k" / "k3.yaml")
      << "name: k3\nhull: {mesh: k3.stl}\ns1: 1\ns2: 3\nuavs: 1\nalgorithms: [lawnmower]\n"
         "instances: 2\ncurve: {step: 10, end: 100}\n";
  const struct {
    fs::path cwd;
    std::string config;
  } spellings[] = {{dir / "k", "k3.yaml"},
                   {dir / "k", "./k3.yaml"},
                   {dir, "k/k3.yaml"},
                   {"/", (dir / "k" / "k3.yaml").string()}};
  std::string manifest_fingerprint;
  std::string runs;
  int n = 0;
  for (const auto& s : spellings) {
    SCOPED_TRACE(s.config);
    const fs::path out = dir / ("r" + std::to_string(n++));
    const auto r =
        run_in(s.cwd, {"experiment", "--config", s.config, "--out", out.string(), "--jobs", "1"});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string manifest = slurp(out / "manifest.json");
    const auto at = manifest.find("\"fingerprint\"");
    ASSERT_NE(at, std::string::npos);
    const std::string fingerprint = manifest.substr(at, manifest.find('\n', at) - at);
    if (runs.empty()) {
      manifest_fingerprint = fingerprint;
      runs = slurp(out / "runs.csv");
    }
    EXPECT_EQ(fingerprint, manifest_fingerprint);
    EXPECT_EQ(slurp(out / "runs.csv"), runs);
  }
  // Started as k3.yaml inside k/, resumed by its absolute path from /.
  const auto r = run_in("/", {"experiment", "--config", (dir / "k" / "k3.yaml").string(), "--out",
                              (dir / "r0").string(), "--resume", "--jobs", "1"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(dir / "r0" / "runs.csv"), runs);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
