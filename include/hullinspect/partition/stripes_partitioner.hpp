#pragma once

#include "hullinspect/partition/partitioner.hpp"

namespace hullinspect::partition {

/// Equal-area vertical bands: hull cells taken column by column (x, then y upward) and cut into n
/// consecutive runs of equal weight (or of the requested shares). Band i goes to the UAV whose
/// start cell has the i-th smallest x (ties by y, then id); start cells are otherwise ignored, so a
/// region need not contain its UAV's start. Throws Error if a band is not 4-connected (hulls whose
/// columns are not single runs of cells); use DARP for such hulls.
class StripesPartitioner final : public Partitioner {
 public:
  Partition partition(const PartitionRequest& request) const override;
};

}  // namespace hullinspect::partition
