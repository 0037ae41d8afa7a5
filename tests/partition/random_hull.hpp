#pragma once
// Test helper: random hull masks (non-convex, with holes, 4-connected) and random start cells,
// drawn from a seeded RandomStream so every run and platform sees the same shapes.

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "hullinspect/grid/distance.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::testing {

/// A width × height rectangle with random rectangular holes inside it and bites out of its border,
/// reduced to its largest 4-connected component (so HullMask accepts it).
inline world::HullMask random_hull(std::uint64_t seed, int width, int height) {
  world::RandomStream rs(seed, 101);
  auto below = [&](int n) { return static_cast<int>(rs.below(static_cast<std::uint64_t>(n))); };
  grid::Grid<std::uint8_t> mask(width, height, 1);
  auto clear = [&](int x0, int y0, int w, int h) {
    for (int y = std::max(0, y0); y < std::min(height, y0 + h); ++y) {
      for (int x = std::max(0, x0); x < std::min(width, x0 + w); ++x) mask(x, y) = 0;
    }
  };
  const int holes = 2 + below(4);
  for (int k = 0; k < holes; ++k) {  // strictly inside: holes, not notches
    const int w = 2 + below(std::max(1, width / 5));
    const int h = 2 + below(std::max(1, height / 4));
    // Named draws: the order of a call's arguments is unspecified (GCC and clang differ); y is
    // drawn first, the order the shapes were first drawn in.
    const int y0 = 1 + below(std::max(1, height - h - 2));
    const int x0 = 1 + below(std::max(1, width - w - 2));
    clear(x0, y0, w, h);
  }
  const int bites = 2 + below(4);
  for (int k = 0; k < bites; ++k) {  // from the border: makes the outline non-convex
    const int w = 2 + below(std::max(1, width / 4));
    const int h = 2 + below(std::max(1, height / 2));
    const bool left = below(2) == 0;
    const bool bottom = below(2) == 0;
    const int x0 = below(2) == 0 ? (left ? 0 : width - w) : below(std::max(1, width - w));
    const int y0 = bottom ? 0 : height - h;
    clear(x0, y0, w, h);
  }
  grid::Grid<int> labels;
  grid::BfsScratch scratch;
  const int parts = grid::label_components(mask, labels, scratch);
  std::vector<int> sizes(static_cast<std::size_t>(parts), 0);
  for (int i = 0; i < mask.size(); ++i) {
    if (labels[i] >= 0) ++sizes[static_cast<std::size_t>(labels[i])];
  }
  const auto largest =
      static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (int i = 0; i < mask.size(); ++i) mask[i] = labels[i] == largest;
  // Make sure of one hole: clear a cell whose eight neighbours are all hull (the ring around it
  // keeps the hull 4-connected).
  std::vector<int> inner;
  for (int y = 1; y + 1 < height; ++y) {
    for (int x = 1; x + 1 < width; ++x) {
      bool ring = true;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) ring = ring && mask(x + dx, y + dy);
      }
      if (ring) inner.push_back(mask.index(x, y));
    }
  }
  if (!inner.empty()) mask[inner[rs.below(inner.size())]] = 0;
  return world::HullMask(std::move(mask), "random:" + std::to_string(seed));
}

/// n distinct hull cells drawn uniformly.
inline std::vector<grid::Cell> random_starts(const world::HullMask& hull, int n,
                                             std::uint64_t seed) {
  world::RandomStream rs(seed, 102);
  std::vector<grid::Cell> starts;
  while (static_cast<int>(starts.size()) < n) {
    const int i = hull.cells()[rs.below(hull.cells().size())];
    const grid::Cell c = hull.mask().cell(i);
    if (std::find(starts.begin(), starts.end(), c) == starts.end()) starts.push_back(c);
  }
  return starts;
}

}  // namespace hullinspect::testing
