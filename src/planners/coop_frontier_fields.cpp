#include "hullinspect/planners/coop_frontier_fields.hpp"

#include <algorithm>

namespace hullinspect::planners {

void manhattan_distance_transform(const grid::Grid<std::uint8_t>& sources, grid::Grid<int>& out) {
  const int w = sources.width();
  const int h = sources.height();
  if (out.width() != w || out.height() != h) out = grid::Grid<int>(w, h);
  // kUnreachable + 1 cannot overflow (kUnreachable = INT_MAX / 4), so no special case is needed.
  constexpr int kFar = grid::kUnreachable;
  // Forward pass: nearest source below or to the left (and any mix of those moves).
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      int d = sources[i] ? 0 : kFar;
      if (x > 0) d = std::min(d, out[i - 1] + 1);
      if (y > 0) d = std::min(d, out[i - w] + 1);
      out[i] = d;
    }
  }
  // Backward pass: combines with the sources above or to the right. Two passes are exact for the
  // city-block metric because every shortest path can be ordered as one monotone run per pass.
  for (int y = h - 1; y >= 0; --y) {
    for (int x = w - 1; x >= 0; --x) {
      const int i = y * w + x;
      int d = out[i];
      if (x + 1 < w) d = std::min(d, out[i + 1] + 1);
      if (y + 1 < h) d = std::min(d, out[i + w] + 1);
      out[i] = std::min(d, kFar);
    }
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

