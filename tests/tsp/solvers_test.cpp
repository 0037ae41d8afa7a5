// Every TSP solver against brute force, against each other and on degenerate instances.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"
#include "support/tsp_checker.hpp"

namespace hullinspect::tsp {
namespace {

using testing::brute_force_length;
using testing::random_free_instance;
using testing::random_strip_instance;
using testing::valid_solution;

struct Config {
  std::string name;
  OptionMap options;
  std::string label;
};

/// Every solver configuration that claims optimality, including each internal method of "exact".
std::vector<Config> exact_configs() {
  return {{"exact", {}, "exact"},
          {"exact", {{"dp-max-segments", "0"}}, "exact (branch-and-cut only)"},
          {"exact", {{"dp-max-segments", "16"}}, "exact (dynamic program only)"},
          {"dfj-iterative", {}, "dfj-iterative"},
          {"cbc-cut", {}, "cbc-cut"}};
}

TEST(TspSolvers, RegistryListsTheFourSolvers) {
  std::vector<std::string> names;
  for (const auto& info : tsp_solver_registry()) names.push_back(info.name);
  EXPECT_EQ(names, (std::vector<std::string>{"exact", "dfj-iterative", "cbc-cut", "heuristic"}));
  EXPECT_EQ(std::string(kDefaultTspSolver), "exact");
}

TEST(TspSolvers, UnknownSolverOrOptionIsAParameterError) {
  try {
    make_tsp_solver("lkh");
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_STREQ(
        e.what(),
        "tsp-solver: unknown TSP solver 'lkh' (known: exact, dfj-iterative, cbc-cut, heuristic)");
  }
  try {
    make_tsp_solver("exact", {{"timelimit", "3"}});
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(),
                 "exact.timelimit: unknown option (did you mean time-limit?) (known: time-limit, "
                 "dp-max-segments, kicks, max-segments, work-budget)");
  }
  try {
    make_tsp_solver("exact", {{"dp-max-segments", "17"}});
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(), "exact.dp-max-segments: must be an integer in [0, 16] (got '17')");
  }
  EXPECT_THROW(make_tsp_solver("heuristic", {{"kicks", "-1"}}), ParameterError);
  EXPECT_THROW(make_tsp_solver("dfj-iterative", {{"time-limit", "soon"}}), ParameterError);
}

TEST(TspSolvers, ExactSolversMatchBruteForce) {
  for (const auto& config : exact_configs()) {
    auto solver = make_tsp_solver(config.name, config.options);
    for (int g = 0; g <= 7; ++g) {
      for (std::uint64_t seed = 0; seed < 12; ++seed) {
        for (bool strips : {true, false}) {
          const SegmentTsp p =
              strips ? random_strip_instance(g, seed) : random_free_instance(g, seed);
          SCOPED_TRACE(config.label + ", g = " + std::to_string(g) + ", seed " +
                       std::to_string(seed) + (strips ? ", strips" : ", free"));
          const TspSolution s = solver->solve(p);
          ASSERT_TRUE(valid_solution(p, s));
          EXPECT_TRUE(s.optimal);
          EXPECT_EQ(s.length, brute_force_length(p));
        }
      }
    }
  }
}

TEST(TspSolvers, HeuristicIsValidAndNeverBelowTheOptimum) {
  auto heuristic = make_tsp_solver("heuristic");
  auto exact = make_tsp_solver("exact");
  int optimal_found = 0;
  int instances = 0;
  for (int g = 0; g <= 30; ++g) {
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
      const SegmentTsp p = random_strip_instance(g, seed, 120, 30, 30);
      SCOPED_TRACE("g = " + std::to_string(g) + ", seed " + std::to_string(seed));
      const TspSolution h = heuristic->solve(p);
      ASSERT_TRUE(valid_solution(p, h));
      EXPECT_EQ(h.optimal, g <= 1);
      const TspSolution e = exact->solve(p);
      ASSERT_TRUE(valid_solution(p, e));
      ASSERT_TRUE(e.optimal);
      EXPECT_GE(h.length, e.length);
      if (g <= 7) {
        EXPECT_EQ(e.length, brute_force_length(p));
      }
      optimal_found += h.length == e.length ? 1 : 0;
      ++instances;
    }
  }
  // The local search is good, not perfect: it must find most optima on these small instances.
  EXPECT_GE(optimal_found, instances * 8 / 10);
}

TEST(TspSolvers, AllOptimalSolversAgreeOnLargerInstances) {
  auto dp = make_tsp_solver("exact", {{"dp-max-segments", "12"}});
  auto cut = make_tsp_solver("exact", {{"dp-max-segments", "0"}});
  auto dfj = make_tsp_solver("dfj-iterative");
  auto cbc = make_tsp_solver("cbc-cut");
  for (int g : {8, 10, 12}) {
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
      const SegmentTsp p = random_strip_instance(g, 100 + seed, 120, 30, 30);
      SCOPED_TRACE("g = " + std::to_string(g) + ", seed " + std::to_string(seed));
      const TspSolution a = dp->solve(p);
      const TspSolution b = cut->solve(p);
      const TspSolution c = dfj->solve(p);
      const TspSolution d = cbc->solve(p);
      for (const auto* s : {&a, &b, &c, &d}) {
        ASSERT_TRUE(valid_solution(p, *s));
        EXPECT_TRUE(s->optimal);
      }
      EXPECT_EQ(a.length, b.length);
      EXPECT_EQ(a.length, c.length);
      EXPECT_EQ(a.length, d.length);
    }
  }
}

