#pragma once
// An integer option whose own check gives the reason for its range ("--uavs: must be at least 1")
// still names that range, not its C++ type's, when its text is no integer at all.

#include <concepts>
#include <string>
#include <string_view>

#include "hullinspect/core/numbers.hpp"

namespace hullinspect {

/// Parses the whole of `text` as any T, for a value whose own check refuses a T outside
/// [min, max] with its reason: text that is no T at all ("x", "1e3", 10^11) is refused naming
/// [min, max], the value's range, not T's ("must be an integer in [1, 16777216] (got 'x')").
template <std::integral T>
T parse_integer_of_range(std::string_view text, T min, T max) {
  try {
    return parse_integer<T>(text);
  } catch (const NumberError&) {
    detail::throw_integer_error(text, std::to_string(min), std::to_string(max));
  }
}

}  // namespace hullinspect
