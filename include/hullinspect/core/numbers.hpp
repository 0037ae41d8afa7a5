#pragma once
// The one number parser of hullinspect: every integer and real read from a command line, a YAML
// config, a JSON file (TSP instances, traces) or a stage option goes through here, so "-1" never
// becomes 2^64 - 1, "4294967306" never becomes 10 and "1e400" or "nan" never becomes a value.
//
// Integers: optional '-', then decimal digits, nothing else ("1e3", "1.0", "+1", " 1" are refused);
// the value must lie in [min, max] (default: the whole range of T) and is computed exactly.
// Reals: a decimal or scientific literal as std::from_chars reads it; it must be finite and lie in
// [min, max] (default: ±kRealLimit). Errors are NumberError, whose what() is one line such as
// "must be an integer in [0, 18446744073709551615] (got '-1')"; callers prefix the option, field or
// file:line (see numbers.cpp for the wrappers used by the CLI, YAML, JSON and OptionReader).

#include <charconv>
#include <concepts>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "hullinspect/core/errors.hpp"

namespace hullinspect {

/// A text that is not a number in the accepted range. what() is the problem only (no name).
class NumberError : public Error {
 public:
  using Error::Error;
};

/// The largest magnitude a real parameter or file value may have unless its caller says otherwise
/// (far beyond every physical quantity of the model, far below overflow in sums and products).
inline constexpr double kRealLimit = 1e15;

/// `text` for an error message: at most `max_chars` characters, control and non-ASCII bytes
/// escaped as \n, \t, \xNN, so a message always stays on one line.
std::string escape_for_message(std::string_view text, std::size_t max_chars = 60);

namespace detail {
[[noreturn]] void throw_integer_error(std::string_view text, std::string_view min,
                                      std::string_view max);
bool is_plain_integer(std::string_view text, bool allow_minus);
}  // namespace detail

/// Parses the whole of `text` as an integer in [min, max]; throws NumberError otherwise.
template <std::integral T>
T parse_integer(std::string_view text, T min = std::numeric_limits<T>::min(),
                T max = std::numeric_limits<T>::max()) {
  T value{};
  bool ok = detail::is_plain_integer(text, std::is_signed_v<T>);
  if (ok) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    ok = ec == std::errc() && end == text.data() + text.size() && !std::cmp_less(value, min) &&
         !std::cmp_greater(value, max);
  }
  if (!ok) detail::throw_integer_error(text, std::to_string(min), std::to_string(max));
  return value;
}

/// Parses the whole of `text` as a finite real in [min, max]; throws NumberError otherwise.
double parse_real(std::string_view text, double min = -kRealLimit, double max = kRealLimit);

/// Checks an already-decoded real (e.g. from a JSON parser) the same way: finite, in [min, max].
double check_real(double value, double min = -kRealLimit, double max = kRealLimit);

}  // namespace hullinspect
