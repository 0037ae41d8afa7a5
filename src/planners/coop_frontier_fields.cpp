#include "hullinspect/planners/coop_frontier_fields.hpp"

#include <algorithm>

namespace hullinspect::planners {

void manhattan_distance_transform(const grid::Grid<std::uint8_t>& sources, grid::Grid<int>& out) {
  const int w = sources.width();
  const int h = sources.height();
  if (out.width() != w || out.height() != h) out = grid::Grid<int>(w, h);
  // kUnreachable + 1 cannot overflow (kUnreachable = INT_MAX / 4), so no special case is needed.
  constexpr int kFar = grid::kUnreachable;
  const std::uint8_t* src = sources.values().data();
  int* d = out.values().data();
  // Forward pass, row by row from the bottom: nearest source below (a column-wise step the compiler
  // can vectorise), then to the left (a running scan along the row).
  for (int y = 0; y < h; ++y) {
    int* row = d + static_cast<std::ptrdiff_t>(y) * w;
    const std::uint8_t* s = src + static_cast<std::ptrdiff_t>(y) * w;
    if (y == 0) {
      for (int x = 0; x < w; ++x) row[x] = s[x] ? 0 : kFar;
    } else {
      const int* below = row - w;
      for (int x = 0; x < w; ++x) row[x] = s[x] ? 0 : below[x] + 1;
    }
    for (int x = 1; x < w; ++x) row[x] = std::min(row[x], row[x - 1] + 1);
  }
  // Backward pass from the top: above, then to the right. Two passes are exact for the city-block
  // metric: a shortest path to a source can be ordered as one monotone run per pass.
  for (int y = h - 1; y >= 0; --y) {
    int* row = d + static_cast<std::ptrdiff_t>(y) * w;
    if (y + 1 < h) {
      const int* above = row + w;
      for (int x = 0; x < w; ++x) row[x] = std::min(row[x], above[x] + 1);
    }
    for (int x = w - 2; x >= 0; --x) row[x] = std::min(row[x], row[x + 1] + 1);
    for (int x = 0; x < w; ++x) row[x] = std::min(row[x], kFar);
  }
}

void SourceDistanceField::reset(int width, int height) {
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
  manhattan_distance_transform(member_, distance_);
  ++transforms_;
  stale_ = false;
}

}  // namespace hullinspect::planners
