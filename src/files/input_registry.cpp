#include "hullinspect/files/input_registry.hpp"

#include <sys/stat.h>

#include <mutex>
#include <vector>

namespace hullinspect::io {

namespace {

std::mutex registry_mutex;
std::uint64_t next_sequence = 0;  // guarded by registry_mutex

std::vector<RegisteredInput>& registry() {
  static std::vector<RegisteredInput> inputs;
  return inputs;
}

}  // namespace

const char* file_kind(const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return "a directory";
  if (S_ISCHR(st.st_mode)) return "a character device";
  if (S_ISBLK(st.st_mode)) return "a block device";
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  if (S_ISREG(st.st_mode)) return "a regular file";
  return "not a regular file";
}

std::uint64_t next_input_sequence() {
  const std::lock_guard lock(registry_mutex);
  return next_sequence;
}

void register_input(const std::filesystem::path& path, dev_t device, ino_t inode) {
  const std::lock_guard lock(registry_mutex);
  const std::uint64_t sequence = next_sequence++;
  for (RegisteredInput& in : registry()) {
    if (in.device == device && in.inode == inode) {
      in.path = path;
      in.sequence = sequence;
      return;
    }
  }
  registry().push_back({device, inode, path, sequence});
}

std::optional<RegisteredInput> registered_input_at(const std::filesystem::path& path,
                                                   std::uint64_t since) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  const std::lock_guard lock(registry_mutex);
  for (const RegisteredInput& in : registry()) {
    if (in.device == st.st_dev && in.inode == st.st_ino && in.sequence >= since) return in;
  }
  return std::nullopt;
}

}  // namespace hullinspect::io