SegmentTsp make(grid::Cell start, std::vector<Segment> segments) {
  return {start, std::move(segments)};
}

TEST(TspSolvers, DegenerateInstances) {
  const std::vector<std::pair<std::string, SegmentTsp>> cases = {
      {"no segment", make({4, 4}, {})},
      {"one segment", make({0, 0}, {{{5, 2}, {9, 2}}})},
      {"one segment, UAV nearer its right end", make({12, 2}, {{{5, 2}, {9, 2}}})},
      {"zero-length segments",
       make({0, 0}, {{{3, 3}, {3, 3}}, {{7, 1}, {7, 1}}, {{1, 8}, {1, 8}}})},
      {"UAV on a segment end",
       make({9, 2}, {{{5, 2}, {9, 2}}, {{0, 7}, {4, 7}}, {{10, 7}, {14, 7}}})},
      {"duplicate segments",
       make({0, 0}, {{{2, 2}, {8, 2}}, {{2, 2}, {8, 2}}, {{2, 2}, {8, 2}}, {{2, 7}, {8, 7}}})},
      {"everything at one cell",
       make({5, 5}, {{{5, 5}, {5, 5}}, {{5, 5}, {5, 5}}, {{5, 5}, {5, 5}}})},
      {"right end left of left end", make({0, 0}, {{{9, 2}, {5, 2}}, {{20, 2}, {15, 2}}})},
  };
  std::vector<Config> configs = exact_configs();
  configs.push_back({"heuristic", {}, "heuristic"});
  for (const auto& config : configs) {
    auto solver = make_tsp_solver(config.name, config.options);
    for (const auto& [label, p] : cases) {
      SCOPED_TRACE(config.label + ": " + label);
      const TspSolution s = solver->solve(p);
      ASSERT_TRUE(valid_solution(p, s));
      EXPECT_EQ(s.length, brute_force_length(p));
      if (config.name != "heuristic" || p.segments.size() <= 1) {
        EXPECT_TRUE(s.optimal);
      }
    }
  }
}

TEST(TspSolvers, KnownAnswers) {
  // UAV left of two segments on one row: fly both left to right, length 10 + 4 + 2 + 4 = 20 ... the
  // gap between them (x 5 → 7) is 2, the approach (0 → 1) is 1: 1 + 4 + 2 + 4 = 11.
  const SegmentTsp row = make({0, 0}, {{{7, 0}, {11, 0}}, {{1, 0}, {5, 0}}});
  // Empty problem.
  const SegmentTsp empty = make({3, 3}, {});
  for (const auto& config : exact_configs()) {
    auto solver = make_tsp_solver(config.name, config.options);
    SCOPED_TRACE(config.label);
    const TspSolution s = solver->solve(row);
    EXPECT_EQ(s.length, 11);
    EXPECT_EQ(s.order, (std::vector<Visit>{{1, false}, {0, false}}));
    const TspSolution e = solver->solve(empty);
    EXPECT_TRUE(e.order.empty());
    EXPECT_EQ(e.length, 0);
    EXPECT_TRUE(e.optimal);
  }
}

TEST(TspSolvers, TimeLimitReturnsAValidUnprovenTour) {
  // A 1 µs limit expires before the branch-and-cut's first node: the local search's tour comes
  // back.
  const SegmentTsp p = random_strip_instance(40, 5, 230, 30, 60);
  for (const std::string name : {"exact", "dfj-iterative", "cbc-cut"}) {
    SCOPED_TRACE(name);
    auto solver = make_tsp_solver(name, {{"time-limit", "0.000001"}});
    const TspSolution s = solver->solve(p);
    ASSERT_TRUE(valid_solution(p, s));
    EXPECT_FALSE(s.optimal);
    EXPECT_GE(s.length, make_tsp_solver("exact")->solve(p).length);
  }
}

TEST(TspSolvers, SolversAreDeterministicAndReusable) {
  for (const std::string name : {"exact", "heuristic"}) {
    auto solver = make_tsp_solver(name);
    auto other = make_tsp_solver(name);
    for (int g : {3, 15, 25}) {
      const SegmentTsp p = random_strip_instance(g, 9, 120, 30, 30);
      const TspSolution a = solver->solve(p);
      const TspSolution b = other->solve(p);
      EXPECT_EQ(a.order, b.order) << name << ", g = " << g;
      EXPECT_EQ(a.length, b.length);
    }
  }
}

}  // namespace
}  // namespace hullinspect::tsp
