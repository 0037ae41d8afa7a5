#pragma once
// A thread-safe PartitionSource that computes each distinct partition once. A partition depends
// only on the partitioner (name, options), the hull, the start cells, weights, shares and its seed —
// not on the instance — so all missions of an experiment cell share one.

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "hullinspect/planners/planner.hpp"

namespace hullinspect::planners {

class PartitionCache final : public PartitionSource {
 public:
  std::shared_ptr<const partition::Partition> get(std::string_view partitioner, const OptionMap& options,
                                                  const partition::PartitionRequest& request) override;
  /// Partitions computed (cache misses) so far.
  int computed() const;
  /// Seconds spent computing partitions.
  double seconds() const;

 private:
  struct Entry {
    std::once_flag once;
    std::shared_ptr<const partition::Partition> partition;
  };
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<Entry>> entries_;
  int computed_ = 0;
  double seconds_ = 0;
};

}  // namespace hullinspect::planners
