#include "hullinspect/experiment/staged_dir.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::experiment {

namespace fs = std::filesystem;

namespace {

fs::path beside(const fs::path& target, const char* what) {
  const fs::path absolute = fs::absolute(target).lexically_normal();
  const fs::path name =
      absolute.has_filename() ? absolute.filename() : absolute.parent_path().filename();
  const fs::path parent =
      absolute.has_filename() ? absolute.parent_path() : absolute.parent_path().parent_path();
  return parent / fmt::format(".{}.{}-{}", name.string(), what, ::getpid());
}

void rename_or_throw(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec)
    throw Error(
        fmt::format("{}: cannot move the new file into place: {}", to.string(), ec.message()));
}

}  // namespace

StagedDir::StagedDir(fs::path target)
    : target_(std::move(target)),
      staging_(beside(target_, "staging")),
      listed_(staging_, io::PendingTemporary::Kind::directory) {
  std::error_code ec;
  fs::create_directories(staging_.parent_path(), ec);
  if (!ec) fs::create_directory(staging_, ec);
  if (ec) throw Error(fmt::format("{}: cannot create: {}", target_.string(), ec.message()));
}

StagedDir::~StagedDir() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void StagedDir::commit() {
  std::error_code ec;
  const bool empty_or_missing =
      !fs::exists(target_, ec) || (fs::is_directory(target_, ec) &&
                                   fs::directory_iterator(target_, ec) == fs::directory_iterator());
  if (empty_or_missing) {
    rename_or_throw(staging_, target_);
    listed_.release();
    committed_ = true;
    return;
  }
  for (const auto& entry : fs::directory_iterator(staging_)) {
    const fs::path to = target_ / entry.path().filename();
    if (entry.is_directory() && fs::exists(to, ec)) {
      // A directory cannot be renamed over a non-empty one: move the old one aside first.
      const fs::path old = beside(to, "old");
      rename_or_throw(to, old);
      rename_or_throw(entry.path(), to);
      fs::remove_all(old, ec);
    } else {
      rename_or_throw(entry.path(), to);
    }
  }
  fs::remove(staging_, ec);
  listed_.release();
  committed_ = true;
}

}  // namespace hullinspect::experiment
