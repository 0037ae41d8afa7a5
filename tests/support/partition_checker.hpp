#pragma once
// Shared partition checker: every hull cell assigned exactly once (non-hull cells −1), every region
// 4-connected and (unless told otherwise) holding its start cell, region sizes matching the reported
// counts, and balance within `tolerance` of the desired weights.

#include <gtest/gtest.h>

#include "hullinspect/partition/partitioner.hpp"

namespace hullinspect::testing {

struct PartitionCheck {
  bool regions_hold_starts = true;
  double tolerance = -1;  ///< < 0: use the partition's reported tolerance
};

::testing::AssertionResult valid_partition(const partition::PartitionRequest& request,
                                           const partition::Partition& result,
                                           PartitionCheck check = {});

}  // namespace hullinspect::testing
