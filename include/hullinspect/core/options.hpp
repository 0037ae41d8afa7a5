#pragma once
// Named options for registry-built stages (planners, partitioners, TSP solvers): a plain string map
// from configs or the command line, read into each stage's own options struct with range checks.

#include <map>
#include <string>
#include <vector>

namespace hullinspect {

using OptionMap = std::map<std::string, std::string>;

/// Superseded by ParamSpec (core/parameters.hpp); kept until every branch has moved over.
struct OptionSpec {
  std::string name;
  std::string default_value;
  std::string description;
};

/// Superseded by Params<Options> (core/parameters.hpp), which declares each option once; kept
/// until every branch has moved over. Reads typed values from an OptionMap.
class OptionReader {
 public:
  OptionReader(const OptionMap& options, std::string owner);
  int get_int(const std::string& key, int fallback, int min, int max);
  double get_double(const std::string& key, double fallback, double min, double max);
  bool get_bool(const std::string& key, bool fallback);
  std::string get_string(const std::string& key, const std::string& fallback);
  /// Throws ParameterError if the map holds a key that no get_* call asked for.
  void reject_unknown() const;

 private:
  const OptionMap& options_;
  std::string owner_;
  std::vector<std::string> known_;
};

}  // namespace hullinspect
