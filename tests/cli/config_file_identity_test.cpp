// The files an experiment config names (prior:, truth:, prior-defects:, truth-defects:, a no-fly
// mask) enter its fingerprint by their content and by the name the config gives them: the
// fingerprint and runs.csv do not depend on how the config's own path is spelled, --resume works
// from another directory, and a file whose content changed under the same name is another
// experiment (and a changed map gives other run ids).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/config_spellings.hpp"
#include "support/dir_snapshot.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

// An 8 x 4 hull with a prior mask, a truth from a defect survey and a no-fly mask beside it.
fs::path write_experiment(const std::string& name) {
  const fs::path dir = fs::absolute(make_temp_dir(name));
  fs::create_directories(dir / "k");
  std::ofstream(dir / "k" / "hull.txt") << "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n";
  std::ofstream(dir / "k" / "prior.txt") << "XX......\nXX......\n........\n......X.\n";
  std::ofstream(dir / "k" / "nofly.txt") << "........\n....X...\n........\n........\n";
  std::ofstream(dir / "k" / "survey.csv") << "x_m,z_m,side,w_m,h_m\n1.0,0.5,starboard,1.0,0.5\n";
  std::ofstream(dir / "k" / "k.yaml")
      << "name: k\nhull: hull.txt\nprior: prior.txt\ntruth-defects: survey.csv\n"
         "no-fly: {file: nofly.txt}\ns1: 1\ns2: 3\nuavs: 1\nalgorithms: [lawnmower]\n"
         "instances: 2\ncurve: {step: 10, end: 100}\n";
  return dir;
}

TEST(ConfigFileIdentity, TheConfigPathsSpellingChangesNoIdAndResumeWorksFromElsewhere) {
  const fs::path dir = write_experiment("config-file-identity");
  expect_one_experiment_however_spelled(dir, "k", "k.yaml");
  fs::remove_all(dir);
}

TEST(ConfigFileIdentity, AFileChangedUnderTheSameNameIsAnotherExperiment) {
  const struct {
    std::string file;
    std::string changed;
  } changes[] = {{"prior.txt", "XX......\nXX......\n........\n.......X\n"},
                 {"survey.csv", "x_m,z_m,side,w_m,h_m\n3.0,0.5,starboard,1.0,0.5\n"},
                 {"nofly.txt", "........\n.....X..\n........\n........\n"}};
  for (const auto& c : changes) {
    SCOPED_TRACE(c.file);
    const fs::path dir = write_experiment("config-file-changed");
    const fs::path out = dir / "r";
    auto r = run_cli_in(dir / "k",
                        {"experiment", "--config", "k.yaml", "--out", out.string(), "--jobs", "1"});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string fingerprint = fingerprint_of(out);
    std::ofstream(dir / "k" / c.file) << c.changed;
    const auto before = snapshot(out);
    r = run_cli_in(dir / "k", {"experiment", "--config", "k.yaml", "--out", out.string(),
                               "--resume", "--jobs", "1"});
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("holds results of a different experiment"), std::string::npos) << r.err;
    EXPECT_TRUE(snapshot(out) == before) << "the refused --resume changed " << out;
    // The changed file is another experiment: run afresh, its fingerprint differs.
    r = run_cli_in(dir / "k", {"experiment", "--config", "k.yaml", "--out", (dir / "r2").string(),
                               "--jobs", "1"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(fingerprint_of(dir / "r2"), fingerprint);
    // And so are its runs: a run id names the maps it was flown with (a config-wide no-fly mask
    // is in the fingerprint only, so that the runs of existing results keep their ids).
    const std::string old_runs = slurp(out / "runs.csv");
    const std::string new_runs = slurp(dir / "r2" / "runs.csv");
    const auto first_id = [](const std::string& runs) {
      const auto line = runs.find('\n') + 1;
      return runs.substr(line, runs.find(',', line) - line);
    };
    if (c.file != "nofly.txt") {
      EXPECT_NE(first_id(new_runs), first_id(old_runs));
    }
    fs::remove_all(dir);
  }
}

}  // namespace
}  // namespace hullinspect::testing
