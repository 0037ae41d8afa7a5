#pragma once
// The entries of a zip archive (a DJI KMZ), for tests that read the flight files back.

#include <map>
#include <string>

namespace hullinspect::testing {

/// Every entry of the zip archive at `path`, by name; records a test failure and returns none
/// when it is not a zip archive.
std::map<std::string, std::string> unzip(const std::string& path);

}  // namespace hullinspect::testing
