#include "support/no_fly_layouts.hpp"

#include <utility>

namespace hullinspect::testing {

void no_fly_box(NoFlyMask& mask, int x0, int y0, int x1, int y1) {
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) mask(x, y) = 1;
  }
}

const world::HullMask& small_keel_hull() {
  static const world::HullMask hull = [] {
    grid::Grid<std::uint8_t> m(60, 20, 1);
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 4 - y; ++x) {
        m(x, y) = 0;
        m(59 - x, y) = 0;
      }
    }
    return world::HullMask(std::move(m), "test:small");
  }();
  return hull;
}

}  // namespace hullinspect::testing
