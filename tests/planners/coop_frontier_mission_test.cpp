// Whole Coop-Frontier missions: completion under the shared invariant checker for every scenario,
// s2 and fleet size; robustness to UAV failures; independence from unseen truth; determinism; and
// the planner's frontier set and targets checked against their definitions at every decision.

#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "coop_frontier_fixtures.hpp"
#include "hullinspect/planners/coop_frontier_planner.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::planners {
namespace {

using Mode = CoopFrontierPlanner::Mode;

#if defined(__SANITIZE_ADDRESS__) || defined(HULLINSPECT_SANITIZED)
constexpr int kSeedsPerCell = 3;  // sanitizer builds run ~10× slower: fewer seeds, same coverage
#else
constexpr int kSeedsPerCell = 20;
#endif

struct MatrixCell {
  std::string scenario;
  int s2;
};

class CoopFrontierMatrix : public ::testing::TestWithParam<MatrixCell> {};

TEST_P(CoopFrontierMatrix, EveryMissionCompletesUnderTheChecker) {
  const auto& hull = world::default_hull();
  const auto corrosion = world::scenario(GetParam().scenario).corrosion(hull.width());
  for (int n = 1; n <= 8; ++n) {
    for (int seed = 1; seed <= kSeedsPerCell; ++seed) {
      const auto instance =
          world::generate_instance(hull, corrosion, static_cast<std::uint64_t>(seed));
      world::MissionParams params;
      params.uavs = n;
      params.s2 = GetParam().s2;
      CoopFrontierPlanner planner;
      testing::MissionChecker checker;
      MissionOptions options;
      options.observers.push_back(&checker);
      const auto r = run_mission(hull, instance, params, planner, options);
      SCOPED_TRACE(::testing::Message()
                   << GetParam().scenario << " s2=" << params.s2 << " n=" << n << " seed=" << seed);
      ASSERT_TRUE(r.complete);
      ASSERT_TRUE(checker.ok());
      ASSERT_TRUE(r.t_c.has_value());
      EXPECT_LE(*r.t_c, *r.t_m);
      EXPECT_EQ(r.steps, *r.t_m);
      EXPECT_GT(r.planner.assignments, 0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllScenarios, CoopFrontierMatrix,
    ::testing::Values(MatrixCell{"perfect", 7}, MatrixCell{"perfect", 9}, MatrixCell{"perfect", 11},
                      MatrixCell{"imperfect", 7}, MatrixCell{"imperfect", 9},
                      MatrixCell{"imperfect", 11}, MatrixCell{"inhomogeneous", 7},
                      MatrixCell{"inhomogeneous", 9}, MatrixCell{"inhomogeneous", 11},
                      MatrixCell{"combined", 7}, MatrixCell{"combined", 9},
                      MatrixCell{"combined", 11}),
    [](const auto& test) { return test.param.scenario + "_s2_" + std::to_string(test.param.s2); });

/// Checks after every step that a failed UAV holds no claims and has no target.
class FailureWatcher final : public MissionObserver {
 public:
  explicit FailureWatcher(std::vector<int> failed) : failed_(std::move(failed)) {}
  void on_start(const sim::Simulator&, const Planner&) override {}
  void on_step(const sim::Simulator& sim, const Planner& planner) override {
    const auto& cf = dynamic_cast<const CoopFrontierPlanner&>(planner);
    for (int k : failed_) {
      if (!sim.uavs()[static_cast<std::size_t>(k)].failed) continue;
      // The planner learns of the failure at its next decision, i.e. one step later.
      if (seen_inactive_.count(k) && cf.mode(k) != Mode::kFailed) bad_ = true;
      if (seen_inactive_.count(k) && (!cf.claims().claims(k).empty() || cf.target(k))) bad_ = true;
      seen_inactive_.insert(k);
    }
  }
  bool ok() const { return !bad_ && seen_inactive_.size() == failed_.size(); }

 private:
  std::vector<int> failed_;
  std::set<int> seen_inactive_;
  bool bad_ = false;
};

TEST(CoopFrontierMission, OthersCompleteWhenUavsFailMidMission) {
  const auto& hull = world::default_hull();
  for (const char* name : {"perfect", "combined"}) {
    const auto corrosion = world::scenario(name).corrosion(hull.width());
    for (int seed = 1; seed <= 5; ++seed) {
      for (const auto& failures : std::vector<std::vector<UavFailure>>{
               {{1, 40}}, {{0, 1}}, {{3, 120}}, {{0, 30}, {2, 60}}}) {
        const auto instance =
            world::generate_instance(hull, corrosion, static_cast<std::uint64_t>(seed));
        world::MissionParams params;
        params.uavs = 4;
        CoopFrontierPlanner planner;
        testing::MissionChecker checker;
        std::vector<int> failed;
        for (const auto& f : failures) failed.push_back(f.uav);
        FailureWatcher watcher(failed);
        MissionOptions options;
        options.observers = {&checker, &watcher};
        options.failures.at = failures;
        const auto r = run_mission(hull, instance, params, planner, options);
        SCOPED_TRACE(::testing::Message() << name << " seed " << seed << " first failure UAV "
                                          << failures[0].uav << " at " << failures[0].time);
        ASSERT_TRUE(r.complete);
        EXPECT_TRUE(checker.ok());
        EXPECT_TRUE(watcher.ok());
        for (const auto& f : failures) {
          EXPECT_EQ(planner.mode(f.uav), Mode::kFailed);
          // A failed UAV stops counting steps on a plane once frozen.
          const auto& c = r.uavs[static_cast<std::size_t>(f.uav)];
          EXPECT_LE(c.moves + c.hovers + c.steps_transit, f.time);
        }
      }
    }
  }
}

TEST(CoopFrontierMission, FailureWhileInspectingReleasesTheClaims) {
  // One UAV at (5, 5) of a 30 × 11 hull detects (8, 5) at t = 0 and claims it; it fails at t = 1,
  // in the middle of its descent. The other UAV must inspect (8, 5) for the mission to complete.
  const auto hull = world::parse_text_mask(testing::full_mask(30, 11), "test");
  const auto instance = testing::hand_instance(hull, {{8, 5}}, {});
  world::MissionParams params;
  params.uavs = 2;
  params.s2 = 9;
  params.starts = {{5, 5}, {25, 5}};
  CoopFrontierPlanner planner;
  testing::MissionChecker checker;
  MissionOptions options;
  options.observers = {&checker};
  options.failures.at = {{0, 1}};
  const auto r = run_mission(hull, instance, params, planner, options);
  ASSERT_TRUE(r.complete);
  EXPECT_TRUE(checker.ok());
  EXPECT_EQ(planner.mode(0), Mode::kFailed);
  EXPECT_TRUE(planner.claims().claims(0).empty());
  EXPECT_EQ(r.uavs[0].moves, 0);
  EXPECT_GE(r.uavs[1].plane_changes, 1);  // UAV 1 went down to inspect (8, 5)
}

TEST(CoopFrontierMission, ActionsDoNotDependOnUnseenTruth) {
  // Same prior, different truth: B has extra corrosion far from the start cells. The two missions
  // must decide identically until some UAV's readings differ.
  const auto& hull = world::default_hull();
  const auto corrosion = world::scenario("imperfect").corrosion(hull.width());
  for (int seed = 1; seed <= 3; ++seed) {
    const auto a = world::generate_instance(hull, corrosion, static_cast<std::uint64_t>(seed));
    auto b = a;
    for (int y = 20; y < 25; ++y) {
      for (int x = 110; x < 118; ++x) {
        if (hull.is_hull(x, y) && b.prior(x, y) == 0) b.truth(x, y) = 1;
      }
    }
    ASSERT_NE(a.truth, b.truth);
    world::MissionParams params;
    params.uavs = 4;
    CoopFrontierPlanner pa;
    CoopFrontierPlanner pb;
    testing::LockStep ra(hull, a, params, pa);
    testing::LockStep rb(hull, b, params, pb);
    int same_steps = 0;
    bool diverged = false;
    while (!ra.sim().finished() && !rb.sim().finished()) {
      const auto& view_a = ra.sim().view();
      const auto& view_b = rb.sim().view();
      for (int k = 0; k < params.uavs && !diverged; ++k) {
        const auto la = view_a.sensed.readings(k);
        const auto lb = view_b.sensed.readings(k);
        if (la.size() != lb.size()) diverged = true;
        for (std::size_t i = 0; i < la.size() && !diverged; ++i) {
          diverged = la[i].index != lb[i].index || la[i].value != lb[i].value;
        }
      }
      if (diverged) break;
      ASSERT_EQ(ra.decide(), rb.decide()) << "seed " << seed << " t = " << ra.sim().time();
      ra.step();
      rb.step();
      ++same_steps;
    }
    EXPECT_TRUE(diverged) << "the extra corrosion was never seen";
    EXPECT_GT(same_steps, 10);
  }
}

TEST(CoopFrontierMission, IdenticalRunsGiveIdenticalResults) {
  const auto& hull = world::default_hull();
  const auto corrosion = world::scenario("combined").corrosion(hull.width());
  const auto instance = world::generate_instance(hull, corrosion, 11);
  world::MissionParams params;
  params.uavs = 6;
  params.s2 = 9;
  CoopFrontierPlanner p1;
  CoopFrontierPlanner p2;
  const auto r1 = run_mission(hull, instance, params, p1);
  const auto r2 = run_mission(hull, instance, params, p2);
  EXPECT_EQ(r1.t_c, r2.t_c);
  EXPECT_EQ(r1.t_m, r2.t_m);
  EXPECT_EQ(r1.inspected_series, r2.inspected_series);
  EXPECT_EQ(r1.known_series, r2.known_series);
  EXPECT_EQ(r1.planner.assignments, r2.planner.assignments);
  for (std::size_t k = 0; k < r1.uavs.size(); ++k) {
    EXPECT_EQ(r1.uavs[k].moves, r2.uavs[k].moves);
    EXPECT_EQ(r1.uavs[k].plane_changes, r2.uavs[k].plane_changes);
  }
}

TEST(CoopFrontierMission, StateMatchesItsDefinitionsAtEveryDecision) {
  // The incrementally kept frontier set equals the definition applied to M; every EXPLORE target is
  // in F; every INSPECT target is an M = 2 cell within reach of the rule; claims belong to one UAV.
  const auto& hull = world::default_hull();
  for (const char* name : {"imperfect", "combined"}) {
    const auto instance =
        world::generate_instance(hull, world::scenario(name).corrosion(hull.width()), 21);
    world::MissionParams params;
    params.uavs = 5;
    params.s2 = 11;
    CoopFrontierPlanner planner;
    testing::LockStep run(hull, instance, params, planner);
    while (!run.sim().finished()) {
      run.decide();
      const auto& map = run.sim().map();
      std::set<int> expected;
      for (int i = 0; i < map.size(); ++i) {
        if (FrontierSet::is_frontier(map, i)) expected.insert(i);
      }
      const std::set<int> got(planner.frontiers().indices().begin(),
                              planner.frontiers().indices().end());
      ASSERT_EQ(got, expected) << name << " t = " << run.sim().time();
      for (int k = 0; k < params.uavs; ++k) {
        const auto& u = run.sim().uavs()[static_cast<std::size_t>(k)];
        const auto target = planner.target(k);
        if (planner.mode(k) == Mode::kExplore && target && !u.in_transit() && u.z == 2) {
          ASSERT_TRUE(planner.frontiers().contains(map.index(*target)))
              << "t = " << run.sim().time();
        }
        if (planner.mode(k) == Mode::kInspect && target && u.z == 1 && !u.in_transit()) {
          ASSERT_EQ(map[*target], sim::kCorrosionSeen) << "t = " << run.sim().time();
          const bool claimed = planner.claims().owner(map.index(*target)) == k;
          ASSERT_TRUE(claimed || grid::manhattan(u.pos, *target) <= planner.close_up_radius());
        }
        for (int i : planner.claims().claims(k)) ASSERT_EQ(planner.claims().owner(i), k);
      }
      run.step();
    }
    EXPECT_TRUE(run.sim().complete());
  }
}

}  // namespace
}  // namespace hullinspect::planners
