#include "hullinspect/planners/sweep_tail.hpp"

#include <algorithm>

namespace hullinspect::planners {

namespace {

/// walk[i]: the walk (Manhattan) from left.from through the waypoints to left.rest[i].
void walk_along(const SweepLeft& left, std::vector<int>& walk) {
  const auto rest = left.rest;
  walk.assign(rest.size(), grid::manhattan(left.from, rest[0]));
  for (std::size_t i = 1; i < rest.size(); ++i)
    walk[i] = walk[i - 1] + grid::manhattan(rest[i - 1], rest[i]);
}

}  // namespace

double sweep_left_end(const SweepLeft& left) {
  int walk = 0;
  grid::Cell at = left.from;
  for (const grid::Cell w : left.rest) {
    walk += grid::manhattan(at, w);
    at = w;
  }
  return left.back + kTailWalkCost * walk;
}

TailSplit split_sweep_tail(const SweepLeft& left, grid::Cell helper, grid::DistanceService& flights,
                           int min_saving, std::vector<int>& walk) {
  TailSplit split;
  const auto rest = left.rest;
  if (rest.empty()) return split;
  walk_along(left, walk);
  const int back = left.back;
  const double alone = back + kTailWalkCost * walk.back();
  // distance(a, b) searches from b: from the helper once for every candidate (flights are
  // symmetric).
  const int to_end = flights.distance(rest.back(), helper);
  const double total = walk.back();
  split.end = alone - min_saving;
  const auto consider = [&](std::size_t leg, grid::Cell at, double kept, bool skip_leg) {
    // The UAV flies to `at` (on leg `leg`, the leg into rest[leg]) and stops; the helper takes
    // the rest: from `at` (or, skipping a leg between bands, from rest[leg]) to the end.
    const grid::Cell first = skip_leg ? rest[leg] : at;
    const double taken = total - (skip_leg ? walk[leg] : kept);
    const int to_first = flights.distance(first, helper);
    if (to_first == grid::kUnreachable) return;
    const double keeps = back + kTailWalkCost * kept;
    const double takes = std::min(to_first, to_end) + kTailWalkCost * taken;
    const double end = std::max(keeps, takes);
    if (end >= split.end) return;
    split = {end, static_cast<int>(leg), at, skip_leg, to_end < to_first};
  };
  for (std::size_t leg = 0; leg < rest.size(); ++leg) {
    const grid::Cell a = leg == 0 ? left.from : rest[leg - 1];
    const grid::Cell b = rest[leg];
    const double before = leg == 0 ? 0.0 : walk[leg - 1];
    if (back + kTailWalkCost * before >= split.end) break;  // the UAV's share only grows
    const bool band_leg = left.axis == BandAxis::kRows ? a.y == b.y : a.x == b.x;
    if (!band_leg) {
      if (leg > 0) consider(leg, a, before, true);
      continue;
    }
    const int length = grid::manhattan(a, b);
    const grid::Cell dir{(b.x > a.x) - (b.x < a.x), (b.y > a.y) - (b.y < a.y)};
    for (int d = 1; d < length; ++d) {
      const grid::Cell at{a.x + d * dir.x, a.y + d * dir.y};
      if (flights.allowed(at)) consider(leg, at, before + d, false);
    }
  }
  return split;
}

}  // namespace hullinspect::planners
