// StagedDir, the all-or-nothing output directory of report and merge: nothing reaches the target
// before commit(), an uncommitted staging directory is removed, and a commit into an existing
// directory replaces only the staged entries (a staged directory whole) and keeps the others.
// A staging directory is listed for the signal handler until it is committed or removed.

#include "hullinspect/experiment/staged_dir.hpp"

#include <gtest/gtest.h>

#include "experiment_test_support.hpp"
#include "hullinspect/files/pending_temporaries.hpp"

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

// What the CLI's SIGINT/SIGTERM handler does (io::remove_pending_temporaries) removes a staging
// directory with its files and sub-directories, half-written temporaries included; a committed
// one is no longer listed, so its files stay.
TEST(StagedDir, TheSignalHandlersCleanupRemovesAnUncommittedStagingDirectory) {
  ScratchDir dir("staged-signal");
  ASSERT_EQ(io::pending_temporaries(), 0u);
  {
    StagedDir staged(dir / "out");
    EXPECT_EQ(io::pending_temporaries(), 1u);
    fs::create_directories(staged.path() / "figures" / "deeper");
    for (int i = 0; i < 300; ++i) {  // more entries than one getdents64 buffer holds
      io::write_file_atomic(staged.path() / ("run" + std::to_string(i) + ".csv"), "x\n");
    }
    io::write_file_atomic(staged.path() / "figures" / "fig6.svg", "<svg/>\n");
    io::write_file_atomic(staged.path() / "figures" / "deeper" / "a.txt", "a\n");
    const io::PendingTemporary half_written(staged.path() / ".summary.csv.tmp-1-0");
    io::write_file_atomic(staged.path() / ".summary.csv.tmp-1-0", "half");
    io::remove_pending_temporaries();  // as the signal handler does
    EXPECT_EQ(entries(dir.path()), 0);
  }
  EXPECT_EQ(io::pending_temporaries(), 0u);
  StagedDir staged(dir / "out");
  io::write_file_atomic(staged.path() / "a.csv", "a\n");
  staged.commit();
  EXPECT_EQ(io::pending_temporaries(), 0u);
  io::remove_pending_temporaries();
  EXPECT_EQ(read(dir / "out" / "a.csv"), "a\n");
}

}  // namespace
}  // namespace hullinspect::experiment
