#include "hullinspect/world/standoff_surface.hpp"

#include <cmath>
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

namespace hullinspect::world {

namespace {
// Divided, not multiplied, by the scale: 0.09 prints as 0.09, not 0.09000000000000001.
double rounded(double v, double scale) {
  return std::round(v * scale) / scale;
}
}  // namespace

grid::StandoffPoints standoff_points(const HullGeometry& g) {
  grid::StandoffPoints out;
  const StandoffSurface s = standoff_surface(g);
  if (s.point.size() == 0) return out;
  out.point = grid::Grid<std::array<double, 3>>(s.point.width(), s.point.height());
  out.normal = grid::Grid<std::array<double, 3>>(s.point.width(), s.point.height());
  for (int i = 0; i < s.point.size(); ++i) {
    const Point3 p = s.point[i];
    const Normal n = s.normal[i];
    out.point[i] = {rounded(p.x, 1e4), rounded(p.y, 1e4), rounded(p.z, 1e4)};
    out.normal[i] = {rounded(n.x, 1e6), rounded(n.y, 1e6), rounded(n.z, 1e6)};
  }
  out.seam = g.seam;
  return out;
}

grid::FlightSteps neighbour_flights(const HullMask& hull, const MissionParams& params) {
  const HullGeometry* g = hull.geometry();
  if (g == nullptr || !g->unrolled()) return {};
  return grid::flight_steps(standoff_points(*g), params.cell_size_m, params.theta_deg, params.s1,
                            params.s2);
}

grid::EdgeSteps seam_links(const HullMask& hull) {
  const HullGeometry* g = hull.geometry();
  if (g == nullptr || !g->seam || hull.width() < 3) return {};
  grid::EdgeSteps links;
  links.east = grid::Grid<std::uint8_t>(hull.width(), hull.height(), 1);
  links.north = grid::Grid<std::uint8_t>(hull.width(), hull.height(), 1);
  links.seam.assign(static_cast<std::size_t>(hull.height()), 1);
  return links;
}

}  // namespace hullinspect::world
