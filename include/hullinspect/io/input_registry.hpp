#pragma once
// The files this process has read, recorded by the one function that opens input files
// (io::read_file), so that io::OutputSet can refuse an output that would overwrite any of them
// whatever option named it and however its path is spelled (links and hard links included: files
// are compared by device and inode).

#include <sys/stat.h>
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>

namespace hullinspect::io {

struct RegisteredInput {
  dev_t device = 0;
  ino_t inode = 0;
  std::filesystem::path path;  // as it was opened, for messages
};

/// What kind of file `st` describes, for messages ("a FIFO", "a directory", "a regular file").
const char* file_kind(const struct stat& st);

/// Records that `path` (whose stat gave `device` and `inode`) was read. Thread-safe; a file
/// recorded twice is kept once.
void register_input(const std::filesystem::path& path, dev_t device, ino_t inode);

/// The recorded input that is the same file as the existing file `path`, if any.
std::optional<RegisteredInput> registered_input_at(const std::filesystem::path& path);

}  // namespace hullinspect::io
