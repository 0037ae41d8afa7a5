#include "hullinspect/planners/part_tsp_segments.hpp"

#include <algorithm>

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
