#include "hullinspect/planners/coop_frontier_claims.hpp"

#include <algorithm>
#include <cstdlib>

#include "hullinspect/sim/types.hpp"

namespace hullinspect::planners {

void InspectionClaims::reset(int uavs, int width, int height) {
  const auto cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  owner_.assign(cells, -1);
  claims_.resize(static_cast<std::size_t>(uavs));
  for (auto& c : claims_) {
    c.clear();
    c.reserve(cells);  // claims never reallocate during a mission
  }
}

bool InspectionClaims::claim(int uav, int index) {
  int& owner = owner_[static_cast<std::size_t>(index)];
  if (owner >= 0) return owner == uav;
  owner = uav;
  claims_[static_cast<std::size_t>(uav)].push_back(index);
  return true;
}

void InspectionClaims::release_all(int uav) {
  auto& list = claims_[static_cast<std::size_t>(uav)];
  for (int i : list) {
    if (owner_[static_cast<std::size_t>(i)] == uav) owner_[static_cast<std::size_t>(i)] = -1;
  }
  list.clear();
}

std::optional<grid::Cell> InspectionClaims::inspect_target(
    int uav, grid::Cell pos, const grid::Grid<std::int8_t>& map, int radius,
    const grid::Grid<int>* distance_from_pos) {
  std::optional<grid::Cell> best;
  int best_d = 0;
  auto consider = [&](grid::Cell c) {
    const int d = distance_from_pos != nullptr ? (*distance_from_pos)[c] : grid::manhattan(pos, c);
    if (!best || d < best_d || (d == best_d && c < *best)) {
      best = c;
      best_d = d;
    }
  };
  // Claimed cells, compacting away those already inspected or cleared.
  auto& list = claims_[static_cast<std::size_t>(uav)];
  std::size_t kept = 0;
  for (int i : list) {
    if (map[i] != sim::kCorrosionSeen) {
      owner_[static_cast<std::size_t>(i)] = -1;
      continue;
    }
    list[kept++] = i;
    consider(map.cell(i));
  }
  list.resize(kept);
  // Every M = 2 cell in the diamond of the close-up radius.
  for (int dy = -radius; dy <= radius; ++dy) {
    const int y = pos.y + dy;
    if (y < 0 || y >= map.height()) continue;
    const int reach = radius - std::abs(dy);
    const int x0 = std::max(0, pos.x - reach);
    const int x1 = std::min(map.width() - 1, pos.x + reach);
    for (int x = x0; x <= x1; ++x) {
      // Shortest flights are never shorter than Manhattan, so the diamond holds every candidate.
      if (map(x, y) != sim::kCorrosionSeen) continue;
      if (distance_from_pos != nullptr && (*distance_from_pos)(x, y) > radius) continue;
      consider({x, y});
    }
  }
  return best;
}

}  // namespace hullinspect::planners
