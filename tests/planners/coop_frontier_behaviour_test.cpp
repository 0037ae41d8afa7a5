// Coop-Frontier on small hand-made worlds: the assignment spreads the fleet, a detection leads to
// close-up inspection and back, the end game, and how the planner reports itself.

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "coop_frontier_fixtures.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/coop_frontier_planner.hpp"
#include "hullinspect/sim/types.hpp"

namespace hullinspect::planners {
namespace {

using grid::Cell;
using Mode = CoopFrontierPlanner::Mode;
using sim::Action;
using testing::hand_instance;
using testing::LockStep;

world::MissionParams params_with(int s2, std::vector<Cell> starts) {
  world::MissionParams p;
  p.uavs = static_cast<int>(starts.size());
  p.s2 = s2;
  p.starts = std::move(starts);
  return p;
}

TEST(CoopFrontierBehaviour, AdjacentUavsAreSentToDifferentFrontiers) {
  // 60 × 7 all hull; UAVs at (24, 3) and (25, 3) see x = 21…28 and every row at t = 0. Prior
  // corrosion at (10, 3) and (50, 3) makes their neighbours frontiers with d_HP = 1, U = 0.5.
  // α = 0.5, β = 1: UAV 0 takes (11, 3) with 0.5 + 1/13; that reduces the frontiers around
  // (10, 3) to ≤ 0.5 · 2/14, so UAV 1 takes (49, 3) with 0.5 + 1/24 instead of (11, 3)'s
  // 0.5 + 1/14, which it would take without eq. 16.
  const auto hull = world::parse_text_mask(testing::full_mask(60, 7), "test");
  const auto instance = hand_instance(hull, {{10, 3}, {50, 3}}, {{10, 3}, {50, 3}});
  const auto params = params_with(7, {{24, 3}, {25, 3}});
  CoopFrontierPlanner planner({.alpha = 0.5, .beta = 1.0, .base_utility = 0.0});
  LockStep run(hull, instance, params, planner);
  const auto& actions = run.decide();
  ASSERT_TRUE(planner.target(0));
  ASSERT_TRUE(planner.target(1));
  EXPECT_EQ(*planner.target(0), (Cell{11, 3}));
  EXPECT_EQ(*planner.target(1), (Cell{49, 3}));
  EXPECT_EQ(actions[0], Action::kWest);
  EXPECT_EQ(actions[1], Action::kEast);
  EXPECT_EQ(planner.mode(0), Mode::kExplore);
  EXPECT_EQ(planner.stats().assignments, 2);

  // Both keep their targets (still frontiers) on the next step: no re-assignment.
  run.step();
  run.decide();
  EXPECT_EQ(*planner.target(0), (Cell{11, 3}));
  EXPECT_EQ(*planner.target(1), (Cell{49, 3}));
  EXPECT_EQ(planner.stats().assignments, 2);
}

TEST(CoopFrontierBehaviour, BaseUtilitySpreadsUavsWhenEquation13IsZero) {
  // No prior and nothing detected: U_f = 0 everywhere. Two UAVs share the start cell (24, 3) of a
  // 60 × 7 hull and see x = 21…27; the frontiers nearest to them are (20, 3) and (28, 3), both 4
  // away, and the tie goes to the lower x.
  const auto hull = world::parse_text_mask(testing::full_mask(60, 7), "test");
  const auto instance = hand_instance(hull, {}, {});
  const auto params = params_with(7, {{24, 3}, {24, 3}});
  // γ = 0 (the paper): the reduction multiplies zeros, so both take (20, 3).
  CoopFrontierPlanner plain({.alpha = 1.0, .beta = 8.0, .base_utility = 0.0});
  LockStep run(hull, instance, params, plain);
  run.decide();
  EXPECT_EQ(*plain.target(0), (Cell{20, 3}));
  EXPECT_EQ(*plain.target(1), (Cell{20, 3}));
  // γ = 0.5: UAV 0 takes (20, 3) with 0.5 + 8/4; then U(20, 3) = 0 and U(28, 3) = 0.5 · 8/14, so
  // UAV 1 scores 2.286 at (28, 3) against 2 at (20, 3).
  CoopFrontierPlanner spread({.alpha = 1.0, .beta = 8.0, .base_utility = 0.5});
  LockStep run2(hull, instance, params, spread);
  run2.decide();
  EXPECT_EQ(*spread.target(0), (Cell{20, 3}));
  EXPECT_EQ(*spread.target(1), (Cell{28, 3}));
}

TEST(CoopFrontierBehaviour, DetectionSwitchesToInspectAndBackToExplore) {
  // s2 = 9, s1 = 5, θ = 90°: Δζ = 2, u_z = 2, close-up radius 2·Δζ = 4. One UAV at (5, 5) on a
  // 30 × 11 all-hull grid sees x = 1…9 at t = 0 and detects the corroded (8, 5). The prior also
  // expects corrosion at (10, 5), out of sight at t = 0.
  const auto hull = world::parse_text_mask(testing::full_mask(30, 11), "test");
  const auto instance = hand_instance(hull, {{8, 5}, {10, 5}}, {{10, 5}});
  const auto params = params_with(9, {{5, 5}});

  CoopFrontierPlanner planner;
  EXPECT_EQ(planner.options().radius_factor, 2.0);
  LockStep run(hull, instance, params, planner);
  EXPECT_EQ(planner.close_up_radius(), 4);
  const auto& map = run.sim().map();

  // t = 0: detection → INSPECT, claim, descend (2 steps).
  EXPECT_EQ(run.decide()[0], Action::kChangePlane);
  EXPECT_EQ(planner.mode(0), Mode::kInspect);
  EXPECT_EQ(planner.claims().owner(map.index(8, 5)), 0);
  run.step();
  EXPECT_EQ(run.decide()[0], Action::kHover);  // in transit
  run.step();
  ASSERT_EQ(run.sim().uavs()[0].z, 1);
  // t = 2 at (5, 5), z = 1 (sees x = 3…7): the claimed (8, 5) is the nearest → east.
  EXPECT_EQ(run.decide()[0], Action::kEast);
  EXPECT_EQ(*planner.target(0), (Cell{8, 5}));
  run.step();
  // t = 3 at (6, 5): (8, 5) inspected. The claim is done, but (10, 5) (M = 2 from the prior) is 4
  // away, within the close-up radius: keep inspecting.
  EXPECT_EQ(map(8, 5), sim::kInspected);
  EXPECT_EQ(run.decide()[0], Action::kEast);
  EXPECT_EQ(planner.mode(0), Mode::kInspect);
  EXPECT_EQ(*planner.target(0), (Cell{10, 5}));
  run.step();
  EXPECT_EQ(run.decide()[0], Action::kEast);  // t = 4 at (7, 5)
  run.step();
  // t = 5 at (8, 5): (10, 5) inspected; nothing left → ascend, EXPLORE.
  EXPECT_EQ(map(10, 5), sim::kInspected);
  EXPECT_EQ(run.decide()[0], Action::kChangePlane);
  EXPECT_EQ(planner.mode(0), Mode::kExplore);
  EXPECT_FALSE(planner.target(0));
  run.step();
  run.decide();
  run.step();
  ASSERT_EQ(run.sim().uavs()[0].z, 2);
  // On arrival it needs a frontier.
  EXPECT_NE(run.decide()[0], Action::kChangePlane);
  EXPECT_EQ(planner.mode(0), Mode::kExplore);
  EXPECT_TRUE(planner.target(0));
  EXPECT_TRUE(planner.frontiers().contains(map.index(*planner.target(0))));

  // Same world with a zero close-up radius: after its claim the UAV ascends at once (t = 3).
  CoopFrontierPlanner narrow({.radius_factor = 0.0});
  LockStep run0(hull, instance, params, narrow);
  for (int t = 0; t < 3; ++t) {
    run0.decide();
    run0.step();
  }
  EXPECT_EQ(run0.sim().map()(8, 5), sim::kInspected);
  EXPECT_EQ(run0.decide()[0], Action::kChangePlane);
  EXPECT_EQ(narrow.mode(0), Mode::kExplore);
  EXPECT_EQ(run0.sim().map()(10, 5), sim::kCorrosionSeen);
}

// 40 × 3 all hull, corrosion (and its prior) on every cell with x ≥ 15; one UAV at (2, 1), s2 = 7.
// It explores x ≤ 14, which never brings x = 15 into its z = 2 footprint: F empties while the prior
// cells are still 2 → the end game.
struct EndGameWorld {
  world::HullMask hull = world::parse_text_mask(testing::full_mask(40, 3), "test");
  world::Instance instance;
  world::MissionParams params = params_with(7, {{2, 1}});
  EndGameWorld() {
    std::vector<Cell> corroded;
    for (int y = 0; y < 3; ++y) {
      for (int x = 15; x < 40; ++x) corroded.push_back({x, y});
    }
    instance = hand_instance(hull, corroded, corroded);
  }
};

TEST(CoopFrontierBehaviour, EndGameTakesTheNearestCorrosionCellAndDescends) {
  EndGameWorld w;
  CoopFrontierPlanner planner({.alpha = 0.5, .beta = 1.0, .base_utility = 0.0});
  LockStep run(w.hull, w.instance, w.params, planner);
  int t = 0;
  while (true) {
    const auto& actions = run.decide();
    if (planner.frontiers().empty()) {
      // The first decision without frontiers: claim the nearest 2 and descend.
      const Cell pos = run.sim().uavs()[0].pos;
      EXPECT_EQ(pos, (Cell{11, 1}));
      EXPECT_EQ(actions[0], Action::kChangePlane);
      EXPECT_EQ(planner.mode(0), Mode::kInspect);
      EXPECT_EQ(*planner.target(0), (Cell{15, 1}));
      EXPECT_EQ(planner.claims().owner(run.sim().map().index(15, 1)), 0);
      break;
    }
    EXPECT_EQ(planner.mode(0), Mode::kExplore) << "t = " << t;
    run.step();
    ASSERT_LT(++t, 100);
  }
}

TEST(CoopFrontierBehaviour, EndGameCompletesAndStayLowAvoidsPlaneChanges) {
  EndGameWorld w;
  CoopFrontierPlanner literal;
  const auto a = run_mission(w.hull, w.instance, w.params, literal);
  ASSERT_TRUE(a.complete);
  EXPECT_EQ(a.t_c, a.t_m);
  // Every ascent finds new detections at z = 2 and descends again.
  EXPECT_GT(a.totals().plane_changes, 2);

  CoopFrontierPlanner low({.endgame_stay_low = true});
  const auto b = run_mission(w.hull, w.instance, w.params, low);
  ASSERT_TRUE(b.complete);
  EXPECT_EQ(b.totals().plane_changes, 1);  // one descent, then z = 1 to the end
  EXPECT_LT(*b.t_m, *a.t_m);
}

class RecordingSink final : public AnnotationSink {
 public:
  void uav(int k, std::string_view mode, Cell target, std::span<const Cell> plan) override {
    modes.resize(std::max<std::size_t>(modes.size(), static_cast<std::size_t>(k) + 1));
    targets.resize(modes.size());
    modes[static_cast<std::size_t>(k)] = std::string(mode);
    targets[static_cast<std::size_t>(k)] = target;
    if (!plan.empty()) {
      EXPECT_EQ(plan.back(), target);
    }
  }
  void cells(std::string_view layer, std::span<const int> indices) override {
    layers[std::string(layer)] = std::set<int>(indices.begin(), indices.end());
  }
  std::vector<std::string> modes;
  std::vector<Cell> targets;
  std::map<std::string, std::set<int>> layers;
};

TEST(CoopFrontierBehaviour, AnnotatesModesTargetsAndFrontiers) {
  const auto hull = world::parse_text_mask(testing::full_mask(30, 11), "test");
  const auto instance = hand_instance(hull, {{8, 5}}, {});
  const auto params = params_with(9, {{5, 5}, {20, 5}});
  CoopFrontierPlanner planner;
  LockStep run(hull, instance, params, planner);
  run.decide();
  RecordingSink sink;
  planner.annotate(sink);
  ASSERT_EQ(sink.modes.size(), 2u);
  EXPECT_EQ(sink.modes[0], "transit");  // detected (8, 5): descending
  EXPECT_EQ(sink.modes[1], "explore");
  EXPECT_EQ(sink.targets[1], *planner.target(1));
  const std::set<int> frontiers(planner.frontiers().indices().begin(),
                                planner.frontiers().indices().end());
  EXPECT_EQ(sink.layers["frontiers"], frontiers);
  EXPECT_FALSE(frontiers.empty());
  run.step();
  run.decide();
  run.step();
  run.decide();  // UAV 0 at z = 1 now
  planner.annotate(sink);
  EXPECT_EQ(sink.modes[0], "inspect");
  EXPECT_EQ(sink.targets[0], (Cell{8, 5}));
}

TEST(CoopFrontierRegistry, BuildsFromOptionsAndRejectsBadOnes) {
  auto p = make_planner("coop-frontier", {{"alpha", "0.3"},
                                          {"beta", "2.5"},
                                          {"base-utility", "0.25"},
                                          {"radius-factor", "1"},
                                          {"endgame-stay-low", "true"}});
  const auto* cf = dynamic_cast<const CoopFrontierPlanner*>(p.get());
  ASSERT_NE(cf, nullptr);
  EXPECT_EQ(cf->options().alpha, 0.3);
  EXPECT_EQ(cf->options().beta, 2.5);
  EXPECT_EQ(cf->options().base_utility, 0.25);
  EXPECT_EQ(cf->options().radius_factor, 1.0);
  EXPECT_TRUE(cf->options().endgame_stay_low);

  try {
    make_planner("coop-frontier", {{"alpha", "1.5"}});
    FAIL() << "alpha = 1.5 accepted";
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(), "coop-frontier.alpha: must be a number in [0, 1] (got '1.5')");
  }
  try {
    make_planner("coop-frontier", {{"gamma", "1"}});
    FAIL() << "unknown option accepted";
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(),
                 "coop-frontier.gamma: unknown option (known: alpha, beta, base-utility, "
                 "radius-factor, endgame-stay-low)");
  }
  bool listed = false;
  for (const auto& info : planner_registry()) listed = listed || info.name == "coop-frontier";
  EXPECT_TRUE(listed);
}

}  // namespace
}  // namespace hullinspect::planners
