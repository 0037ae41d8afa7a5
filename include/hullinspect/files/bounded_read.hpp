#pragma once
// Reading an input whole, with a size limit checked before and while it is read, so that
// `--hull /dev/zero` or a 10 GB file fails at once with one line instead of exhausting memory.

#include <cstddef>
#include <filesystem>
#include <string>

namespace hullinspect::io {

/// The limit of io::read_file(path) (atomic_file.hpp) when its caller gives none.
inline constexpr std::size_t kDefaultInputLimit = std::size_t{256} << 20;

/// Reads a whole file of at most `limit` bytes; throws InputError naming the path if it cannot be
/// read, is a directory, or is larger (a device such as /dev/zero stops at the limit).
/// `what` names the input in "cannot open the hull file".
std::string read_file(const std::filesystem::path& path, std::size_t limit,
                      const char* what = "the file");

}  // namespace hullinspect::io
