#include "hullinspect/planners/coop_frontier_nearest.hpp"

#include <algorithm>
#include <bit>
#include <cstdlib>

#include "hullinspect/grid/distance.hpp"

namespace hullinspect::planners {

void NearestSourceIndex::reset(int width, int height) {
  width_ = width;
  height_ = height;
  words_ = (height + 63) / 64;
  columns_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(words_), 0);
  column_count_.assign(static_cast<std::size_t>(width), 0);
  count_ = 0;
  additions_ = 0;
  const auto cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  cached_.assign(cells, Cached{});
}

void NearestSourceIndex::set(int index, bool member) {
  const int x = index % width_;
  const int y = index / width_;
  std::uint64_t& word = columns_[static_cast<std::size_t>(x) * static_cast<std::size_t>(words_) +
                                 static_cast<std::size_t>(y / 64)];
  const std::uint64_t bit = std::uint64_t{1} << (y % 64);
  if (member) {
    word |= bit;
    ++column_count_[static_cast<std::size_t>(x)];
    ++count_;
    ++additions_;
  } else {
    word &= ~bit;
    --column_count_[static_cast<std::size_t>(x)];
    --count_;
  }
}

int NearestSourceIndex::nearest_in_column(int x, int y, int& row) const {
  const std::uint64_t* column =
      &columns_[static_cast<std::size_t>(x) * static_cast<std::size_t>(words_)];
  int best = -1;
  // Upwards from y: the lowest member row ≥ y.
  for (int w = y / 64; w < words_; ++w) {
    std::uint64_t bits = column[w];
    if (w == y / 64) bits &= ~std::uint64_t{0} << (y % 64);
    if (bits != 0) {
      row = 64 * w + std::countr_zero(bits);
      best = row - y;
      break;
    }
  }
  // Downwards: the highest member row ≤ y, if nearer.
  for (int w = y / 64; w >= 0; --w) {
    std::uint64_t bits = column[w];
    if (w == y / 64 && y % 64 != 63) bits &= (std::uint64_t{1} << (y % 64 + 1)) - 1;
    if (bits != 0) {
      const int down = 64 * w + 63 - std::countl_zero(bits);
      if (best < 0 || y - down < best) {
        row = down;
        best = y - down;
      }
      break;
    }
  }
  return best;
}

int NearestSourceIndex::distance(int index) const {
  if (count_ == 0) return grid::kUnreachable;
  Cached& cached = cached_[static_cast<std::size_t>(index)];
  // The set only lost members since: the cached nearest, still a member, is still the nearest.
  if (cached.at == additions_ && cached.word >= 0 &&
      (columns_[static_cast<std::size_t>(cached.word)] & cached.bit) != 0) {
    return cached.distance;
  }
  const int x = index % width_;
  const int y = index / width_;
  int best = grid::kUnreachable;
  int best_column = -1;
  int best_row = -1;
  for (int dx = 0; dx < best && (x - dx >= 0 || x + dx < width_); ++dx) {
    for (const int c : {x - dx, x + dx}) {
      if (c < 0 || c >= width_ || column_count_[static_cast<std::size_t>(c)] == 0) continue;
      int row = 0;
      const int dy = nearest_in_column(c, y, row);
      if (dy >= 0 && dx + dy < best) {
        best = dx + dy;
        best_column = c;
        best_row = row;
      }
      if (dx == 0) break;  // x − 0 and x + 0 are one column
    }
  }
  cached.at = additions_;
  cached.distance = best;
  cached.word = best_column < 0 ? -1 : best_column * words_ + best_row / 64;
  cached.bit = best_column < 0 ? 0 : std::uint64_t{1} << (best_row % 64);
  return best;
}

}  // namespace hullinspect::planners
