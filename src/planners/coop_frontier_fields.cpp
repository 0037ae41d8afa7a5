#include "hullinspect/planners/coop_frontier_fields.hpp"

namespace hullinspect::planners {

void SourceDistanceField::reset(int width, int height, grid::DistanceService* distances,
                                int on_demand_cells) {
  distances_ = distances;
  on_demand_ = (distances == nullptr || !distances->has_no_fly()) &&
               static_cast<long long>(width) * height > on_demand_cells;
  member_ = grid::Grid<std::uint8_t>(width, height, 0);
  if (on_demand_) {
    nearest_.reset(width, height);
    distance_ = grid::Grid<int>();
  } else {
    distance_ = grid::Grid<int>(width, height, grid::kUnreachable);
  }
  incremental_ = !on_demand_ && (distances == nullptr || !distances->searched());
  if (incremental_) {
    removed_.clear();
    removed_.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  }
  needs_transform_ = false;  // the empty set's field is already exact
  count_ = 0;
  stale_ = false;
}

void SourceDistanceField::set(int index, bool member) {
  std::uint8_t& m = member_[index];
  if ((m != 0) == member) return;
  m = member ? 1 : 0;
  count_ += member ? 1 : -1;
  if (on_demand_) {
    nearest_.set(index, member);
    return;
  }
  stale_ = true;
  if (!incremental_ || needs_transform_) return;
  if (member) {
    needs_transform_ = true;
    removed_.clear();
  } else {
    removed_.push_back(index);
  }
}

void SourceDistanceField::refresh() {
  if (!stale_) return;
  stale_ = false;
  if (incremental_ && !needs_transform_) {
    remove_members(removed_, member_, distance_);
    removed_.clear();
    ++partial_updates_;
    return;
  }
  needs_transform_ = false;
  if (distances_ != nullptr) {
    distances_->distances_from(member_, distance_);
  } else {
    grid::manhattan_distance_transform(member_, distance_);
  }
  ++transforms_;
}

}  // namespace hullinspect::planners
