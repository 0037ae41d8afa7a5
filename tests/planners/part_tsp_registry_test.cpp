// part-tsp and part-tsp0 in the planner registry: declared options, parsing and exact errors.

#include <gtest/gtest.h>

#include <algorithm>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/planners/planner.hpp"

namespace hullinspect::planners {
namespace {

PlannerInfo info(std::string_view name) {
  const auto all = planner_registry();
  const auto it =
      std::find_if(all.begin(), all.end(), [&](const auto& i) { return i.name == name; });
  EXPECT_NE(it, all.end()) << name;
  return *it;
}

std::string error_of(std::string_view name, const OptionMap& options) {
  try {
    make_planner(name, options);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PartTspRegistry, BothPlannersDeclareTheirOptions) {
  for (const char* name : {"part-tsp", "part-tsp0"}) {
    std::vector<std::string> names;
    for (const auto& o : info(name).options) names.push_back(o.name);
    EXPECT_EQ(names, (std::vector<std::string>{"r1", "r2", "tsp-solver", "tsp-max-segments",
                                               "partitioner", "partition-seed", "skip-resolved",
                                               "trim-ends", "tsp.<key>", "partitioner.<key>",
                                               "prior-weights", "prior-statistics", "share-work"}))
        << name;
    EXPECT_EQ(info(name).options[0].default_value, "2");
    EXPECT_EQ(info(name).options[1].default_value, "0");
    EXPECT_EQ(info(name).options[2].default_value, "exact");
    EXPECT_EQ(info(name).options[3].default_value, "30");
  }
}

TEST(PartTspRegistry, ReadsTheOptions) {
  auto p = make_planner("part-tsp0", {{"r1", "3"},
                                      {"r2", "1"},
                                      {"tsp-solver", "exact"},
                                      {"partitioner", "stripes"},
                                      {"partition-seed", "7"},
                                      {"skip-resolved", "true"},
                                      {"trim-ends", "on"},
                                      {"tsp-max-segments", "40"}});
  const auto& o = dynamic_cast<const PartTspPlanner&>(*p).options();
  EXPECT_FALSE(o.use_prior);
  EXPECT_EQ(o.r1, 3);
  EXPECT_EQ(o.r2, 1);
  EXPECT_EQ(o.tsp_solver, "exact");
  EXPECT_EQ(o.partitioner, "stripes");
  EXPECT_EQ(o.partition_seed, 7u);
  EXPECT_TRUE(o.skip_resolved);
  EXPECT_TRUE(o.trim_ends);
  EXPECT_EQ(o.tsp_max_segments, 40);
  const auto default_planner = make_planner("part-tsp");
  const auto& d = dynamic_cast<const PartTspPlanner&>(*default_planner).options();
  EXPECT_TRUE(d.use_prior);
  EXPECT_EQ(d.r1, 2);
  EXPECT_EQ(d.r2, 0);
  EXPECT_EQ(d.tsp_solver, "exact");
  EXPECT_FALSE(d.skip_resolved);
  EXPECT_FALSE(d.trim_ends);
  EXPECT_EQ(d.tsp_max_segments, 30);
}

TEST(PartTspRegistry, RejectsBadOptionsWithExactMessages) {
  EXPECT_EQ(error_of("part-tsp", {{"r1", "-1"}}),
            "part-tsp.r1: must be an integer in [0, 1048576] (got '-1')");
  EXPECT_EQ(error_of("part-tsp0", {{"r2", "x"}}),
            "part-tsp0.r2: must be an integer in [0, 1048576] (got 'x')");
  EXPECT_EQ(error_of("part-tsp", {{"trim-ends", "maybe"}}),
            "part-tsp.trim-ends: must be true or false (got 'maybe')");
  EXPECT_EQ(error_of("part-tsp0", {{"alpha", "0.5"}}),
            "part-tsp0.alpha: unknown option (known: r1, r2, tsp-solver, tsp-max-segments, "
            "partitioner, partition-seed, skip-resolved, trim-ends, tsp.<key>, partitioner.<key>, "
            "prior-weights, prior-statistics, share-work)");
  EXPECT_EQ(error_of("part-tsp", {{"tsp-solver", "nope"}})
                .rfind("part-tsp.tsp-solver: unknown name 'nope'", 0),
            0u);
  EXPECT_EQ(
      error_of("part-tsp", {{"partitioner", "nope"}}).rfind("part-tsp.partitioner: unknown", 0),
      0u);
  EXPECT_EQ(error_of("part-tsp", {{"tsp.bogus", "1"}}).rfind("exact.bogus: ", 0), 0u)
      << error_of("part-tsp", {{"tsp.bogus", "1"}});
}

TEST(PartTspRegistry, ForwardsTspPrefixedOptionsToTheSolver) {
  const auto p = make_planner("part-tsp", {{"tsp.dp-max-segments", "12"}});
  const auto& o = dynamic_cast<const PartTspPlanner&>(*p).options();
  // The solver's effective options: the one given plus its defaults.
  EXPECT_EQ(o.tsp_solver_options, (OptionMap{{"dp-max-segments", "12"},
                                             {"kicks", "10"},
                                             {"max-segments", "120"},
                                             {"time-limit", "0"},
                                             {"work-budget", "50"}}));
}

}  // namespace
}  // namespace hullinspect::planners
