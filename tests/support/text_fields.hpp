#pragma once
// Lines and fields of the text files an export writes (csv, WPL), for tests that read them back.

#include <string>
#include <vector>

namespace hullinspect::testing {

/// The fields of `line` between separators `sep` (a trailing empty field is dropped).
std::vector<std::string> split(const std::string& line, char sep);

/// The lines of `text`, without their line ends.
std::vector<std::string> lines_of(const std::string& text);

}  // namespace hullinspect::testing
