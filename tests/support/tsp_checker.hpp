#pragma once
// Shared segment-TSP helpers for tests: an independent brute-force optimum, seeded random instances
// and a checker of solutions (valid order, reported length equal to the recomputed one).

#include <gtest/gtest.h>

#include <cstdint>

#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::testing {

/// Shortest path length over every order × every direction (g ≤ 8), computed without the
/// solvers' code.
long long brute_force_length(const tsp::SegmentTsp& problem);

/// Mission-like: g segments on strip centre rows of a width × height grid, 1–max_cells cells long,
/// UAV anywhere on the grid. Segments may overlap (the solvers must not care).
tsp::SegmentTsp random_strip_instance(int g, std::uint64_t seed, int width = 60, int height = 20,
                                      int max_cells = 20);
/// Ends anywhere on the grid (segments not horizontal), to test the general case.
tsp::SegmentTsp random_free_instance(int g, std::uint64_t seed, int width = 30, int height = 30);

/// Every segment exactly once and `solution.length` equal to tour_length().
::testing::AssertionResult valid_solution(const tsp::SegmentTsp& problem,
                                          const tsp::TspSolution& solution);

}  // namespace hullinspect::testing
