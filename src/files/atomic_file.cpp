#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/bounded_read.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/output_error.hpp"
#include "hullinspect/files/pending_temporaries.hpp"
#include "hullinspect/files/input_registry.hpp"

namespace hullinspect::io {

namespace {

// Writes all of `content` to `fd`, retrying short writes; false on any error (errno set).
bool write_all(int fd, std::string_view content) {
  while (!content.empty()) {
    const ssize_t n = ::write(fd, content.data(), content.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    content.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  const std::filesystem::path tmp =
      path.string() + fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  const PendingTemporary pending(tmp);  // removed by the CLI's signal handler until renamed
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0)
    throw OutputError(path.string(), fmt::format("cannot write: {}", std::strerror(errno)));
  const bool written = write_all(fd, content);
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw OutputError(path.string(), fmt::format("write failed: {}",
                                                 std::strerror(written ? errno : write_errno)));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw OutputError(path.string(), fmt::format("cannot rename into place: {}", ec.message()));
  }
}

std::string read_file(const std::filesystem::path& path, std::size_t limit, const char* what) {
  const std::string name = path.string();
  // O_NONBLOCK: opening a FIFO without a writer would otherwise wait forever; it is refused below
  // like every file that is not a regular file (and regular files ignore the flag).
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    if (errno == ENOENT) throw InputError(name, 0, fmt::format("cannot open {}", what));
    throw InputError(name, 0, fmt::format("cannot open {}: {}", what, std::strerror(errno)));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    throw InputError(name, 0, fmt::format("cannot open {}: {}", what, std::strerror(err)));
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd);
    throw InputError(name, 0, "is a directory, expected a file");
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    throw InputError(name, 0, fmt::format("is {}, expected a regular file", file_kind(st)));
  }
  std::string bytes;
  if (static_cast<std::size_t>(st.st_size) > limit) {
    ::close(fd);
    throw InputError(name, 0,
                     fmt::format("is larger than the {} MiB limit for this input", limit >> 20));
  }
  register_input(path, st.st_dev, st.st_ino);
  char buffer[65536];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      throw InputError(name, 0, fmt::format("cannot read: {}", std::strerror(err)));
    }
    if (n == 0) break;
    if (bytes.size() + static_cast<std::size_t>(n) > limit) {
      ::close(fd);
      throw InputError(name, 0,
                       fmt::format("is larger than the {} MiB limit for this input", limit >> 20));
    }
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return bytes;
}

std::string read_file(const std::filesystem::path& path) {
  return read_file(path, kDefaultInputLimit);
}

}  // namespace hullinspect::io
