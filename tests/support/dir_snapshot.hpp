#pragma once
// What a directory holds, to check that a refused command changed nothing in it.

#include <filesystem>
#include <map>
#include <string>

namespace hullinspect::testing {

/// The bytes of the file at `path` ("" if it cannot be read).
std::string slurp(const std::filesystem::path& path);

/// Every entry under `dir` (recursively), by its path relative to `dir`: "symlink:TARGET",
/// "file:BYTES", "dir" or "other" (a FIFO, a socket, a device).
std::map<std::string, std::string> snapshot(const std::filesystem::path& dir);

}  // namespace hullinspect::testing
