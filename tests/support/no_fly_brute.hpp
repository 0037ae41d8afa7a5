#pragma once
// Brute-force recount of what no-fly zones leave unreachable (docs/model.md §8), independent of
// world::compute_reachability: for the mission tests to compare against.

#include <cstdint>
#include <utility>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::testing {

/// {hull cells unreachable at z = 1, at z = 2}: a hull cell is z-reachable when some position
/// within its footprint (side s1 or s2) is not no-fly and is connected to a start by a 4-path of
/// positions that are not no-fly.
std::pair<int, int> brute_unreachable(const world::HullMask& hull,
                                      const grid::Grid<std::uint8_t>& no_fly,
                                      const std::vector<grid::Cell>& starts, int s1, int s2);

}  // namespace hullinspect::testing
