#include "hullinspect/planners/band_rejoin.hpp"

#include <algorithm>
#include <cstdlib>

#include "sweep_inspect_detail.hpp"

namespace hullinspect::planners {

using sweep_inspect_detail::leg_along_x;
using sweep_inspect_detail::unobserved;

grid::Cell band_rejoin_point(const LeftBand& band, grid::Cell pos, int half,
                             const sim::PlannerView& view, const grid::DistanceService& flights) {
  const grid::Cell end = band.end;
  const grid::Cell left = band.left;
  const bool rows = leg_along_x(band.axis, left, end);
  const int end_along = rows ? end.x : end.y;
  const int left_along = rows ? left.x : left.y;
  const int line = rows ? left.y : left.x;
  if ((rows ? end.y : end.x) != line || end_along == left_along) return left;
  const int dir = end_along > left_along ? 1 : -1;
  const int reach = std::min(std::max(0, dir * ((rows ? pos.x : pos.y) - left_along)),
                             std::abs(end_along - left_along));
  const auto& map = view.map;
  const int across_size = rows ? map.height() : map.width();
  int ahead = 0;
  for (int r = 1; r <= reach; ++r) {
    // The band's cells across at `along`, just behind r's footprint, must have been observed.
    const int along = left_along + dir * (r - half - 1);
    if (r > 2 * half + 1) {
      bool gap = false;
      for (int a = std::max(0, line - half); a <= std::min(across_size - 1, line + half); ++a) {
        const int i = rows ? map.index(along, a) : map.index(a, along);
        if (map[i] != sim::kNotHull && unobserved(view, i)) gap = true;
      }
      if (gap) break;
    }
    const grid::Cell candidate =
        rows ? grid::Cell{left_along + dir * r, line} : grid::Cell{line, left_along + dir * r};
    if (flights.allowed(candidate)) ahead = r;
  }
  return rows ? grid::Cell{left_along + dir * ahead, line}
              : grid::Cell{line, left_along + dir * ahead};
}

}  // namespace hullinspect::planners
