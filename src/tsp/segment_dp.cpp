#include "segment_dp.hpp"

#include <algorithm>
#include <limits>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::tsp::detail {

namespace {
constexpr std::int32_t kUnreached = std::numeric_limits<std::int32_t>::max() / 2;
}

void SegmentDp::solve(const EndCosts& costs, std::vector<int>& entries) {
  const int g = costs.segments();
  if (g < 1 || g > kMaxSegments) throw LogicError("segment DP called with g outside [1, 16]");
  const int n = 2 * g;
  const std::uint32_t full = (1u << g) - 1;
  const std::size_t width = static_cast<std::size_t>(n);
  table_.assign((static_cast<std::size_t>(full) + 1) * width, kUnreached);
  auto row = [&](std::uint32_t mask) { return table_.data() + mask * width; };

  for (int entry = 0; entry < n; ++entry) {
    row(1u << (entry >> 1))[entry ^ 1] = costs(costs.start(), entry);
  }
  // Push each reached state to every unvisited segment, in both directions.
  for (std::uint32_t mask = 1; mask < full; ++mask) {
    const std::int32_t* from = row(mask);
    for (std::uint32_t left = mask; left != 0; left &= left - 1) {
      const int l = __builtin_ctz(left);
      for (int exit = 2 * l; exit < 2 * l + 2; ++exit) {
        const std::int32_t base = from[exit];
        if (base >= kUnreached) continue;
        for (std::uint32_t open = full & ~mask; open != 0; open &= open - 1) {
          const int j = __builtin_ctz(open);
          std::int32_t* to = row(mask | (1u << j));
          const std::int32_t forward = base + costs(exit, 2 * j);       // enter first, exit second
          const std::int32_t backward = base + costs(exit, 2 * j + 1);  // enter second, exit first
          if (forward < to[2 * j + 1]) to[2 * j + 1] = forward;
          if (backward < to[2 * j]) to[2 * j] = backward;
        }
      }
    }
  }

  // Walk back from the cheapest final exit, recomputing each predecessor.
  entries.clear();
  const std::int32_t* last = row(full);
  int exit = static_cast<int>(std::min_element(last, last + n) - last);
  std::uint32_t mask = full;
  while (true) {
    const int entry = exit ^ 1;
    entries.push_back(entry);
    const std::int32_t value = row(mask)[exit];
    mask &= ~(1u << (exit >> 1));
    if (mask == 0) break;
    const std::int32_t* prev = row(mask);
    int found = -1;
    for (int e = 0; e < n && found < 0; ++e) {
      if ((mask >> (e >> 1) & 1u) != 0 && prev[e] < kUnreached &&
          prev[e] + costs(e, entry) == value) {
        found = e;
      }
    }
    if (found < 0) throw LogicError("segment DP: no predecessor while reconstructing the tour");
    exit = found;
  }
  std::reverse(entries.begin(), entries.end());
}

}  // namespace hullinspect::tsp::detail
