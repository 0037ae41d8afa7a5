// StagedDir, the all-or-nothing output directory of report and merge: nothing reaches the target
// before commit(), an uncommitted staging directory is removed, and a commit into an existing
// directory replaces only the staged entries (a staged directory whole) and keeps the others.

#include "hullinspect/experiment/staged_dir.hpp"

#include <gtest/gtest.h>

#include "experiment_test_support.hpp"

namespace hullinspect::experiment {
namespace {

namespace fs = std::filesystem;
using testing::read;
using testing::ScratchDir;

int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(StagedDir, NothingReachesTheTargetBeforeCommit) {
  ScratchDir dir("staged");
  const auto target = dir / "out";
  {
    StagedDir staged(target);
    EXPECT_EQ(staged.path().parent_path(), fs::absolute(dir.path()));
    io::write_file_atomic(staged.path() / "a.csv", "a\n");
    EXPECT_FALSE(fs::exists(target));
  }
  // Not committed: the staging directory is gone and nothing else was made.
  EXPECT_FALSE(fs::exists(target));
  EXPECT_EQ(entries(dir.path()), 0);

  StagedDir staged(target);
  io::write_file_atomic(staged.path() / "a.csv", "a\n");
  staged.commit();
  EXPECT_EQ(read(target / "a.csv"), "a\n");
  EXPECT_EQ(entries(dir.path()), 1);  // only the target
}

TEST(StagedDir, ACommitIntoAnExistingDirectoryReplacesOnlyWhatWasStaged) {
  ScratchDir dir("existing");
  const auto target = dir / "report";
  fs::create_directories(target / "figures");
  io::write_file_atomic(target / "notes.txt", "mine\n");
  io::write_file_atomic(target / "summary.csv", "old\n");
  io::write_file_atomic(target / "figures" / "fig6_old.png", "old\n");
  StagedDir staged(target);
  fs::create_directories(staged.path() / "figures");
  io::write_file_atomic(staged.path() / "summary.csv", "new\n");
  io::write_file_atomic(staged.path() / "figures" / "fig6_new.svg", "new\n");
  staged.commit();
  EXPECT_EQ(read(target / "notes.txt"), "mine\n");
  EXPECT_EQ(read(target / "summary.csv"), "new\n");
  EXPECT_FALSE(fs::exists(target / "figures" / "fig6_old.png"));
  EXPECT_EQ(read(target / "figures" / "fig6_new.svg"), "new\n");
  EXPECT_EQ(entries(dir.path()), 1);  // no staging or old directory left beside it
}

}  // namespace
}  // namespace hullinspect::experiment
