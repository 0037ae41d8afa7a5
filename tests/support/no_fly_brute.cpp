#include "support/no_fly_brute.hpp"

namespace hullinspect::testing {

std::pair<int, int> brute_unreachable(const world::HullMask& hull,
                                      const grid::Grid<std::uint8_t>& no_fly,
                                      const std::vector<grid::Cell>& starts, int s1, int s2) {
  grid::Grid<std::uint8_t> flyable(hull.width(), hull.height(), 0);
  std::vector<grid::Cell> stack(starts.begin(), starts.end());
  for (const auto& s : starts) flyable[s] = 1;
  while (!stack.empty()) {
    const grid::Cell c = stack.back();
    stack.pop_back();
    for (int d = 0; d < 4; ++d) {
      const grid::Cell n{c.x + grid::kNeighbourDx[d], c.y + grid::kNeighbourDy[d]};
      if (!flyable.contains(n) || flyable[n] || no_fly[n]) continue;
      flyable[n] = 1;
      stack.push_back(n);
    }
  }
  auto count = [&](int s) {
    const int half = (s - 1) / 2;
    int unreachable = 0;
    for (int i : hull.cells()) {
      const grid::Cell c = hull.mask().cell(i);
      bool seen = false;
      for (int y = c.y - half; y <= c.y + half && !seen; ++y) {
        for (int x = c.x - half; x <= c.x + half && !seen; ++x) {
          seen = flyable.contains(x, y) && flyable(x, y);
        }
      }
      unreachable += seen ? 0 : 1;
    }
    return unreachable;
  };
  return {count(s1), count(s2)};
}

}  // namespace hullinspect::testing
