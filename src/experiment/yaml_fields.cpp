#include "yaml_fields.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <set>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"

namespace hullinspect::experiment::detail {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += fmt::format("{}{}", out.empty() ? "" : ", ", n);
  return out;
}

std::string shown(const YAML::Node& node) {
  if (node.IsScalar()) return fmt::format("'{}'", escape_for_message(node.Scalar()));
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "nothing";
}

}  // namespace

int YamlFields::line(const YAML::Node& node) {
  const auto mark = node.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

void YamlFields::fail(const YAML::Node& node, std::string_view key,
                      std::string_view problem) const {
  fail_at(line(node), key, problem);
}

void YamlFields::fail_at(int at, std::string_view key, std::string_view problem) const {
  throw InputError(source_, at, fmt::format("{}: {}", key, problem));
}

void YamlFields::expect_map(const YAML::Node& node, std::string_view key,
                            std::initializer_list<std::string_view> known) const {
  expect_map(node, key, std::vector<std::string>(known.begin(), known.end()));
}

void YamlFields::expect_map(const YAML::Node& node, std::string_view key,
                            const std::vector<std::string>& known) const {
  if (!node.IsMap()) {
    fail(node, key.empty() ? "config" : key, fmt::format("must be a map (got {})", shown(node)));
  }
  std::set<std::string> seen;
  for (const auto& entry : node) {
    const YAML::Node& k = entry.first;
    const std::string name = k.IsScalar() ? escape_for_message(k.Scalar()) : std::string("?");
    const std::string path = key.empty() ? name : fmt::format("{}.{}", key, name);
    bool ok = false;
    for (const auto& n : known) ok = ok || n == name;
    if (!ok) fail(k, path, fmt::format("unknown key (known: {})", join(known)));
    if (!seen.insert(name).second) fail(k, path, "appears twice");
  }
}

int YamlFields::as_int(const YAML::Node& node, std::string_view key, int min, int max) const {
  long long value = 0;
  try {
    if (!node.IsScalar()) throw NumberError("not a scalar");
    value = parse_integer<long long>(node.Scalar());
  } catch (const NumberError&) {
    fail(node, key, fmt::format("must be an integer (got {})", shown(node)));
  }
  if (value < min || value > max) {
    fail(node, key, fmt::format("must be an integer in [{}, {}] (got {})", min, max, value));
  }
  return static_cast<int>(value);
}

std::uint64_t YamlFields::as_seed(const YAML::Node& node, std::string_view key) const {
  try {
    if (!node.IsScalar()) throw NumberError("not a scalar");
    return parse_integer<std::uint64_t>(node.Scalar());
  } catch (const NumberError&) {
    fail(node, key,
         fmt::format("must be a non-negative integer seed below 2^64 (got {})", shown(node)));
  }
}

double YamlFields::as_number(const YAML::Node& node, std::string_view key, double min,
                             double max) const {
  double value = 0;
  try {
    if (!node.IsScalar()) throw NumberError("not a scalar");
    value = parse_real(node.Scalar(), -std::numeric_limits<double>::max(),
                       std::numeric_limits<double>::max());
  } catch (const NumberError&) {
    fail(node, key, fmt::format("must be a number (got {})", shown(node)));
  }
  if (value < min || value > max) {
    fail(node, key,
         fmt::format("must be a number in [{}, {}] (got {})", min, max,
                     escape_for_message(node.Scalar())));
  }
  return value;
}

std::string YamlFields::as_string(const YAML::Node& node, std::string_view key) const {
  if (!node.IsScalar()) fail(node, key, fmt::format("must be a string (got {})", shown(node)));
  return node.Scalar();
}

std::string YamlFields::as_label(const YAML::Node& node, std::string_view key) const {
  std::string s = as_string(node, key);
  if (auto problem = label_problem(s); !problem.empty()) fail(node, key, problem);
  return s;
}

std::vector<YAML::Node> YamlFields::as_list(const YAML::Node& node, std::string_view key) const {
  std::vector<YAML::Node> items;
  if (node.IsScalar()) {
    items.push_back(node);
  } else if (node.IsSequence()) {
    for (const auto& item : node) items.push_back(item);
    if (items.empty()) fail(node, key, "must not be an empty list");
  } else {
    fail(node, key, fmt::format("must be a value or a list of values (got {})", shown(node)));
  }
  return items;
}

std::string label_problem(std::string_view label) {
  if (label.empty()) return "must not be empty";
  for (char c : label) {
    if (c == ',' || c == '"' || c == '\n' || c == '\r') {
      return fmt::format(
          "'{}' must not contain commas, quotes or line breaks (it names a CSV "
          "value)",
          escape_for_message(label));
    }
  }
  return {};
}

}  // namespace hullinspect::experiment::detail
