#pragma once
// Temporary files written but not yet renamed into place (OutputSet, write_file_atomic), listed in
// a fixed table that a signal handler can read: remove_pending_temporaries() unlinks them, so a
// command interrupted by SIGINT or SIGTERM while writing its outputs leaves no temporary behind.
// The table holds kMaxPendingTemporaries paths of up to kMaxPendingPath bytes; a temporary beyond
// that is still removed by its owner's destructor on every error, only not on a signal.

#include <cstddef>
#include <filesystem>

namespace hullinspect::io {

inline constexpr std::size_t kMaxPendingTemporaries = 64;
inline constexpr std::size_t kMaxPendingPath = 1024;

/// Lists `path` while it lives (or until release()): create it before the temporary is opened.
/// A listed directory (a staging directory of report or merge) is removed with what it holds.
class PendingTemporary {
 public:
  enum class Kind { file, directory };
  PendingTemporary() = default;
  explicit PendingTemporary(const std::filesystem::path& path, Kind kind = Kind::file);
  PendingTemporary(PendingTemporary&& other) noexcept;
  PendingTemporary& operator=(PendingTemporary&& other) noexcept;
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;
  ~PendingTemporary();

  /// Takes the path off the table (after it was renamed into place or removed).
  void release() noexcept;

 private:
  int slot_ = -1;
};

/// Unlinks every listed temporary, then removes every listed directory with its contents (up to
/// four levels deep). Async-signal-safe: only atomics and system calls (unlink, open, getdents64,
/// unlinkat, close, rmdir), buffers on the stack.
void remove_pending_temporaries() noexcept;

/// How many temporaries are listed now (for tests).
std::size_t pending_temporaries() noexcept;

}  // namespace hullinspect::io
