#pragma once
// Partitions per flight component (docs/model.md §8, "Flight components"): when no-fly positions
// cut the flight space into parts with UAVs in several of them, a UAV can only ever see the hull
// cells seen from its own part. Each hull cell goes to the flight component that sees it
// (PartitionRequest::seen_from); each component's cells are cut into their 4-connected pieces, and
// each piece holding starts is partitioned among the UAVs starting in it by the given partitioner
// (a sub-request on that piece, with the component's positions only). A piece without a start goes
// whole to the UAV of its component with the shortest flight to it. Cells no one sees (they are
// left out of the metrics) are balanced against nothing: afterwards each joins the region of the
// nearest owned cell over hull cells.
//
// With one flight space in which every hull cell is seen (no `seen_from`, or every start in one
// component and no cell unseen) the request goes to the partitioner unchanged, so results are bit
// for bit those of the partitioner alone.

#include <functional>

#include "hullinspect/partition/partitioner.hpp"

namespace hullinspect::partition {

/// Partitions one request that lies in one flight space.
using PartitionOne = std::function<Partition(const PartitionRequest&)>;

/// The partition of `request`, made per flight component with `partition_one` as above. The
/// merged partition: owners in global UAV ids; per UAV its piece's cells and desired weight
/// (plus any piece it was given whole); iterations and seconds summed; converged when every piece
/// converged; the largest tolerance; each piece's warnings prefixed with the UAVs it concerns;
/// `fallback` set when some piece used one.
Partition partition_per_flight_component(const PartitionRequest& request,
                                         const PartitionOne& partition_one);

/// The flight component of each UAV's start (-1 when its start is seen from none); empty when the
/// request has no `seen_from`.
std::vector<int> start_components(const PartitionRequest& request);

}  // namespace hullinspect::partition
