#include "hullinspect/files/pending_temporaries.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>

namespace hullinspect::io {

namespace {

// A slot is free (0), being filled or emptied by its owner (1), or holds a path (2). Only the
// owner moves a slot 1 → 2 → 1 → 0; the signal handler only reads slots in state 2.
// A listed directory is in state kListedDirectory instead of kListed.
enum : int { kFree = 0, kBusy = 1, kListed = 2, kListedDirectory = 3 };

struct Table {
  std::array<std::atomic<int>, kMaxPendingTemporaries> state{};
  std::array<std::array<char, kMaxPendingPath>, kMaxPendingTemporaries> path{};
};

// Constant-initialised (every slot free) before any code runs, so a signal handler may read it at
// any time.
constinit Table g_table{};

Table& table() {
  return g_table;
}

// Removes what the directory `fd` holds, descending `depth` more levels, with system calls only
// (no allocation, no lock): a signal handler's way to remove a staging directory. Entries are
// read again from the start until none is left, since unlinking while reading may skip some.
void empty_directory(int fd, int depth) noexcept {
  alignas(8) char buffer[4096];
  for (int pass = 0; pass < 64; ++pass) {
    ::lseek(fd, 0, SEEK_SET);
    bool removed = false;
    for (;;) {
      const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
      if (n <= 0) break;
      for (long at = 0; at < n;) {
        // A linux_dirent64: inode (8 bytes), offset (8), record length (2), type (1), name.
        const char* record = buffer + at;
        unsigned short length = 0;
        std::memcpy(&length, record + 16, sizeof length);
        const unsigned char type = static_cast<unsigned char>(record[18]);
        const char* name = record + 19;
        if (length == 0) break;  // never from the kernel; guards the loop
        at += length;
        if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
        // A file system that does not give the type (DT_UNKNOWN) refuses to unlink a directory.
        if (type != DT_DIR && ::unlinkat(fd, name, 0) == 0) {
          removed = true;
          continue;
        }
        if (depth <= 0) continue;
        const int sub = ::openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (sub < 0) continue;
        empty_directory(sub, depth - 1);
        ::close(sub);
        removed |= ::unlinkat(fd, name, AT_REMOVEDIR) == 0;
      }
    }
    if (!removed) return;
  }
}

void remove_directory(const char* path) noexcept {
  const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  empty_directory(fd, 3);
  ::close(fd);
  ::rmdir(path);
}

}  // namespace

PendingTemporary::PendingTemporary(const std::filesystem::path& path, Kind kind) {
  const std::string& text = path.native();
  if (text.size() >= kMaxPendingPath) return;
  Table& t = table();
  for (std::size_t i = 0; i < kMaxPendingTemporaries; ++i) {
    int expected = kFree;
    if (!t.state[i].compare_exchange_strong(expected, kBusy)) continue;
    std::memcpy(t.path[i].data(), text.c_str(), text.size() + 1);
    t.state[i].store(kind == Kind::directory ? kListedDirectory : kListed);
    slot_ = static_cast<int>(i);
    return;
  }
}

PendingTemporary::PendingTemporary(PendingTemporary&& other) noexcept : slot_(other.slot_) {
  other.slot_ = -1;
}

PendingTemporary& PendingTemporary::operator=(PendingTemporary&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

PendingTemporary::~PendingTemporary() {
  release();
}

void PendingTemporary::release() noexcept {
  if (slot_ < 0) return;
  table().state[static_cast<std::size_t>(slot_)].store(kFree);
  slot_ = -1;
}

void remove_pending_temporaries() noexcept {
  Table& t = table();
  for (std::size_t i = 0; i < kMaxPendingTemporaries; ++i) {
    if (t.state[i].load() == kListed) ::unlink(t.path[i].data());
  }
  for (std::size_t i = 0; i < kMaxPendingTemporaries; ++i) {
    if (t.state[i].load() == kListedDirectory) remove_directory(t.path[i].data());
  }
}

std::size_t pending_temporaries() noexcept {
  std::size_t n = 0;
  for (const auto& s : table().state) n += s.load() >= kListed ? 1 : 0;
  return n;
}

}  // namespace hullinspect::io
