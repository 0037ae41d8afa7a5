// The prior-aware partition (planners/prior_weights.hpp, docs/model.md §5.5): the odds against the
// instance generator's own frequencies, the weights, the partitions the option gives each
// partitioned planner, the partition cache, and whole missions under the shared MissionChecker.

#include "hullinspect/planners/prior_weights.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/partition_cache.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"
#include "support/partition_checker.hpp"

namespace hullinspect::planners {
namespace {

// The same sample in every build: the tolerances below hold for 12 instances (corrosion comes in
// clusters, so the effective sample is the clusters, not the cells); with 3 instances (an earlier
// sanitized-build shortcut) the outside-prior rate was off by 11.7 % under clang ASan.
constexpr int kOddsInstances = 12;

world::CorrosionParams scenario_params(const std::string& name) {
  return world::scenario(name).corrosion(world::default_hull().width());
}

TEST(CorrosionOdds, ARightPriorIsCertain) {
  // p_TP = 1, p_FP = 0: a prior cell is corroded, another is not — exactly.
  for (int l_c : {1, 3, 5, 7}) {
    const world::CorrosionZone zone{0, 10, 0.01, l_c};
    EXPECT_EQ(corrosion_odds(zone, 1.0, 0.0), (CorrosionOdds{1.0, 0.0})) << l_c;
  }
}

TEST(CorrosionOdds, FollowThePriorsQuality) {
  const world::CorrosionZone zone{0, 10, 0.005, 5};
  const CorrosionOdds right = corrosion_odds(zone, 1.0, 0.0);
  const CorrosionOdds missing = corrosion_odds(zone, 0.6, 0.0);  // misses only
  const CorrosionOdds noisy = corrosion_odds(zone, 1.0, 0.003);  // false positives only
  const CorrosionOdds imperfect = corrosion_odds(zone, 0.6, 0.003);
  EXPECT_DOUBLE_EQ(missing.in_prior, 1.0);  // every prior rectangle is a true one
  EXPECT_GT(missing.outside_prior, 0.0);
  EXPECT_LT(noisy.in_prior, right.in_prior);
  EXPECT_EQ(noisy.outside_prior, 0.0);            // nothing missed
  EXPECT_LT(imperfect.in_prior, noisy.in_prior);  // fewer true rectangles among the prior's
  EXPECT_DOUBLE_EQ(imperfect.outside_prior, missing.outside_prior);
}

// Brute force: the odds against the frequencies of the instance generator itself on a square
// all-hull grid (few edges), for the paper's imperfect and combined priors and their zones.
TEST(CorrosionOdds, MatchTheGeneratorsFrequencies) {
  const int side = 200;
  const world::HullMask hull(grid::Grid<std::uint8_t>(side, side, 1), "square");
  struct Case {
    double p_c;
    int l_c;
    double p_tp;
    double p_fp;
  };
  for (const Case c : {Case{0.005, 5, 0.6, 0.003}, Case{0.0025, 3, 0.4, 0.005},
                       Case{0.01, 7, 0.4, 0.005}, Case{0.005, 5, 0.8, 0.0}}) {
    const auto params = world::CorrosionParams::homogeneous(side, c.p_c, c.l_c, c.p_tp, c.p_fp);
    int prior = 0, prior_corroded = 0, other = 0, other_corroded = 0;
    for (int seed = 1; seed <= kOddsInstances; ++seed) {
      const auto instance =
          world::generate_instance(hull, params, static_cast<std::uint64_t>(seed));
      for (int i : hull.cells()) {
        const bool corroded = instance.truth[i] == 1;
        if (instance.prior[i] == 1) {
          ++prior;
          prior_corroded += corroded ? 1 : 0;
        } else {
          ++other;
          other_corroded += corroded ? 1 : 0;
        }
      }
    }
    const CorrosionOdds odds =
        corrosion_odds(world::CorrosionZone{0, side, c.p_c, c.l_c}, c.p_tp, c.p_fp);
    SCOPED_TRACE(::testing::Message() << "p_c " << c.p_c << " l_c " << c.l_c << " p_tp " << c.p_tp
                                      << " p_fp " << c.p_fp);
    ASSERT_GT(prior, 1000);
    EXPECT_NEAR(odds.in_prior, static_cast<double>(prior_corroded) / prior, 0.04);
    const double outside = static_cast<double>(other_corroded) / other;
    EXPECT_NEAR(odds.outside_prior, outside, 0.1 * outside);
  }
}

PlannerContext context_for(const world::HullMask& hull, const world::MissionParams& params,
                           const world::Instance& instance, const std::vector<grid::Cell>& starts,
                           PartitionSource& partitions, const world::CorrosionParams* corrosion) {
  PlannerContext context{hull, params, instance.prior, starts, partitions};
  context.corrosion = corrosion;
  return context;
}

TEST(PriorWorkWeights, ARightPriorGivesSweepInspectsFormula) {
  // 1 + s2/s1 on a prior cell, 1 elsewhere, 0 off the hull: with the perfect scenario's
  // statistics, without statistics, and when the statistics are unknown.
  const auto& hull = world::default_hull();
  const auto corrosion = scenario_params("perfect");
  const auto instance = world::generate_instance(hull, corrosion, 4);
  world::MissionParams params;
  params.s2 = 9;
  const auto starts = world::start_cells(params, hull);
  DirectPartitionSource partitions;
  const world::CorrosionParams* unknown = nullptr;
  for (const world::CorrosionParams* known : {&corrosion, unknown}) {
    const auto context = context_for(hull, params, instance, starts, partitions, known);
    for (bool statistics : {true, false}) {
      const auto w = prior_work_weights(context, statistics);
      for (int i = 0; i < hull.mask().width() * hull.mask().height(); ++i) {
        const double expected =
            !hull.is_hull(i) ? 0.0 : (instance.prior[i] == 1 ? 1.0 + 9.0 / 5.0 : 1.0);
        ASSERT_EQ(w[i], expected) << i;
      }
    }
  }
}

TEST(PartitionRequest, CarriesTheMissionsHullStartsSeedNoFlyAndWeights) {
  const auto& hull = world::default_hull();
  const auto corrosion = scenario_params("perfect");
  const auto instance = world::generate_instance(hull, corrosion, 4);
  world::MissionParams params;
  auto no_fly = std::make_shared<grid::Grid<std::uint8_t>>(hull.width(), hull.height(), 0);
  for (int y = 10; y <= 20; ++y) (*no_fly)(40, y) = 1;
  params.no_fly = no_fly;
  const auto starts = world::start_cells(params, hull);
  const auto reach =
      world::compute_reachability(hull, params.no_fly.get(), params.s1, params.s2, starts);
  DirectPartitionSource partitions;
  auto context = context_for(hull, params, instance, starts, partitions, &corrosion);
  context.reach = &reach;

  const auto uniform = partition_request(context, 7, false, true);
  EXPECT_EQ(uniform.hull, &hull);
  EXPECT_EQ(uniform.starts, starts);
  EXPECT_EQ(uniform.seed, 7U);
  EXPECT_EQ(uniform.weights.size(), 0);
  ASSERT_EQ(uniform.allowed.size(), reach.flyable.size());  // the no-fly zones, as add_no_fly
  EXPECT_EQ(uniform.allowed(40, 15), 0);

  const auto weighted = partition_request(context, 7, true, false);
  const auto w = prior_work_weights(context, false);
  ASSERT_EQ(weighted.weights.size(), w.size());
  for (int i = 0; i < hull.width() * hull.height(); ++i) ASSERT_EQ(weighted.weights[i], w[i]);
}

TEST(PriorWorkWeights, AnImperfectPriorWeighsLessAndTheRestMore) {
  const auto& hull = world::default_hull();
  const auto corrosion = scenario_params("combined");  // zones: back / front halves
  const auto instance = world::generate_instance(hull, corrosion, 4);
  world::MissionParams params;
  const auto starts = world::start_cells(params, hull);
  DirectPartitionSource partitions;
  const auto context = context_for(hull, params, instance, starts, partitions, &corrosion);
  const auto aware = prior_work_weights(context, true);
  const auto trusting = prior_work_weights(context, false);
  std::map<std::pair<bool, bool>, double> seen;  // (front half, prior cell) -> weight
  for (int i : hull.cells()) {
    const bool in_prior = instance.prior[i] == 1;
    const bool front = i % hull.width() >= hull.width() / 2;
    EXPECT_EQ(trusting[i], in_prior ? 1.0 + 7.0 / 5.0 : 1.0);
    if (in_prior) {
      EXPECT_LT(aware[i], trusting[i]);
    } else {
      EXPECT_GT(aware[i], 1.0);
    }
    auto [it, inserted] = seen.emplace(std::pair{front, in_prior}, aware[i]);
    EXPECT_EQ(it->second, aware[i]);  // one weight per zone and prior value
  }
  ASSERT_EQ(seen.size(), 4u);
  // The front half (p_C 0.01, l_C 7) hides more missed corrosion than the back (0.0025, 3).
  EXPECT_GT((seen[{true, false}]), (seen[{false, false}]));
  // The weights are 1 + P·s2/s1 of corrosion_probabilities, which are the zone's odds.
  const auto probability = corrosion_probabilities(context, true);
  for (int i : hull.cells()) {
    const auto& zone = corrosion.zones[i % hull.width() >= corrosion.zones[1].x_begin ? 1 : 0];
    const CorrosionOdds odds = corrosion_odds(zone, corrosion.p_tp, corrosion.p_fp);
    ASSERT_EQ(probability[i], instance.prior[i] == 1 ? odds.in_prior : odds.outside_prior) << i;
    ASSERT_DOUBLE_EQ(aware[i], 1.0 + probability[i] * 7.0 / 5.0) << i;
  }
}

struct Started {
  std::unique_ptr<Planner> planner;
  const partition::Partition& partition() const { return *planner->partition(); }
};

Started start_planner(const std::string& algorithm, const OptionMap& options,
                      const world::Instance& instance, const world::MissionParams& params,
                      PartitionSource& partitions, const world::CorrosionParams* corrosion) {
  const auto& hull = world::default_hull();
  const auto starts = world::start_cells(params, hull);
  Started s{make_planner(algorithm, options)};
  s.planner->start(context_for(hull, params, instance, starts, partitions, corrosion));
  return s;
}

std::vector<double> region_work(const partition::Partition& p, const grid::Grid<double>& w, int n) {
  std::vector<double> work(static_cast<std::size_t>(n), 0.0);
  for (int i : world::default_hull().cells()) work[static_cast<std::size_t>(p.owner[i])] += w[i];
  return work;
}

double spread(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi / *lo;
}

// The option changes the partition as designed: the expected work per region is balanced, and
// every partitioned planner gets the same partition from the one shared weighting.
TEST(PriorWeightedPartition, BalancesTheExpectedWorkForEveryPartitionedPlanner) {
  const auto& hull = world::default_hull();
  for (const char* scenario_name : {"inhomogeneous", "combined"}) {
    const auto corrosion = scenario_params(scenario_name);
    const auto instance = world::generate_instance(hull, corrosion, 2);
    world::MissionParams params;
    params.uavs = 4;
    DirectPartitionSource partitions;
    const auto starts = world::start_cells(params, hull);
    const auto weights = prior_work_weights(
        context_for(hull, params, instance, starts, partitions, &corrosion), true);
    const auto plain = start_planner("part-tsp", {}, instance, params, partitions, &corrosion);
    const double plain_spread = spread(region_work(plain.partition(), weights, params.uavs));
    std::vector<Started> weighted;
    for (const char* algorithm : {"part-tsp", "lawnmower"}) {
      // (Sweep-Inspect's regions are the band partition, then column slabs of the same weights:
      // the slabs are checked below, the band partition in band_partition_test.cpp.)
      OptionMap options{{"prior-weights", "true"}};
      weighted.push_back(
          start_planner(algorithm, options, instance, params, partitions, &corrosion));
    }
    SCOPED_TRACE(scenario_name);
    partition::PartitionRequest request;
    request.hull = &hull;
    request.starts = starts;
    request.weights = weights;
    for (const auto& s : weighted) {
      EXPECT_TRUE(testing::valid_partition(request, s.partition()));
      EXPECT_EQ(s.partition().owner.values().size(), weighted[0].partition().owner.values().size());
      EXPECT_TRUE(std::equal(s.partition().owner.values().begin(),
                             s.partition().owner.values().end(),
                             weighted[0].partition().owner.values().begin()));
    }
    const double weighted_spread =
        spread(region_work(weighted[0].partition(), weights, params.uavs));
    EXPECT_LT(weighted_spread, plain_spread);
    EXPECT_LT(weighted_spread, 1.01);
    EXPECT_GT(plain_spread, 1.05);  // the inhomogeneous hull's front half has more work
    // Sweep-Inspect's fallback regions: column slabs (the stripes partitioner), in the order of
    // the starts along x, that balance the same weights as well: every column but the n - 1 cut
    // ones has one owner.
    const partition::Partition slabs = partition::make_partitioner("stripes")->partition(request);
    testing::PartitionCheck slab_check;
    slab_check.regions_hold_starts = false;  // a slab need not hold its UAV's start
    EXPECT_TRUE(testing::valid_partition(request, slabs, slab_check));
    EXPECT_LT(spread(region_work(slabs, weights, params.uavs)), 1.01);
    const auto& owner = slabs.owner;
    int cut_columns = 0;
    int last_owner = -1;
    for (int x = 0; x < owner.width(); ++x) {
      int first = -2;
      bool cut = false;
      for (int y = 0; y < owner.height(); ++y) {
        const int k = owner(x, y);
        if (k < 0) continue;
        if (first == -2) first = k;
        cut = cut || k != first;
        EXPECT_GE(k, last_owner) << "column " << x;  // slabs left to right
        last_owner = std::max(last_owner, k);
      }
      cut_columns += cut;
    }
    EXPECT_LE(cut_columns, params.uavs - 1);
  }
}

TEST(PriorWeightedPartition, StatisticsChangeThePartitionOnlyWhenThePriorIsImperfect) {
  const auto& hull = world::default_hull();
  world::MissionParams params;
  params.uavs = 4;
  DirectPartitionSource partitions;
  for (const char* scenario_name : {"perfect", "combined"}) {
    const auto corrosion = scenario_params(scenario_name);
    const auto instance = world::generate_instance(hull, corrosion, 3);
    const auto aware = start_planner("part-tsp", {{"prior-weights", "true"}}, instance, params,
                                     partitions, &corrosion);
    const auto trusting =
        start_planner("part-tsp", {{"prior-weights", "true"}, {"prior-statistics", "false"}},
                      instance, params, partitions, &corrosion);
    const auto a = aware.partition().owner.values();
    const auto b = trusting.partition().owner.values();
    EXPECT_EQ(std::equal(a.begin(), a.end(), b.begin()), std::string(scenario_name) == "perfect")
        << scenario_name;
  }
}

TEST(PriorWeightedPartition, IsOffByDefaultForThePapersPlanners) {
  for (const char* algorithm : {"lawnmower", "part-tsp", "part-tsp0", "oracle-part-tsp"}) {
    const auto options = resolve_planner_options(algorithm);
    EXPECT_EQ(options.at("prior-weights"), "false") << algorithm;
    EXPECT_EQ(options.at("prior-statistics"), "true") << algorithm;
  }
  EXPECT_EQ(resolve_planner_options("sweep-inspect").at("prior-weights"), "true");
  // Off: the partition is the unweighted one, whatever the prior.
  const auto& hull = world::default_hull();
  const auto corrosion = scenario_params("inhomogeneous");
  const auto instance = world::generate_instance(hull, corrosion, 5);
  world::MissionParams params;
  params.uavs = 5;
  DirectPartitionSource partitions;
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = world::start_cells(params, hull);
  const auto unweighted = partitions.get("darp", {}, request);
  for (const char* algorithm : {"lawnmower", "part-tsp"}) {
    const auto s = start_planner(algorithm, {}, instance, params, partitions, &corrosion);
    const auto a = s.partition().owner.values();
    EXPECT_TRUE(std::equal(a.begin(), a.end(), unweighted->owner.values().begin())) << algorithm;
  }
}

TEST(PriorWeightedPartition, TheCacheKeepsWeightingsApart) {
  const auto& hull = world::default_hull();
  const auto corrosion = scenario_params("inhomogeneous");
  world::MissionParams params;
  params.uavs = 4;
  PartitionCache cache;
  const auto one = world::generate_instance(hull, corrosion, 1);
  const auto two = world::generate_instance(hull, corrosion, 2);
  const auto plain = start_planner("part-tsp", {}, one, params, cache, &corrosion);
  const auto weighted =
      start_planner("part-tsp", {{"prior-weights", "true"}}, one, params, cache, &corrosion);
  EXPECT_EQ(cache.computed(), 2);
  const auto a = plain.partition().owner.values();
  const auto b = weighted.partition().owner.values();
  EXPECT_FALSE(std::equal(a.begin(), a.end(), b.begin()));
  // The same weighting again is a hit; another instance's prior is another partition; the
  // unweighted one is shared by every instance.
  (void)start_planner("lawnmower", {{"prior-weights", "true"}}, one, params, cache, &corrosion);
  EXPECT_EQ(cache.computed(), 2);
  (void)start_planner("lawnmower", {{"prior-weights", "true"}}, two, params, cache, &corrosion);
  EXPECT_EQ(cache.computed(), 3);
  (void)start_planner("lawnmower", {}, two, params, cache, &corrosion);
  EXPECT_EQ(cache.computed(), 3);
}

// Whole missions with the option: complete, and every step valid under the MissionChecker.
struct MissionCell {
  std::string scenario;
  int s2;
};
class PriorWeightedMissions : public ::testing::TestWithParam<MissionCell> {};

TEST_P(PriorWeightedMissions, CompleteUnderTheMissionChecker) {
  const auto [scenario_name, s2] = GetParam();
  PartitionCache cache;
  for (const char* algorithm : {"part-tsp", "lawnmower"}) {
    for (int n : {4, 8}) {
      MissionSpec spec;
      spec.algorithm = algorithm;
      spec.planner_options = {{"prior-weights", "true"}};
      spec.params.uavs = n;
      spec.params.s2 = s2;
      spec.corrosion = scenario_params(scenario_name);
      spec.seed = 7;
      testing::MissionChecker checker;
      MissionOptions options;
      options.observers = {&checker};
      options.partitions = &cache;
      const auto r = run_mission(spec, world::default_hull(), options);
      SCOPED_TRACE(::testing::Message() << algorithm << " n " << n);
      EXPECT_TRUE(r.complete);
      EXPECT_TRUE(checker.ok());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenarios, PriorWeightedMissions,
                         ::testing::Values(MissionCell{"perfect", 7}, MissionCell{"imperfect", 9},
                                           MissionCell{"inhomogeneous", 11},
                                           MissionCell{"combined", 7}),
                         [](const auto& test) {
                           return test.param.scenario + "_s2_" + std::to_string(test.param.s2);
                         });

}  // namespace
}  // namespace hullinspect::planners
