#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace hullinspect::io {

/// Writes `content` to a temporary file beside `path`, then renames it over `path`, so a failed or
/// interrupted run never leaves a half-written file. Throws InputError naming the path on failure.
/// Commands with user-named outputs use OutputSet (output_set.hpp), which also refuses devices,
/// directories and outputs that are one of the inputs.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// The size limit of read_file unless its caller gives another (inputs are read whole).
inline constexpr std::size_t kDefaultInputLimit = std::size_t{256} << 20;

/// Reads a whole file of at most `limit` bytes; throws InputError naming the path if it cannot be
/// read, is a directory, or is larger (a device such as /dev/zero stops at the limit).
std::string read_file(const std::filesystem::path& path, std::size_t limit = kDefaultInputLimit);

}  // namespace hullinspect::io
