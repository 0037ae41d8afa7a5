#include "hullinspect/planners/part_tsp_segments.hpp"

#include <algorithm>
#include <cstdlib>

namespace hullinspect::planners::part_tsp {

void divide_into_segments(const LocalMaps& maps, int k, int z, std::int8_t value,
                          std::vector<StripSegment>& out) {
  out.clear();
  const StripLayout& layout = maps.layout(z);
  const int x_begin = maps.x_begin(k);
  const int x_end = maps.x_end(k);
  for (int j = 0; j < layout.strips(); ++j) {
    int run_start = -1;
    for (int x = x_begin; x <= x_end; ++x) {
      const bool targeted = x < x_end && maps.column_count(k, z, value, j, x) > 0;
      if (targeted && run_start < 0) run_start = x;
      if (!targeted && run_start >= 0) {
        out.push_back(StripSegment{j, layout.flight_row(j), run_start, x - 1});
        run_start = -1;
      }
    }
  }
}

void divide_around_no_fly(const LocalMaps& maps, int k, int z, std::int8_t value, int trim,
                          grid::DistanceService& distances, std::vector<StripSegment>& out,
                          std::vector<std::pair<grid::Cell, grid::Cell>>& ends) {
  out.clear();
  ends.clear();
  const StripLayout& layout = maps.layout(z);
  const int half = world::footprint_half(layout.s);
  const int x_begin = maps.x_begin(k);
  const int x_end = maps.x_end(k);
  for (int j = 0; j < layout.strips(); ++j) {
    const int row = layout.flight_row(j);
    const std::size_t strip_first = out.size();
    int run_start = -1;
    for (int x = x_begin; x <= x_end; ++x) {
      const bool targeted = x < x_end && maps.column_count(k, z, value, j, x) > 0 &&
                            distances.allowed(grid::Cell{x, row});
      if (targeted && run_start < 0) run_start = x;
      if (!targeted && run_start >= 0) {
        out.push_back(StripSegment{j, row, run_start, x - 1});
        ends.push_back(segment_ends(out.back(), trim));
        run_start = -1;
      }
    }
    const std::size_t strip_segments = out.size();
    // Targeted columns whose flight-row position is no-fly: seen from a neighbouring segment's
    // footprint, else from point visits.
    for (int x = x_begin; x < x_end; ++x) {
      if (maps.column_count(k, z, value, j, x) == 0 || distances.allowed(grid::Cell{x, row})) {
        continue;
      }
      bool seen = false;
      for (std::size_t s = strip_first; s < strip_segments && !seen; ++s) {
        seen = x >= ends[s].first.x - half && x <= ends[s].second.x + half;
      }
      if (seen) continue;
      for (int y = layout.first_row(j); y <= layout.last_row(j); ++y) {
        const grid::Cell c{x, y};
        if (maps.owner(c) != k || maps.value(c) != value) continue;
        bool covered = false;
        for (std::size_t s = strip_segments; s < out.size() && !covered; ++s) {
          const grid::Cell p = out[s].point;
          covered = std::abs(p.x - c.x) <= half && std::abs(p.y - c.y) <= half;
        }
        if (covered) continue;
        const grid::Cell v = distances.viewpoint(c, half);
        if (v == grid::kNoCell) continue;
        out.push_back(StripSegment{j, v.y, x, x, v});
        ends.emplace_back(v, v);
      }
    }
  }
}

bool has_targets(const LocalMaps& maps, int k, int z, std::int8_t value,
                 const StripSegment& segment, int x_from, int x_to) {
  const int lo = std::max(std::min(x_from, x_to), segment.x_left);
  const int hi = std::min(std::max(x_from, x_to), segment.x_right);
  for (int x = lo; x <= hi; ++x) {
    if (maps.column_count(k, z, value, segment.strip, x) > 0) return true;
  }
  return false;
}

std::pair<grid::Cell, grid::Cell> segment_ends(const StripSegment& segment, int trim) {
  int left = segment.x_left;
  int right = segment.x_right;
  if (trim > 0) {
    if (right - left >= 2 * trim) {
      left += trim;
      right -= trim;
    } else {
      left = right = (left + right) / 2;
    }
  }
  return {grid::Cell{left, segment.row}, grid::Cell{right, segment.row}};
}

}  // namespace hullinspect::planners::part_tsp
