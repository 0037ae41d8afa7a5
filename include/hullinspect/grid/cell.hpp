#pragma once

#include <compare>
#include <cstdlib>

namespace hullinspect::grid {

/// A grid cell. x runs along the hull (0 = stern), y upward (0 = bottom).
struct Cell {
  int x = 0;
  int y = 0;
  friend constexpr bool operator==(Cell, Cell) = default;
  /// Orders by (y, x): the model's tie-break order ("lowest (y, x)").
  friend constexpr std::strong_ordering operator<=>(Cell a, Cell b) {
    if (auto c = a.y <=> b.y; c != 0) return c;
    return a.x <=> b.x;
  }
};

constexpr int manhattan(Cell a, Cell b) {
  return std::abs(a.x - b.x) + std::abs(a.y - b.y);
}
/// max(|Δx|, |Δy|): the distance the separation rule measures (docs/model.md, "Separation").
constexpr int chebyshev(Cell a, Cell b) {
  const int dx = std::abs(a.x - b.x);
  const int dy = std::abs(a.y - b.y);
  return dx > dy ? dx : dy;
}

/// A cell that is none: returned when no answer exists.
inline constexpr Cell kNoCell{-1, -1};

/// The four neighbour offsets in a fixed order: east, west, north (up), south (down).
inline constexpr int kNeighbourDx[4] = {1, -1, 0, 0};
inline constexpr int kNeighbourDy[4] = {0, 0, 1, -1};

}  // namespace hullinspect::grid
