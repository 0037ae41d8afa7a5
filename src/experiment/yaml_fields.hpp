#pragma once
// Strict, typed reading of YAML nodes for configs: every error is an InputError "FILE:LINE: KEY:
// problem" with the node's line (yaml-cpp marks are 0-based; messages are 1-based).

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace hullinspect::experiment::detail {

class YamlFields {
 public:
  explicit YamlFields(std::string source) : source_(std::move(source)) {}

  const std::string& source() const { return source_; }
  static int line(const YAML::Node& node);

  [[noreturn]] void fail(const YAML::Node& node, std::string_view key,
                         std::string_view problem) const;
  [[noreturn]] void fail_at(int line, std::string_view key, std::string_view problem) const;

  /// Checks that `node` is a map whose keys are all in `known` and appear once.
  void expect_map(const YAML::Node& node, std::string_view key,
                  std::initializer_list<std::string_view> known) const;
  void expect_map(const YAML::Node& node, std::string_view key,
                  const std::vector<std::string>& known) const;

  int as_int(const YAML::Node& node, std::string_view key, int min, int max) const;
  std::uint64_t as_seed(const YAML::Node& node, std::string_view key) const;
  double as_number(const YAML::Node& node, std::string_view key, double min, double max) const;
  std::string as_string(const YAML::Node& node, std::string_view key) const;
  /// A label used in result tables: non-empty, no commas, quotes or line breaks (CSV-safe).
  std::string as_label(const YAML::Node& node, std::string_view key) const;
  /// A scalar or a sequence of scalars; items are returned in order.
  std::vector<YAML::Node> as_list(const YAML::Node& node, std::string_view key) const;

 private:
  std::string source_;
};

/// Why a label is not CSV-safe, or empty when it is.
std::string label_problem(std::string_view label);

}  // namespace hullinspect::experiment::detail
