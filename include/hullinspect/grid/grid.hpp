#pragma once

#include <cassert>
#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"

namespace hullinspect::grid {

/// Dense row-major matrix indexed [y][x] (size height × width = b × a), as the paper's C, C', M, A.
/// Cells are also addressed by a flat index y * width + x.
template <class T>
class Grid {
 public:
  Grid() = default;
  Grid(int width, int height, T fill = T{})
      : width_(width), height_(height), data_(static_cast<std::size_t>(width) * height, fill) {}

  int width() const { return width_; }
  int height() const { return height_; }
  int size() const { return static_cast<int>(data_.size()); }

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  bool contains(Cell c) const { return contains(c.x, c.y); }
  int index(int x, int y) const { return y * width_ + x; }
  int index(Cell c) const { return index(c.x, c.y); }
  Cell cell(int index) const { return {index % width_, index / width_}; }

  T& operator()(int x, int y) {
    assert(contains(x, y));
    return data_[static_cast<std::size_t>(index(x, y))];
  }
  const T& operator()(int x, int y) const {
    assert(contains(x, y));
    return data_[static_cast<std::size_t>(index(x, y))];
  }
  T& operator[](Cell c) { return (*this)(c.x, c.y); }
  const T& operator[](Cell c) const { return (*this)(c.x, c.y); }
  T& operator[](int i) { return data_[static_cast<std::size_t>(i)]; }
  const T& operator[](int i) const { return data_[static_cast<std::size_t>(i)]; }

  std::span<T> values() { return data_; }
  std::span<const T> values() const { return data_; }
  void fill(T value) { std::fill(data_.begin(), data_.end(), value); }

  friend bool operator==(const Grid&, const Grid&) = default;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<T> data_;
};

}  // namespace hullinspect::grid
