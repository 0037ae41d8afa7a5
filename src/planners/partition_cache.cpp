#include "hullinspect/planners/partition_cache.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstring>
#include <functional>

#include "hullinspect/partition/fallback.hpp"

namespace hullinspect::planners {

namespace {

// A key that identifies the request exactly: the mask itself (not its source name), starts,
// weights, shares and seed.
std::string request_key(std::string_view partitioner, const OptionMap& options,
                        const partition::PartitionRequest& r) {
  std::string key(partitioner);
  for (const auto& [k, v] : options) key += fmt::format("|{}={}", k, v);
  const auto& mask = r.hull->mask();
  key += fmt::format("|{}x{}|", mask.width(), mask.height());
  for (auto v : mask.values()) key += static_cast<char>('0' + v);
  for (const auto& s : r.starts) key += fmt::format("|{},{}", s.x, s.y);
  key += fmt::format("|seed={}", r.seed);
  // Weights (prior-aware partitions: one per instance) run-length encoded: they take few
  // distinct values, and an experiment keeps one key per instance.
  const auto& weights = r.weights.values();
  key += "|weights";
  for (std::size_t i = 0; i < weights.size();) {
    std::size_t j = i + 1;
    while (j < weights.size() && weights[j] == weights[i]) ++j;
    key += fmt::format("|{}*{}", weights[i], j - i);
    i = j;
  }
  key += "|shares";
  for (double s : r.shares) key += fmt::format("|{}", s);
  if (r.allowed.size() > 0) {
    key += "|allowed|";
    for (auto v : r.allowed.values()) key += static_cast<char>('0' + v);
  }
  if (r.seen_from.size() > 0) {
    key += "|seen_from";
    for (int v : r.seen_from.values()) key += fmt::format("|{}", v);
  }
  if (!r.flights.empty()) {
    key += "|flights|";
    for (auto v : r.flights.east.values()) key += fmt::format("{},", v);
    key += "|";
    for (auto v : r.flights.north.values()) key += fmt::format("{},", v);
    key += "|seam|";
    for (auto v : r.flights.seam) key += fmt::format("{},", v);
  }
  return key;
}

}  // namespace

std::shared_ptr<const partition::Partition> PartitionCache::get(
    std::string_view partitioner, const OptionMap& options,
    const partition::PartitionRequest& request) {
  const std::string key = request_key(partitioner, options, request);
  std::shared_ptr<Entry> entry;
  {
    std::lock_guard lock(mutex_);
    auto& slot = entries_[key];
    if (!slot) slot = std::make_shared<Entry>();
    entry = slot;
  }
  std::call_once(entry->once, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    entry->partition = std::make_shared<const partition::Partition>(
        partition::partition_with_fallback(partitioner, options, request));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::lock_guard lock(mutex_);
    ++computed_;
    seconds_ += s;
  });
  return entry->partition;
}

int PartitionCache::computed() const {
  std::lock_guard lock(mutex_);
  return computed_;
}

double PartitionCache::seconds() const {
  std::lock_guard lock(mutex_);
  return seconds_;
}

}  // namespace hullinspect::planners
