#include "support/config_spellings.hpp"

#include <gtest/gtest.h>

#include "support/dir_snapshot.hpp"

namespace hullinspect::testing {

namespace fs = std::filesystem;

CliResult run_cli_in(const fs::path& cwd, const std::vector<std::string>& args) {
  const fs::path before = fs::current_path();
  fs::current_path(cwd);
  const CliResult r = run_cli(args);
  fs::current_path(before);
  return r;
}

std::string fingerprint_of(const fs::path& results) {
  const std::string manifest = slurp(results / "manifest.json");
  const auto at = manifest.find("\"fingerprint\"");
  if (at == std::string::npos) return {};
  return manifest.substr(at, manifest.find('\n', at) - at);
}

void expect_one_experiment_however_spelled(const fs::path& dir, const std::string& sub,
                                           const std::string& name) {
  const fs::path config = dir / sub / name;
  const struct {
    fs::path cwd;
    std::string config;
  } spellings[] = {{dir / sub, name},
                   {dir / sub, "./" + name},
                   {dir, (fs::path(sub) / name).string()},
                   {"/", config.string()}};
  std::string first_fingerprint;
  std::string runs;
  int n = 0;
  for (const auto& s : spellings) {
    SCOPED_TRACE(s.config);
    const fs::path out = dir / ("r" + std::to_string(n++));
    const auto r = run_cli_in(
        s.cwd, {"experiment", "--config", s.config, "--out", out.string(), "--jobs", "1"});
    ASSERT_EQ(r.status, 0) << r.err;
    if (runs.empty()) {
      first_fingerprint = fingerprint_of(out);
      runs = slurp(out / "runs.csv");
      ASSERT_FALSE(first_fingerprint.empty());
    }
    EXPECT_EQ(fingerprint_of(out), first_fingerprint);
    EXPECT_EQ(slurp(out / "runs.csv"), runs);
  }
  // Started as NAME inside sub/, resumed as ./NAME there and by the absolute path from /.
  for (const auto& [cwd, spelled] :
       {std::pair<fs::path, std::string>{dir / sub, "./" + name}, {"/", config.string()}}) {
    SCOPED_TRACE("resumed as " + spelled);
    const auto r = run_cli_in(cwd, {"experiment", "--config", spelled, "--out",
                                    (dir / "r0").string(), "--resume", "--jobs", "1"});
    EXPECT_EQ(r.status, 0) << r.err;
  }
  EXPECT_EQ(slurp(dir / "r0" / "runs.csv"), runs);
}

}  // namespace hullinspect::testing
