#include "hullinspect/planners/coop_frontier_distance_floor.hpp"

namespace hullinspect::planners {

void DistanceFloor::reset(int cells, int levels) {
  head_.assign(static_cast<std::size_t>(std::max(1, levels)), -1);
  const auto n = static_cast<std::size_t>(std::max(0, cells));
  next_.assign(n, -1);
  prev_.assign(n, -1);
  level_.assign(n, -1);
  low_ = 0;
}

void DistanceFloor::add(int index) {
  if (level_[static_cast<std::size_t>(index)] == 0) return;  // already waiting in bucket 0
  unlink(index);
  link(index, 0);
  low_ = 0;
}

void DistanceFloor::link(int index, int level) {
  const auto i = static_cast<std::size_t>(index);
  int& head = head_[static_cast<std::size_t>(level)];
  level_[i] = level;
  prev_[i] = -1;
  next_[i] = head;
  if (head >= 0) prev_[static_cast<std::size_t>(head)] = index;
  head = index;
}

void DistanceFloor::unlink(int index) {
  const auto i = static_cast<std::size_t>(index);
  const int level = level_[i];
  if (level < 0) return;
  if (prev_[i] >= 0) {
    next_[static_cast<std::size_t>(prev_[i])] = next_[i];
  } else {
    head_[static_cast<std::size_t>(level)] = next_[i];
  }
  if (next_[i] >= 0) prev_[static_cast<std::size_t>(next_[i])] = prev_[i];
  level_[i] = -1;
  next_[i] = prev_[i] = -1;
}

}  // namespace hullinspect::planners
