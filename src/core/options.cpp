#include "hullinspect/core/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "hullinspect/core/errors.hpp"

namespace hullinspect {

OptionReader::OptionReader(const OptionMap& options, std::string owner)
    : options_(options), owner_(std::move(owner)) {}

int OptionReader::get_int(const std::string& key, int fallback, int min, int max) {
  known_.push_back(key);
  auto it = options_.find(key);
  if (it == options_.end()) return fallback;
  int value = 0;
  const auto& s = it->second;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size() || value < min || value > max) {
    throw ParameterError(owner_ + "." + key,
                         fmt::format("must be an integer in [{}, {}] (got '{}')", min, max, s));
  }
  return value;
}

double OptionReader::get_double(const std::string& key, double fallback, double min, double max) {
  known_.push_back(key);
  auto it = options_.find(key);
  if (it == options_.end()) return fallback;
  const auto& s = it->second;
  double value = 0;
  std::size_t used = 0;
  bool ok = true;
  try {
    value = std::stod(s, &used);
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok || used != s.size() || !std::isfinite(value) || value < min || value > max) {
    throw ParameterError(owner_ + "." + key,
                         fmt::format("must be a number in [{}, {}] (got '{}')", min, max, s));
  }
  return value;
}

bool OptionReader::get_bool(const std::string& key, bool fallback) {
  known_.push_back(key);
  auto it = options_.find(key);
  if (it == options_.end()) return fallback;
  const auto& s = it->second;
  if (s == "true" || s == "1" || s == "on" || s == "yes") return true;
  if (s == "false" || s == "0" || s == "off" || s == "no") return false;
  throw ParameterError(owner_ + "." + key, fmt::format("must be true or false (got '{}')", s));
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
