#include "hullinspect/files/output_set.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/core/output_error.hpp"
#include "hullinspect/files/input_registry.hpp"

namespace hullinspect::io {

namespace fs = std::filesystem;

namespace {

std::string shown(const fs::path& p) {
  return escape_for_message(p.string(), 200);
}

fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p) : r;
}

// The directory an output is created in ("." for a bare file name).
fs::path parent_of(const fs::path& p) {
  const fs::path parent = fs::absolute(p).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

// An output directory is created with its missing parents (like mkdir -p, as `--out results/x`
// always did), so for one the nearest existing ancestor is checked instead.
void check_parent(const fs::path& path, const std::string& option, bool create_parents) {
  fs::path parent = parent_of(path);
  struct stat st {};
  if (create_parents) {
    while (::stat(parent.c_str(), &st) != 0 && parent.has_relative_path()) {
      parent = parent.parent_path();
    }
  }
  if (::stat(parent.c_str(), &st) != 0) {
    throw ParameterError(option, fmt::format("cannot write '{}': directory '{}' does not exist",
                                             shown(path), shown(parent)));
  }
  if (!S_ISDIR(st.st_mode)) {
    throw ParameterError(option, fmt::format("cannot write '{}': '{}' is not a directory",
                                             shown(path), shown(parent)));
  }
  if (::access(parent.c_str(), W_OK | X_OK) != 0) {
    throw ParameterError(option, fmt::format("cannot write '{}': directory '{}': {}", shown(path),
                                             shown(parent), std::strerror(errno)));
  }
}

std::atomic<int> temporary_counter{0};

}  // namespace

bool same_file(const fs::path& a, const fs::path& b) {
  struct stat sa {};
  struct stat sb {};
  if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0) {
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  }
  return resolved(a) == resolved(b);
}

OutputSet::OutputSet() : first_input_(next_input_sequence()) {}

OutputSet::~OutputSet() {
  for (const auto& out : outputs_) {
    if (!out.temporary.empty()) ::unlink(out.temporary.c_str());
  }
  // Directories write() created for a command that failed: innermost first (empty by now).
  for (auto it = created_dirs_.rbegin(); it != created_dirs_.rend(); ++it) ::rmdir(it->c_str());
}

const OutputSet::Entry* OutputSet::declared_parent_dir(const fs::path& path) const {
  const fs::path parent = parent_of(path);
  for (const auto& out : outputs_) {
    if (out.directory && resolved(out.path) == resolved(parent)) return &out;
  }
  return nullptr;
}

void OutputSet::add_input(const fs::path& path, std::string option) {
  if (!path.empty()) inputs_.push_back({path, std::move(option), false, {}, false, {}});
}

void OutputSet::add_output(const fs::path& path, std::string option) {
  if (!path.empty()) outputs_.push_back({path, std::move(option), false, {}, false, {}});
}

void OutputSet::add_output_dir(const fs::path& path, std::string option, bool must_be_empty) {
  if (!path.empty()) outputs_.push_back({path, std::move(option), true, {}, must_be_empty, {}});
}

void OutputSet::check() const {
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    const Entry& out = outputs_[k];
    struct stat st {};
    if (::stat(out.path.c_str(), &st) == 0) {
      if (out.directory && !S_ISDIR(st.st_mode)) {
        throw ParameterError(out.option, fmt::format("'{}' is {}, expected a directory",
                                                     shown(out.path), file_kind(st)));
      }
      if (!out.directory && !S_ISREG(st.st_mode)) {
        throw ParameterError(out.option,
                             fmt::format("'{}' is {}; an output must be a regular file or a new "
                                         "path",
                                         shown(out.path), file_kind(st)));
      }
      if (out.directory && ::access(out.path.c_str(), W_OK | X_OK) != 0) {
        throw ParameterError(out.option, fmt::format("cannot write into '{}': {}", shown(out.path),
                                                     std::strerror(errno)));
      }
      if (out.directory && out.must_be_empty) check_empty(out);
    } else if (errno != ENOENT) {
      throw ParameterError(
          out.option, fmt::format("cannot use '{}': {}", shown(out.path), std::strerror(errno)));
    }
    // A file in a declared output directory that does not exist yet: that directory's own check
    // (with its parents) covers where it goes.
    const bool in_new_dir = !out.directory && ::stat(parent_of(out.path).c_str(), &st) != 0 &&
                            declared_parent_dir(out.path) != nullptr;
    if (!in_new_dir && (!out.directory || ::stat(out.path.c_str(), &st) != 0)) {
      check_parent(out.path, out.option, out.directory);
    }
    for (const Entry& in : inputs_) {
      if (same_file(out.path, in.path)) {
        throw ParameterError(out.option,
                             fmt::format("'{}' is the same file as the {} '{}'; it would be "
                                         "overwritten",
                                         shown(out.path), in.option, shown(in.path)));
      }
    }
    check_not_read(out);
    for (std::size_t j = 0; j < k; ++j) {
      if (same_file(out.path, outputs_[j].path)) {
        throw ParameterError(
            out.option, fmt::format("'{}' is the same file as the output of --{} '{}'",
                                    shown(out.path), outputs_[j].option, shown(outputs_[j].path)));
      }
    }
  }
}

