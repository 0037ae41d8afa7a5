#pragma once
// The partition a mission uses (docs/model.md, "Partition fallback"): the requested partitioner's,
// except when DARP does not converge — then the `transfer` partitioner's partition of the same
// request, when it is better balanced. DARP stays the paper's partitioner: wherever it converges
// the mission's partition is DARP's, bit for bit; `hullinspect partition --partitioner darp` always
// shows DARP's own result.

#include <string_view>

#include "hullinspect/core/options.hpp"
#include "hullinspect/partition/partitioner.hpp"

namespace hullinspect::partition {

/// The partitioner a non-converged DARP partition falls back to.
inline constexpr std::string_view kFallbackPartitioner = "transfer";

/// `name`'s partition of `request` with `options`; when `name` is "darp" and DARP did not converge,
/// the `transfer` partitioner (default options, same request and seed) is run as well and its
/// partition is returned instead if it converged or its largest imbalance is smaller. The returned
/// partition then has `fallback` = "transfer", DARP's warnings followed by one saying so, and
/// `seconds` covering both runs. A request whose starts lie in several flight components is
/// partitioned per component (partition/flight_split.hpp), the rule applying to each piece.
Partition partition_with_fallback(std::string_view name, const OptionMap& options,
                                  const PartitionRequest& request);

}  // namespace hullinspect::partition
