#include "support/seam_hull.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "hullinspect/world/hull_geometry.hpp"

namespace hullinspect::testing {

world::HullMask seam_cylinder_hull(std::string_view text, double cell_size) {
  world::HullMask hull = world::parse_text_mask(text, "seam-cylinder");
  const int w = hull.width();
  const int h = hull.height();
  const double radius = w * cell_size / (2 * std::numbers::pi);
  world::HullGeometry g;
  g.side = world::HullSide::both;
  g.cell_size = cell_size;
  g.x0 = -0.5 * w * cell_size;
  g.depth = grid::Grid<float>(w, h, 0.0f);
  g.coverage = grid::Grid<float>(w, h, 0.0f);
  g.normal = grid::Grid<world::Normal>(w, h);
  g.surface = grid::Grid<world::Point3>(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double angle = 2 * std::numbers::pi * (x + 0.5) / w;
      const auto c = static_cast<float>(std::cos(angle));
      const auto s = static_cast<float>(std::sin(angle));
      g.normal(x, y) = {c, s, 0.0f};
      g.surface(x, y) = {static_cast<float>(radius) * c, static_cast<float>(radius) * s,
                         static_cast<float>((y + 0.5) * cell_size)};
      g.coverage(x, y) = hull.is_hull(x, y) ? 1.0f : 0.0f;
    }
  }
  g.seam = true;
  hull.attach_geometry(std::move(g));
  return hull;
}

}  // namespace hullinspect::testing
