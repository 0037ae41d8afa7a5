#include "support/tsp_checker.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <vector>

#include "hullinspect/world/random.hpp"

namespace hullinspect::testing {

namespace {
long long distance(grid::Cell a, grid::Cell b) {
  return std::llabs(static_cast<long long>(a.x) - b.x) +
         std::llabs(static_cast<long long>(a.y) - b.y);
}
int below(world::RandomStream& random, int n) {
  return static_cast<int>(random.below(static_cast<std::uint64_t>(n)));
}
}  // namespace

long long brute_force_length(const tsp::SegmentTsp& problem) {
  const int g = static_cast<int>(problem.segments.size());
  std::vector<int> order(static_cast<std::size_t>(g));
  std::iota(order.begin(), order.end(), 0);
  long long best = std::numeric_limits<long long>::max();
  do {
    for (unsigned directions = 0; directions < (1u << g); ++directions) {
      long long length = 0;
      grid::Cell at = problem.start;
      for (int k = 0; k < g; ++k) {
        const auto& s =
            problem.segments[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])];
        const bool reversed = ((directions >> k) & 1u) != 0;
        const grid::Cell in = reversed ? s.second : s.first;
        const grid::Cell out = reversed ? s.first : s.second;
        length += distance(at, in) + distance(in, out);
        at = out;
      }
      best = std::min(best, length);
    }
  } while (std::next_permutation(order.begin(), order.end()));
  return g == 0 ? 0 : best;
}

tsp::SegmentTsp random_strip_instance(int g, std::uint64_t seed, int width, int height,
                                      int max_cells) {
  world::RandomStream random(seed, 77);
  const int strip = 3 + 2 * below(random, 3);  // 3, 5 or 7 rows
  tsp::SegmentTsp p;
  p.start = {below(random, width), below(random, height)};
  for (int l = 0; l < g; ++l) {
    const int rows = (height + strip - 1) / strip;
    const int y = std::min(below(random, rows) * strip + (strip - 1) / 2, height - 1);
    const int cells = 1 + below(random, max_cells);
    const int x = below(random, width - cells + 1);
    p.segments.push_back({{x, y}, {x + cells - 1, y}});
  }
  return p;
}

tsp::SegmentTsp random_free_instance(int g, std::uint64_t seed, int width, int height) {
  world::RandomStream random(seed, 78);
  tsp::SegmentTsp p;
  p.start = {below(random, width), below(random, height)};
  for (int l = 0; l < g; ++l) {
    p.segments.push_back({{below(random, width), below(random, height)},
                          {below(random, width), below(random, height)}});
  }
  return p;
}

::testing::AssertionResult valid_solution(const tsp::SegmentTsp& problem,
                                          const tsp::TspSolution& solution) {
  const std::string problem_text = tsp::order_problem(problem, solution.order);
  if (!problem_text.empty()) return ::testing::AssertionFailure() << problem_text;
  const long long length = tsp::tour_length(problem, solution.order);
  if (length != solution.length) {
    return ::testing::AssertionFailure()
           << "reported length " << solution.length << " but the order is " << length << " long";
  }
  return ::testing::AssertionSuccess();
}

}  // namespace hullinspect::testing
