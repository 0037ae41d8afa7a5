#pragma once

#include <filesystem>
#include <string_view>

namespace hullinspect::io {

/// Writes `content` to a temporary file beside `path`, then renames it over `path`, so a failed or
/// interrupted run never leaves a half-written file. Throws InputError naming the path on failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Reads a whole file; throws InputError naming the path if it cannot be read.
std::string read_file(const std::filesystem::path& path);

}  // namespace hullinspect::io
