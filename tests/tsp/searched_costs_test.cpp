// Segment TSPs whose costs are searched distances (long neighbour flights, as on an unrolled
// hull): the solvers' tours and lengths follow those distances, read from one table of end-to-end
// costs per solve, with no whole-grid field searched.

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"
#include "support/tsp_checker.hpp"

namespace hullinspect::tsp {
namespace {

using testing::random_strip_instance;
using testing::valid_solution;

// A 60 × 20 grid where about a third of the neighbour flights take 2 … 6 steps.
grid::DistanceService long_flights(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> percent(0, 99);
  grid::EdgeSteps steps{
      grid::Grid<std::uint8_t>(60, 20, 1), grid::Grid<std::uint8_t>(60, 20, 1), {}};
  for (int i = 0; i < steps.east.size(); ++i) {
    if (percent(rng) < 30) steps.east[i] = static_cast<std::uint8_t>(2 + percent(rng) % 5);
    if (percent(rng) < 30) steps.north[i] = static_cast<std::uint8_t>(2 + percent(rng) % 5);
  }
  return grid::DistanceService(grid::Grid<std::uint8_t>(60, 20, 1), steps);
}

TEST(SearchedCosts, SolversFollowTheServiceWithoutWholeGridSearches) {
  const auto reference = make_tsp_solver("dfj-iterative");
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    for (const int g : {1, 5, 12}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", g = " + std::to_string(g));
      SegmentTsp problem = random_strip_instance(g, seed);
      // The reference solver reads the service pair by pair (its own fields).
      grid::DistanceService reference_service = long_flights(seed);
      ASSERT_TRUE(reference_service.searched());
      problem.distances = &reference_service;
      const TspSolution optimum = reference->solve(problem);
      ASSERT_TRUE(optimum.optimal);
      for (const auto& [name, options] : {std::pair<std::string, OptionMap>{"exact", {}},
                                          {"exact", {{"dp-max-segments", "0"}}},
                                          {"heuristic", {}}}) {
        SCOPED_TRACE(name + (options.empty() ? "" : " (branch-and-cut)"));
        grid::DistanceService service = long_flights(seed);  // a fresh one: no field cached
        problem.distances = &service;
        const TspSolution s = make_tsp_solver(name, options)->solve(problem);
        EXPECT_EQ(service.searches(), 0) << "a whole-grid field was searched";
        ASSERT_TRUE(valid_solution(problem, s));  // the length is tour_length()'s
        if (name == "exact") {
          EXPECT_EQ(s.length, optimum.length);
        } else {
          EXPECT_GE(s.length, optimum.length);
        }
      }
    }
  }
}

}  // namespace
}  // namespace hullinspect::tsp
