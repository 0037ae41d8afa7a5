#include "hullinspect/core/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"

namespace hullinspect {

OptionReader::OptionReader(const OptionMap& options, std::string owner)
    : options_(options), owner_(std::move(owner)) {}

int OptionReader::get_int(const std::string& key, int fallback, int min, int max) {
  known_.push_back(key);
  auto it = options_.find(key);
  if (it == options_.end()) return fallback;
  try {
    return parse_integer<int>(it->second, min, max);
  } catch (const NumberError& e) {
    throw ParameterError(owner_ + "." + key, e.what());
  }
}

double OptionReader::get_double(const std::string& key, double fallback, double min, double max) {
  known_.push_back(key);
  auto it = options_.find(key);
  if (it == options_.end()) return fallback;
  try {
    return parse_real(it->second, min, max);
  } catch (const NumberError& e) {
    throw ParameterError(owner_ + "." + key, e.what());
  }
}

bool OptionReader::get_bool(const std::string& key, bool fallback) {
  known_.push_back(key);
  auto it = options_.find(key);
  if (it == options_.end()) return fallback;
  const auto& s = it->second;
  if (s == "true" || s == "1" || s == "on" || s == "yes") return true;
  if (s == "false" || s == "0" || s == "off" || s == "no") return false;
  throw ParameterError(owner_ + "." + key,
                       fmt::format("must be true or false (got '{}')", escape_for_message(s)));
}

std::string OptionReader::get_string(const std::string& key, const std::string& fallback) {
  known_.push_back(key);
  auto it = options_.find(key);
  return it == options_.end() ? fallback : it->second;
}

void OptionReader::reject_unknown() const {
  for (const auto& [key, value] : options_) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
      std::string list;
      for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
      throw ParameterError(owner_ + "." + key,
                           fmt::format("unknown option (known: {})", list.empty() ? "none" : list));
    }
  }
}

}  // namespace hullinspect
