#include "hullinspect/files/pending_temporaries.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>

namespace hullinspect::io {

namespace {

// A slot is free (0), being filled or emptied by its owner (1), or holds a path (2). Only the
// owner moves a slot 1 → 2 → 1 → 0; the signal handler only reads slots in state 2.
enum : int { kFree = 0, kBusy = 1, kListed = 2 };

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

}  // namespace

PendingTemporary::PendingTemporary(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.size() >= kMaxPendingPath) return;
  Table& t = table();
  for (std::size_t i = 0; i < kMaxPendingTemporaries; ++i) {
    int expected = kFree;
    if (!t.state[i].compare_exchange_strong(expected, kBusy)) continue;
    std::memcpy(t.path[i].data(), text.c_str(), text.size() + 1);
    t.state[i].store(kListed);
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
}

std::size_t pending_temporaries() noexcept {
  std::size_t n = 0;
  for (const auto& s : table().state) n += s.load() == kListed ? 1 : 0;
  return n;
}

}  // namespace hullinspect::io
