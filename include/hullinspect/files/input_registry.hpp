#pragma once
// The files this process has read, recorded by the one function that opens input files
// (io::read_file), so that io::OutputSet can refuse an output that would overwrite any of them
// whatever option named it and however its path is spelled (links and hard links included: files
// are compared by device and inode). Each record carries a sequence number, so that an OutputSet
// considers the files read while it exists (its command's), not those of earlier work in the same
// process (a test, a Python session).

#include <sys/stat.h>
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace hullinspect::io {

struct RegisteredInput {
  dev_t device = 0;
  ino_t inode = 0;
  std::filesystem::path path;  // as it was opened, for messages
  std::uint64_t sequence = 0;  // when it was last read: later reads have larger numbers
};

/// The sequence number the next recorded read will get.
std::uint64_t next_input_sequence();

/// What kind of file `st` describes, for messages ("a FIFO", "a directory", "a regular file").
const char* file_kind(const struct stat& st);

/// Records that `path` (whose stat gave `device` and `inode`) was read. Thread-safe; a file
/// recorded twice is kept once, with its latest sequence number.
void register_input(const std::filesystem::path& path, dev_t device, ino_t inode);

/// The input recorded with a sequence number of at least `since` that is the same file as the
/// existing file `path`, if any.
std::optional<RegisteredInput> registered_input_at(const std::filesystem::path& path,
                                                   std::uint64_t since);

}  // namespace hullinspect::io
