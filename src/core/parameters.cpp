#include "hullinspect/core/parameters.hpp"

#include "hullinspect/core/numbers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace hullinspect {

std::string_view param_type_name(ParamType type) {
  switch (type) {
    case ParamType::kInt:
      return "int";
    case ParamType::kDouble:
      return "double";
    case ParamType::kBool:
      return "bool";
    case ParamType::kString:
      return "string";
    case ParamType::kEnum:
      return "enum";
    case ParamType::kNested:
      return "options";
  }
  return "string";
}

std::string describe_params(const std::vector<ParamSpec>& specs, std::string_view indent) {
  std::string out;
  for (const auto& s : specs) {
    std::string detail(param_type_name(s.type));
    if (s.type != ParamType::kNested) {
      detail += ", default " + (s.default_value.empty() ? std::string("''") : s.default_value);
    }
    if (!s.range.empty() && s.type != ParamType::kBool) detail += ", " + s.range;
    out += fmt::format("{}{} ({}): {}\n", indent, s.name, detail, s.description);
  }
  return out;
}

// Both go through the shared number parser (core/numbers.hpp): exact integers, finite reals.
long long parse_int_param(const std::string& owner_key, const std::string& text, long long min,
                          long long max) {
  try {
    return parse_integer<long long>(text, min, max);
  } catch (const NumberError& e) {
    throw ParameterError(owner_key, e.what());
  }
}

double parse_double_param(const std::string& owner_key, const std::string& text, double min,
                          double max) {
  try {
    return parse_real(text, min, max);
  } catch (const NumberError& e) {
    throw ParameterError(owner_key, e.what());
  }
}

bool parse_bool_param(const std::string& owner_key, const std::string& text) {
  if (text == "true" || text == "1" || text == "on" || text == "yes") return true;
  if (text == "false" || text == "0" || text == "off" || text == "no") return false;
  throw ParameterError(owner_key,
                       fmt::format("must be true or false (got '{}')", escape_for_message(text)));
}

std::string param_text(double value) {
  return fmt::format("{}", value);
}
std::string param_text(long long value) {
  return std::to_string(value);
}
std::string param_text(bool value) {
  return value ? "true" : "false";
}

namespace {

std::string folded(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '_') c = '-';
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closest_name(std::string_view key, const std::vector<std::string>& known) {
  const std::string k = folded(key);
  std::string best;
  std::size_t best_distance = 3;  // at most two edits away
  for (const auto& name : known) {
    const std::size_t d = folded(name) == k ? 0 : edit_distance(k, folded(name));
    if (d < best_distance && d < std::max<std::size_t>(k.size(), 1)) {
      best = name;
      best_distance = d;
    }
  }
  return best;
}

void throw_unknown_param(const std::string& owner, const std::string& key,
                         const std::vector<std::string>& known) {
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  std::string message = "unknown option";
  if (auto near = closest_name(key, known); !near.empty()) {
    message += fmt::format(" (did you mean {}?)", near);
  }
  throw ParameterError(owner + "." + key,
                       fmt::format("{} (known: {})", message, list.empty() ? "none" : list));
}

}  // namespace hullinspect
