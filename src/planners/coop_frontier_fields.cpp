#include "hullinspect/planners/coop_frontier_fields.hpp"

namespace hullinspect::planners {

void SourceDistanceField::reset(int width, int height, grid::DistanceService* distances) {
  distances_ = distances;
  member_ = grid::Grid<std::uint8_t>(width, height, 0);
  distance_ = grid::Grid<int>(width, height, grid::kUnreachable);
  count_ = 0;
  stale_ = false;
}

void SourceDistanceField::set(int index, bool member) {
  std::uint8_t& m = member_[index];
  if ((m != 0) == member) return;
  m = member ? 1 : 0;
  count_ += member ? 1 : -1;
  stale_ = true;
}

void SourceDistanceField::refresh() {
  if (!stale_) return;
  if (distances_ != nullptr) {
    distances_->distances_from(member_, distance_);
  } else {
    grid::manhattan_distance_transform(member_, distance_);
  }
  ++transforms_;
  stale_ = false;
}

}  // namespace hullinspect::planners