void OutputSet::write(const fs::path& path, std::string_view content) {
  Entry* entry = nullptr;
  for (auto& out : outputs_) {
    if (!out.directory && out.path == path) entry = &out;
  }
  if (entry == nullptr)
    throw LogicError(fmt::format("output '{}' was not declared", path.string()));
  // Every input has been read by the time an output is written: refuse one now, before the
  // command prints its result (commit() checks again for inputs read later).
  check_not_read(*entry);
  if (struct stat st{};
      ::stat(parent_of(path).c_str(), &st) != 0 && declared_parent_dir(path) != nullptr) {
    // The declared output directory and its missing parents, outermost first.
    std::vector<fs::path> missing;
    for (fs::path d = parent_of(path); ::stat(d.c_str(), &st) != 0 && d.has_relative_path();
         d = d.parent_path()) {
      missing.push_back(d);
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      if (::mkdir(it->c_str(), 0777) != 0 && errno != EEXIST) {
        throw OutputError(it->string(),
                          fmt::format("cannot create the directory: {}", std::strerror(errno)));
      }
      created_dirs_.push_back(*it);
    }
  }
  if (entry->temporary.empty()) {
    entry->temporary =
        parent_of(path) / fmt::format(".{}.tmp-{}-{}", path.filename().string(),
                                      static_cast<long>(::getpid()), temporary_counter++);
    entry->pending = PendingTemporary(entry->temporary);
  }
  const int fd = ::open(entry->temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int err = errno;
    entry->temporary.clear();
    entry->pending.release();
    throw OutputError(path.string(), fmt::format("cannot write: {}", std::strerror(err)));
  }
  bool ok = true;
  while (ok && !content.empty()) {
    const ssize_t n = ::write(fd, content.data(), content.size());
    if (n < 0 && errno == EINTR) continue;
    ok = n >= 0;
    if (ok) content.remove_prefix(static_cast<std::size_t>(n));
  }
  int err = ok ? 0 : errno;
  if (::close(fd) != 0 && ok) {
    ok = false;
    err = errno;
  }
  if (!ok) throw OutputError(path.string(), fmt::format("write failed: {}", std::strerror(err)));
}

void OutputSet::check_empty(const Entry& out) {
  std::error_code ec;
  fs::directory_iterator it(out.path, ec);
  if (ec) {
    throw ParameterError(out.option,
                         fmt::format("cannot list '{}': {}", shown(out.path), ec.message()));
  }
  if (it == fs::directory_iterator()) return;
  // The first name in order, so that the message does not depend on the directory's layout.
  fs::path first = it->path().filename();
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    first = std::min(first, it->path().filename());
  }
  throw ParameterError(out.option,
                       fmt::format("'{}' is not empty (it holds '{}'); give a new or empty "
                                   "directory, or --force to write into it",
                                   shown(out.path), shown(first)));
}

void OutputSet::check_not_read(const Entry& out) const {
  if (out.directory) return;
  if (const auto in = registered_input_at(out.path, first_input_)) {
    throw ParameterError(out.option,
                         fmt::format("'{}' is the same file as the input '{}'; it would be "
                                     "overwritten",
                                     shown(out.path), shown(in->path)));
  }
}

void OutputSet::commit() {
  // Inputs read since check() (a prior, a no-fly map, a mesh) are known only now.
  for (const auto& out : outputs_) {
    if (!out.temporary.empty()) check_not_read(out);
  }
  for (auto& out : outputs_) {
    if (out.temporary.empty()) continue;
    if (::rename(out.temporary.c_str(), out.path.c_str()) != 0) {
      throw OutputError(out.path.string(),
                        fmt::format("cannot rename into place: {}", std::strerror(errno)));
    }
    out.temporary.clear();
    out.pending.release();
  }
  created_dirs_.clear();  // they hold the outputs now
}

}  // namespace hullinspect::io
