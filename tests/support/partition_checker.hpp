#pragma once
// Shared partition checker: every hull cell assigned exactly once (non-hull cells −1), every region
// 4-connected (unless told otherwise; across the seam of request.flights too) and holding its start
// cell (likewise), region sizes matching the reported counts, and balance within `tolerance` of the
// desired weights. With no-fly zones (request.seen_from) every region is flyable: each of its cells
// that some flight component sees is seen from the component of its UAV's start (docs/model.md §8).

#include <gtest/gtest.h>

#include "hullinspect/partition/partitioner.hpp"

namespace hullinspect::testing {

struct PartitionCheck {
  bool regions_hold_starts = true;
  bool regions_connected = true;  ///< false: a region may be several 4-connected pieces
  double tolerance = -1;          ///< < 0: use the partition's reported tolerance
};

::testing::AssertionResult valid_partition(const partition::PartitionRequest& request,
                                           const partition::Partition& result,
                                           PartitionCheck check = {});

}  // namespace hullinspect::testing
