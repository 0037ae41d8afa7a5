// Every registered planner, whatever it is, cannot reach the ground truth C.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/truth_blindness.hpp"

namespace hullinspect::planners {
namespace {

TEST(TruthBlindness, EveryRegisteredPlannerDecidesOnlyFromWhatWasSensed) {
  world::MissionParams params;
  params.uavs = 4;
  for (const auto& info : planner_registry()) {
    if (info.sees_truth) continue;  // an oracle (a bound): the next test
    testing::TruthBlindnessReport report;
    EXPECT_TRUE(testing::planner_is_truth_blind(info.name, {}, params, 5, &report)) << info.name;
    EXPECT_GE(report.first_differing_reading, 1) << info.name;  // the two missions did diverge
  }
}

// The same check with the difference where each planner looks last (cells first sensed in the
// last 10 % of the time it took to sense everything): the decisions of most of the mission —
// help, hand-overs, take-overs of a failed UAV's work, the end game — are compared, not only the
// first ~20 steps before the default change (the top rows) comes into view.
TEST(TruthBlindness, LateDecisionsDependOnlyOnWhatWasSensed) {
  world::MissionParams params;
  params.uavs = 4;
  struct Case {
    std::string algorithm;
    OptionMap options;
    world::FailurePlan failures;
  };
  std::vector<Case> cases;
  for (const auto& info : planner_registry()) {
    if (!info.sees_truth) cases.push_back({info.name, {}, {}});
  }
  world::FailurePlan one_fails;
  one_fails.at = {{1, 40}};
  cases.push_back({"part-tsp", {{"share-work", "true"}}, {}});
  cases.push_back({"part-tsp", {{"share-work", "true"}}, one_fails});
  cases.push_back({"sweep-inspect", {}, one_fails});
  cases.push_back({"coop-frontier", {}, one_fails});
  for (const auto& c : cases) {
    int last = 0;
    int altered = 0;
    const auto alter = testing::corrosion_where_sensed_last(c.algorithm, c.options, params, 7,
                                                            c.failures, &last, &altered);
    testing::TruthBlindnessReport report;
    EXPECT_TRUE(testing::planner_is_truth_blind(c.algorithm, c.options, params, 7, &report,
                                                c.failures, alter))
        << c.algorithm;
    EXPECT_GT(altered, 0) << c.algorithm;
    // The missions saw the same until late: most of the mission's decisions were compared.
    EXPECT_GE(10 * report.first_differing_reading, 9 * last) << c.algorithm;
    EXPECT_GE(last, 100) << c.algorithm;
  }
  // And it can tell: an oracle, whose decisions read C, is caught with this change too.
  for (const auto& info : planner_registry()) {
    if (!info.sees_truth) continue;
    const auto alter = testing::corrosion_where_sensed_last(info.name, {}, params, 7);
    EXPECT_FALSE(testing::planner_is_truth_blind(info.name, {}, params, 7, nullptr, {}, alter))
        << info.name;
  }
}

// The prior-aware partition (with and without the scenario's statistics) on every partitioned
// planner: weights come from the prior and the statistics, never from C.
TEST(TruthBlindness, PriorWeightedPartitionsAreTruthBlind) {
  world::MissionParams params;
  params.uavs = 4;
  for (const char* algorithm : {"lawnmower", "part-tsp", "part-tsp0", "sweep-inspect"}) {
    for (const auto& options :
         {OptionMap{{"prior-weights", "true"}},
          OptionMap{{"prior-weights", "true"}, {"prior-statistics", "false"}}}) {
      testing::TruthBlindnessReport report;
      EXPECT_TRUE(testing::planner_is_truth_blind(algorithm, options, params, 6, &report))
          << algorithm;
      EXPECT_GE(report.first_differing_reading, 1) << algorithm;
    }
  }
}

// Part-TSP's work sharing (share-work): hand-overs read the local maps and the UAVs' positions and
// failed flags only. UAV 3 fails at t = 0 and the second instance differs only deep inside its
// region (farther than s2 from every other region and from every start), which nobody sees before
// someone has taken the region over: the decisions compared include the hand-overs.
TEST(TruthBlindness, PartTspWorkSharingIsTruthBlind) {
  const auto& hull = world::default_hull();
  world::MissionParams params;
  params.uavs = 8;
  params.s2 = 11;
  MissionOptions mission;
  mission.failures.at = {{3, 0}};
  const auto corrosion = world::scenario("imperfect").corrosion(hull.width());
  mission.corrosion = &corrosion;
  for (const char* algorithm : {"part-tsp", "part-tsp0"}) {
    const OptionMap options{{"share-work", "true"}};
    struct Watch final : MissionObserver {
      grid::Grid<std::int16_t> owner;
      int t = 0;
      int first_hand_over = -1;
      void on_start(const sim::Simulator&, const Planner& planner) override {
        const auto& maps = dynamic_cast<const PartTspPlanner&>(planner).local_maps();
        owner = grid::Grid<std::int16_t>(maps.width(), maps.height(), -1);
        for (int i = 0; i < owner.size(); ++i) owner[i] = static_cast<std::int16_t>(maps.owner(i));
      }
      void on_step(const sim::Simulator&, const Planner& planner) override {
        ++t;
        const auto& p = dynamic_cast<const PartTspPlanner&>(planner);
        if (first_hand_over < 0 && p.failed_regions_taken() + p.pieces_taken() > 0)
          first_hand_over = t;
      }
    } watch;
    mission.observers = {&watch};
    auto planner = make_planner(algorithm, options);
    run_mission(hull, world::generate_instance(hull, corrosion, 5), params, *planner, mission);
    ASSERT_GT(watch.first_hand_over, 0) << algorithm;
    const int r = params.s2;
    const auto starts = world::start_cells(params, hull);
    auto deep_in_region_3 = [&](grid::Cell c) {
      for (int y = c.y - r; y <= c.y + r; ++y) {
        for (int x = c.x - r; x <= c.x + r; ++x) {
          if (watch.owner.contains(grid::Cell{x, y}) && watch.owner(x, y) >= 0 &&
              watch.owner(x, y) != 3)
            return false;
        }
      }
      for (const grid::Cell& start : starts) {  // seen at t = 0, before the failure
        if (std::abs(start.x - c.x) <= r && std::abs(start.y - c.y) <= r) return false;
      }
      return watch.owner[c] == 3;
    };
    int altered = 0;
    auto alter = [&](grid::Grid<std::int8_t>& truth) {
      for (int i : hull.cells()) {
        const grid::Cell c = truth.cell(i);
        if ((c.x + c.y) % 3 == 0 && deep_in_region_3(c)) {
          truth[i] = 1;
          ++altered;
        }
      }
    };
    testing::TruthBlindnessReport report;
    EXPECT_TRUE(testing::planner_is_truth_blind(algorithm, options, params, 5, &report,
                                                mission.failures, alter))
        << algorithm;
    EXPECT_GT(altered, 0) << algorithm;
    EXPECT_GT(report.first_differing_reading, watch.first_hand_over) << algorithm;
  }
}

// The check can tell: a registered oracle, which reads C by design, is caught by it.
TEST(TruthBlindness, TheCheckCatchesEveryOracle) {
  world::MissionParams params;
  params.uavs = 4;
  int oracles = 0;
  for (const auto& info : planner_registry()) {
    if (!info.sees_truth) continue;
    ++oracles;
    EXPECT_FALSE(testing::planner_is_truth_blind(info.name, {}, params, 5)) << info.name;
  }
  EXPECT_GE(oracles, 1);
}

}  // namespace
}  // namespace hullinspect::planners
