#include "hullinspect/partition/fallback.hpp"

#include <fmt/format.h>

#include "request_checks.hpp"

#include "hullinspect/partition/flight_split.hpp"

namespace hullinspect::partition {

using detail::largest_imbalance;

namespace {

// The fallback rule on a request that lies in one flight space.
Partition partition_one_with_fallback(std::string_view name, const OptionMap& options,
                                      const PartitionRequest& request) {
  Partition first = make_partitioner(name, options)->partition(request);
  if (first.converged || name != "darp") return first;
  Partition second = make_partitioner(kFallbackPartitioner)->partition(request);
  const double darp_worst = largest_imbalance(first);
  const double transfer_worst = largest_imbalance(second);
  if (!second.converged && transfer_worst >= darp_worst) return first;
  std::vector<std::string> warnings = std::move(first.warnings);
  warnings.push_back(fmt::format(
      "darp did not converge (largest imbalance {:g}); the mission uses the {} partitioner's "
      "partition ({}, largest imbalance {:g})",
      darp_worst, kFallbackPartitioner, second.converged ? "converged" : "not converged",
      transfer_worst));
  for (auto& w : second.warnings) warnings.push_back(std::move(w));
  second.warnings = std::move(warnings);
  second.seconds += first.seconds;
  second.fallback = std::string(kFallbackPartitioner);
  return second;
}

}  // namespace

Partition partition_with_fallback(std::string_view name, const OptionMap& options,
                                  const PartitionRequest& request) {
  return partition_per_flight_component(request, [&](const PartitionRequest& one) {
    return partition_one_with_fallback(name, options, one);
  });
}

}  // namespace hullinspect::partition
