#include "hullinspect/planners/coop_frontier_cell_set.hpp"

namespace hullinspect::planners {

void IndexedCellSet::reset(int width, int height) {
  width_ = width;
  height_ = height;
  const auto cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  slot_.assign(cells, -1);
  indices_.clear();
  indices_.reserve(cells);
  cells_.clear();
  cells_.reserve(cells);
}

void IndexedCellSet::insert(int index) {
  int& slot = slot_[static_cast<std::size_t>(index)];
  if (slot >= 0) return;
  slot = static_cast<int>(indices_.size());
  indices_.push_back(index);
  cells_.push_back({index % width_, index / width_});
}

void IndexedCellSet::erase(int index) {
  int& slot = slot_[static_cast<std::size_t>(index)];
  if (slot < 0) return;
  const auto at = static_cast<std::size_t>(slot);
  const int last = indices_.back();
  indices_[at] = last;
  cells_[at] = cells_.back();
  slot_[static_cast<std::size_t>(last)] = slot;
  indices_.pop_back();
  cells_.pop_back();
  slot = -1;
}

}  // namespace hullinspect::planners
