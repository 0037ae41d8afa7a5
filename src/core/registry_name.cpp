#include "hullinspect/core/registry_name.hpp"

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"

namespace hullinspect {

namespace {
bool is_alnum(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}
}  // namespace

void check_registry_name(std::string_view kind, const std::string& parameter,
                         std::string_view name) {
  bool ok = !name.empty() && name.size() <= kMaxRegistryNameLength && is_alnum(name.front());
  for (const char c : name) ok = ok && (is_alnum(c) || c == '-' || c == '_' || c == '.');
  if (ok) return;
  throw ParameterError(parameter,
                       fmt::format("a {} name must be 1 to {} letters, digits, '-', '_' or '.', "
                                   "starting with a letter or digit (got '{}')",
                                   kind, kMaxRegistryNameLength, escape_for_message(name)));
}

}  // namespace hullinspect
