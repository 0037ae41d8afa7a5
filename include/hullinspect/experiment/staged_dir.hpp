#pragma once
// All-or-nothing output directories (report, merge): every file is written into a hidden staging
// directory beside the target, and only when all are written does commit() move them in, so a full
// disk, a failing child program or an interrupt leaves the target as it was (and no staging
// directory: the destructor removes an uncommitted one, and the CLI's SIGINT/SIGTERM/SIGHUP
// handler one listed among the pending temporaries).

#include <filesystem>

#include "hullinspect/files/pending_temporaries.hpp"

namespace hullinspect::experiment {

class StagedDir {
 public:
  /// Creates an empty staging directory beside `target` (on the same file system, so that the
  /// commit is made of renames). Throws InputError naming the target when it cannot.
  explicit StagedDir(std::filesystem::path target);
  ~StagedDir();
  StagedDir(const StagedDir&) = delete;
  StagedDir& operator=(const StagedDir&) = delete;

  /// Where to write the outputs.
  const std::filesystem::path& path() const { return staging_; }

  /// Moves the staged entries into the target: a missing or empty target is replaced by the
  /// staging directory in one rename; into an existing one each staged entry is renamed over its
  /// namesake (a staged directory replaces the old one whole), other entries are left alone.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  io::PendingTemporary listed_;  ///< the staging directory, for the signal handler
  bool committed_ = false;
};

}  // namespace hullinspect::experiment
