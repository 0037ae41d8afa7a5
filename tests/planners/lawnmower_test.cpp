#include "hullinspect/planners/band_sweep.hpp"
#include "hullinspect/planners/lawnmower_planner.hpp"

#include <gtest/gtest.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/result_json.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/partition_cache.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"
#include "support/printers.hpp"
#include "support/truth_blindness.hpp"

namespace hullinspect::planners {
namespace {

struct Case {
  int n;
  int s2;
};

class LawnmowerMissions : public ::testing::TestWithParam<Case> {};

TEST_P(LawnmowerMissions, CompleteOnTheDefaultHullWithInvariants) {
  const auto [n, s2] = GetParam();
  PartitionCache partitions;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    MissionSpec spec;
    spec.params.uavs = n;
    spec.params.s2 = s2;
    spec.seed = seed;
    spec.corrosion = world::scenario("perfect").corrosion(230);
    testing::MissionChecker checker;
    MissionOptions options;
    options.observers = {&checker};
    options.partitions = &partitions;
    const auto r = run_mission(spec, world::default_hull(), options);
    ASSERT_TRUE(r.complete) << "n=" << n << " s2=" << s2 << " seed=" << seed;
    ASSERT_TRUE(checker.ok());
    ASSERT_TRUE(r.t_c && r.t_m);
    EXPECT_LE(*r.t_c, *r.t_m);
    // Descends once, at t = 0, and never changes plane again.
    const auto total = r.totals();
    EXPECT_EQ(total.plane_changes, n);
    for (const auto& u : r.uavs) EXPECT_EQ(u.steps_z2, 0);
  }
  EXPECT_EQ(partitions.computed(), 1);  // shared across the five instances
}

INSTANTIATE_TEST_SUITE_P(AllFleets, LawnmowerMissions, ::testing::ValuesIn([] {
                           std::vector<Case> cases;
                           for (int n = 1; n <= 8; ++n) {
                             for (int s2 : {7, 9, 11}) cases.push_back({n, s2});
                           }
                           return cases;
                         }()),
                         [](const auto& test) {
                           return "n" + std::to_string(test.param.n) + "_s2_" +
                                  std::to_string(test.param.s2);
                         });

TEST(Lawnmower, SweepVisitsStripsBottomToTopFromTheNearerEnd) {
  // Region: the whole 12 × 10 grid owned by UAV 0; s1 = 5 → strips [0, 5) and [5, 10).
  grid::Grid<std::int16_t> owner(12, 10, 0);
  owner(11, 9) = -1;
  const auto w = LawnmowerPlanner::sweep(owner, 0, 5, {10, 8});
  ASSERT_EQ(w.size(), 4u);
  EXPECT_EQ(w[0], (grid::Cell{11, 2}));  // right end is nearer to the start (10, 8)
  EXPECT_EQ(w[1], (grid::Cell{0, 2}));
  EXPECT_EQ(w[2], (grid::Cell{0, 7}));   // then the next strip from its nearer (left) end
  EXPECT_EQ(w[3], (grid::Cell{11, 7}));  // the extent of the top strip still reaches x = 11
}

TEST(Lawnmower, MissionTimeIsDescentPlusSweep) {
  // n = 1 on the default hull: the sweep is u_z + the waypoint path; T_m cannot exceed it.
  MissionSpec spec;
  spec.params.uavs = 1;
  spec.planner_options["partitioner"] = "stripes";
  const auto r = run_mission(spec, world::default_hull());
  partition::PartitionRequest request;
  request.hull = &world::default_hull();
  request.starts = world::start_cells(spec.params, world::default_hull());
  const auto p = partition::make_partitioner("stripes")->partition(request);
  const auto w = LawnmowerPlanner::sweep(p.owner, 0, 5, request.starts[0]);
  const int length = flight_length(request.starts[0], w);
  ASSERT_TRUE(r.t_m);
  EXPECT_LE(*r.t_m, 1 + length);
  EXPECT_GE(*r.t_m, 1 + length - 230);  // the last strip is flown almost to its end
}

TEST(Lawnmower, CannotReachTheGroundTruth) {
  world::MissionParams params;
  params.uavs = 4;
  testing::TruthBlindnessReport report;
  EXPECT_TRUE(testing::planner_is_truth_blind("lawnmower", {}, params, 3, &report));
  EXPECT_GE(report.first_differing_reading, 1);  // the two missions did diverge in what they saw
}

TEST(Determinism, SameInputsGiveIdenticalResultsAndTraces) {
  MissionSpec spec;
  spec.params.uavs = 3;
  spec.corrosion = world::scenario("imperfect").corrosion(230);
  spec.seed = 11;
  auto run_traced = [&] {
    const auto instance =
        world::generate_instance(world::default_hull(), spec.corrosion, spec.seed);
    auto planner = make_planner(spec.algorithm, spec.planner_options);
    io::TraceRecorder recorder(instance, io::spec_json(spec, "builtin:default"));
    MissionOptions options;
    options.observers = {&recorder};
    const auto r = run_mission(world::default_hull(), instance, spec.params, *planner, options);
    auto summary = io::result_json(spec, r);
    summary.erase("planner_seconds");
    return std::pair{summary, recorder.finish(r)};
  };
  const auto [a, trace_a] = run_traced();
  const auto [b, trace_b] = run_traced();
  EXPECT_EQ(a, b);
  EXPECT_EQ(trace_a, trace_b);
  EXPECT_EQ(trace_a["frames"].size(), static_cast<std::size_t>(a["steps"].get<int>() + 1));
}

TEST(Registry, UnknownNamesAndOptionsAreNamed) {
  try {
    make_planner("zigzag");
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.name(), "algorithm");
    EXPECT_NE(std::string(e.what()).find("unknown algorithm 'zigzag' (known: lawnmower"),
              std::string::npos);
  }
  try {
    make_planner("lawnmower", {{"alpha", "0.5"}});
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()),
              "lawnmower.alpha: unknown option (known: partitioner, partition-seed, "
              "partitioner.<key>, prior-weights, prior-statistics)");
  }
}

}  // namespace
}  // namespace hullinspect::planners
