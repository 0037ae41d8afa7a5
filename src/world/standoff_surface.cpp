#include "hullinspect/world/standoff_surface.hpp"

#include <cstdlib>
#include <limits>

namespace hullinspect::world {

StandoffSurface standoff_surface(const HullGeometry& g) {
  StandoffSurface out;
  if (!g.unrolled()) return out;
  const int width = g.width();
  const int height = g.height();
  out.point = grid::Grid<Point3>(width, height, Point3{});
  out.normal = grid::Grid<Normal>(width, height, Normal{});
  const auto has_surface = [&](int x, int y) { return g.coverage(x, y) > 0; };
  // The nearest row with surface in column x (ties: the lower row), or -1.
  const auto nearest_row = [&](int x, int y) {
    for (int d = 0; d < height; ++d) {
      if (y - d >= 0 && has_surface(x, y - d)) return y - d;
      if (y + d < height && has_surface(x, y + d)) return y + d;
    }
    return -1;
  };
  for (int x = 0; x < width; ++x) {
    for (int y = 0; y < height; ++y) {
      // The column itself first, then the nearest column with surface (ties: the lower x).
      int from_x = -1, from_y = -1;
      for (int d = 0; d < width && from_y < 0; ++d) {
        for (const int cx : {x - d, x + d}) {
          if (cx < 0 || cx >= width) continue;
          from_y = nearest_row(cx, y);
          if (from_y >= 0) {
            from_x = cx;
            break;
          }
        }
      }
      if (from_y < 0) continue;  // no surface at all: left at the origin
      Point3 p = g.surface(from_x, from_y);
      if (from_x != x || from_y != y) p.z = static_cast<float>(g.centre_z(y));
      out.point(x, y) = p;
      out.normal(x, y) = g.normal(from_x, from_y);
    }
  }
  return out;
}

}  // namespace hullinspect::world
