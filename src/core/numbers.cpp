#include "hullinspect/core/numbers.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hullinspect {

std::string escape_for_message(std::string_view text, std::size_t max_chars) {
  std::string out;
  std::size_t shown = 0;
  for (const char ch : text) {
    if (shown == max_chars) {
      out += "…";
      break;
    }
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\\') {
      out += "\\\\";
    } else if (c < 0x20 || c >= 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += ch;
    }
    ++shown;
  }
  return out;
}

namespace detail {

bool is_plain_integer(std::string_view text, bool allow_minus) {
  std::size_t i = 0;
  if (allow_minus && !text.empty() && text[0] == '-') i = 1;
  if (i == text.size()) return false;
  for (; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return false;
  }
  return true;
}

void throw_integer_error(std::string_view text, std::string_view min, std::string_view max) {
  throw NumberError(
      fmt::format("must be an integer in [{}, {}] (got '{}')", min, max, escape_for_message(text)));
}

}  // namespace detail

namespace {
[[noreturn]] void throw_real_error(std::string_view shown, double min, double max) {
  if (min == -kRealLimit && max == kRealLimit) {
    throw NumberError(fmt::format("must be a finite number of magnitude at most 1e15 (got '{}')",
                                  escape_for_message(shown)));
  }
  throw NumberError(fmt::format("must be a number in [{:g}, {:g}] (got '{}')", min, max,
                                escape_for_message(shown)));
}
}  // namespace

double parse_real(std::string_view text, double min, double max) {
  double value = 0;
  // from_chars accepts "inf", "nan" and hex floats only with their own spellings; std::isfinite
  // and the range check below refuse the first two, out-of-range literals fail with an errc.
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value) || value < min || value > max) {
    throw_real_error(text, min, max);
  }
  return value;
}

double check_real(double value, double min, double max) {
  if (!std::isfinite(value) || value < min || value > max) {
    throw_real_error(fmt::format("{}", value), min, max);
  }
  return value;
}

}  // namespace hullinspect
