#pragma once
// The rule for names chosen by users for registry entries (planners registered from C++ or
// Python): names appear in configs, CSV rows, command lines and messages, so a name that would need
// quoting there (empty, blanks, quotes, newlines) is refused when it is registered.

#include <string>
#include <string_view>

namespace hullinspect {

inline constexpr std::size_t kMaxRegistryNameLength = 64;

/// Throws ParameterError(parameter, …) unless `name` is 1 to 64 characters, each a letter, digit,
/// '-', '_' or '.', the first a letter or digit. `kind` ("planner") names the entry in the message.
void check_registry_name(std::string_view kind, const std::string& parameter,
                         std::string_view name);

}  // namespace hullinspect
