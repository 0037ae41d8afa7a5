#include "hullinspect/planners/coop_frontier_distance_floor.hpp"

namespace hullinspect::planners {

void DistanceFloor::reset(int cells, int levels) {
  buckets_.assign(static_cast<std::size_t>(std::max(1, levels)), {});
  level_.assign(static_cast<std::size_t>(std::max(0, cells)), -1);
  low_ = 0;
}

void DistanceFloor::add(int index) {
  int& level = level_[static_cast<std::size_t>(index)];
  if (level == 0) return;  // already waiting in bucket 0
  level = 0;
  buckets_.front().push_back(index);
  low_ = 0;
}

}  // namespace hullinspect::planners
