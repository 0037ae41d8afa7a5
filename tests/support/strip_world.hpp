#pragma once
// A small world for simulator tests: a 20 × 5 grid whose hull is rows 1..3 (rows 0 and 4 are open
// water along the hull), no corrosion, one UAV starting at (5, 2) with footprints s1 = 1, s2 = 3.

#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::testing {

struct StripWorld {
  world::HullMask hull{make_mask(), "test"};
  world::Instance instance;
  world::MissionParams params;
  StripWorld() {
    instance.truth = grid::Grid<std::int8_t>(20, 5, 0);
    instance.prior = grid::Grid<std::int8_t>(20, 5, 0);
    params.uavs = 1;
    params.s1 = 1;
    params.s2 = 3;
    params.starts = {{5, 2}};
  }
  static grid::Grid<std::uint8_t> make_mask() {
    grid::Grid<std::uint8_t> m(20, 5, 0);
    for (int y = 1; y <= 3; ++y)
      for (int x = 0; x < 20; ++x) m(x, y) = 1;
    return m;
  }
};

}  // namespace hullinspect::testing
