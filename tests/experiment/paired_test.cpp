// Paired comparisons of the report (docs/experiments.md#hullinspect-report): differences seed by
// seed, bootstrap intervals, win rates, rankings and the paper's claims, on small hand-made tables.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/paired.hpp"

namespace hullinspect::experiment {
namespace {

struct RunRow {
  std::string scenario, algorithm;
  int s2, uavs, seed;
  std::string t_c, t_m;
  std::string planner = "";  // the registry name behind the label; "" = the label itself
};

CsvTable table(const std::vector<RunRow>& runs) {
  CsvTable t;
  t.header = {"scenario", "algorithm", "planner", "s2", "uavs", "seed", "T_c", "T_m"};
  for (const auto& r : runs) {
    t.rows.push_back({r.scenario, r.algorithm, r.planner.empty() ? r.algorithm : r.planner,
                      std::to_string(r.s2), std::to_string(r.uavs), std::to_string(r.seed), r.t_c,
                      r.t_m});
  }
  return t;
}

// `algorithm` with T_c = base_c + seed·step and T_m = base_m + seed on seeds 1..seeds.
void add(std::vector<RunRow>& runs, const std::string& scenario, const std::string& algorithm,
         int base_c, int base_m, int seeds = 8, int s2 = 7, int uavs = 4, int step = 3,
         const std::string& planner = "") {
  for (int seed = 1; seed <= seeds; ++seed) {
    runs.push_back({scenario, algorithm, s2, uavs, seed, std::to_string(base_c + seed * step),
                    std::to_string(base_m + seed), planner});
  }
}

TEST(Bootstrap, ConstantValuesGiveAPointInterval) {
  const auto b = bootstrap_mean({-10, -10, -10, -10}, 500, 1);
  EXPECT_EQ(b.mean, -10);
  EXPECT_EQ(b.low, -10);
  EXPECT_EQ(b.high, -10);
}

TEST(Bootstrap, IntervalHoldsTheMeanAndIsReproducible) {
  const std::vector<double> v = {1, 5, 2, 8, 3, 9, 4, 7, 6, 10};
  const auto a = bootstrap_mean(v, 2000, 1);
  EXPECT_DOUBLE_EQ(a.mean, 5.5);
  EXPECT_LT(a.low, 5.5);
  EXPECT_GT(a.high, 5.5);
  EXPECT_GT(a.low, 1.0);  // a mean of ten values from 1..10 hardly reaches the extremes
  EXPECT_LT(a.high, 10.0);
  const auto again = bootstrap_mean(v, 2000, 1);
  EXPECT_EQ(again.low, a.low);
  EXPECT_EQ(again.high, a.high);
  // Another seed draws other resamples, but 2000 of them pin the interval down closely.
  const auto other = bootstrap_mean(v, 2000, 2);
  EXPECT_NEAR(other.low, a.low, 0.3);
  EXPECT_NEAR(other.high, a.high, 0.3);
}

TEST(Paired, DifferencesAreTakenSeedBySeed) {
  std::vector<RunRow> runs;
  add(runs, "perfect", "fast", 100, 300);
  add(runs, "perfect", "slow", 110, 290);
  const auto an = analyse_pairs(table(runs), "runs.csv");
  const auto* d = an.find({"perfect", 7, 4}, "T_c", "fast", "slow");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->pairs, 8);
  // The seeds vary T_c by 3 per seed in both: the paired difference is exactly −10 every time.
  EXPECT_DOUBLE_EQ(d->mean, -10);
  EXPECT_DOUBLE_EQ(d->ci_low, -10);
  EXPECT_DOUBLE_EQ(d->ci_high, -10);
  EXPECT_DOUBLE_EQ(d->win_rate, 1);
  EXPECT_EQ(d->verdict(), -1);
  const auto* m = an.find({"perfect", 7, 4}, "T_m", "fast", "slow");
  ASSERT_NE(m, nullptr);
  EXPECT_DOUBLE_EQ(m->mean, 10);
  EXPECT_EQ(m->verdict(), 1);
  EXPECT_DOUBLE_EQ(m->win_rate, 0);
}

TEST(Paired, IncompleteAndUnsharedSeedsAreLeftOutTiesCountHalf) {
  std::vector<RunRow> runs = {
      {"s", "a", 7, 4, 1, "100", "200", ""}, {"s", "b", 7, 4, 1, "100", "210", ""},  // tie on T_c
      {"s", "a", 7, 4, 2, "90", "200", ""},  {"s", "b", 7, 4, 2, "100", "210", ""},
      {"s", "a", 7, 4, 3, "", "", ""},       {"s", "b", 7, 4, 3, "50", "60", ""},  // a incomplete
      {"s", "a", 7, 4, 4, "10", "20", ""},  // b never ran seed 4
  };
  const auto an = analyse_pairs(table(runs), "runs.csv");
  const auto* d = an.find({"s", 7, 4}, "T_c", "a", "b");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->pairs, 2);
  EXPECT_DOUBLE_EQ(d->mean, -5);
  EXPECT_DOUBLE_EQ(d->win_rate, 0.75);
  EXPECT_EQ(d->verdict(), 0);  // [−10, 0]: the interval reaches zero
}

TEST(Paired, RankingOrdersByMeanRankOverCommonSeeds) {
  std::vector<RunRow> runs;
  add(runs, "perfect", "middle", 150, 300);
  add(runs, "perfect", "best", 100, 300);
  add(runs, "perfect", "worst", 200, 300);
  const auto an = analyse_pairs(table(runs), "runs.csv");
  ASSERT_EQ(an.rankings.size(), 2u);
  const auto& r = an.rankings[0];
  EXPECT_EQ(r.metric, "T_c");
  EXPECT_EQ(r.seeds, 8);
  ASSERT_EQ(r.order.size(), 3u);
  EXPECT_EQ(r.order[0].algorithm, "best");
  EXPECT_DOUBLE_EQ(r.order[0].mean_rank, 1);
  EXPECT_EQ(r.order[1].algorithm, "middle");
  EXPECT_EQ(r.order[2].algorithm, "worst");
  EXPECT_DOUBLE_EQ(r.order[2].mean, 200 + 4.5 * 3);
  // T_m: all equal, so all share rank 2.
  for (const auto& e : an.rankings[1].order) EXPECT_DOUBLE_EQ(e.mean_rank, 2);
}

TEST(Paired, OraclesAreComparedButNotRanked) {
  // Which label is an oracle comes from its planner's registry entry (sees_truth), not its name.
  std::vector<RunRow> runs;
  add(runs, "perfect", "part-tsp", 150, 300);
  add(runs, "perfect", "bound", 90, 280, 8, 7, 4, 3, "oracle-part-tsp");
  add(runs, "perfect", "oracle-like", 120, 290, 8, 7, 4, 3, "part-tsp0");
  const auto an = analyse_pairs(table(runs), "runs.csv");
  EXPECT_EQ(an.references, (std::set<std::string>{"bound"}));
  ASSERT_NE(an.find({"perfect", 7, 4}, "T_c", "part-tsp", "bound"), nullptr);
  ASSERT_EQ(an.rankings[0].order.size(), 2u);
  EXPECT_EQ(an.rankings[0].order[0].algorithm, "oracle-like");
  EXPECT_EQ(an.rankings[0].order[1].algorithm, "part-tsp");
}

TEST(Paired, AMalformedTimeNamesTheFileLineAndColumn) {
  // Times are seconds (whole or not); a negative one is no time.
  std::vector<RunRow> runs = {{"s", "a", 7, 4, 1, "-5", "200", ""}};
  try {
    analyse_pairs(table(runs), "runs.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "runs.csv:2: T_c: must be a number in [0, 1e+15] (got '-5')");
  }
}

TEST(Paired, PlannersChooseAndOrderTheComparison) {
  std::vector<RunRow> runs;
  add(runs, "perfect", "a", 100, 300);
  add(runs, "perfect", "b", 110, 300);
  add(runs, "perfect", "c", 120, 300);
  PairedOptions options;
  options.algorithms = {"c", "a"};
  const auto an = analyse_pairs(table(runs), "runs.csv", options);
  EXPECT_EQ(an.algorithms, (std::vector<std::string>{"c", "a"}));
  ASSERT_NE(an.find({"perfect", 7, 4}, "T_c", "c", "a"), nullptr);
  EXPECT_EQ(an.find({"perfect", 7, 4}, "T_c", "a", "b"), nullptr);
  options.algorithms = {"a", "zz"};
  try {
    analyse_pairs(table(runs), "runs.csv", options);
    FAIL() << "accepted an algorithm with no runs";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "runs.csv: no runs of algorithm 'zz' (the runs hold: a, b, c)");
  }
}

std::string verdict(const std::vector<ClaimCheck>& claims, const std::string& id) {
  for (const auto& c : claims) {
    if (c.id == id) return c.verdict;
  }
  return "(missing)";
}

TEST(Claims, CheckedAgainstThePairedNumbers) {
  std::vector<RunRow> runs;
  for (int n : {4, 8}) {
    // Part-TSP fastest in T_c but slower than Part-TSP0 in T_m; Coop-Frontier slower than
    // Part-TSP0.
    add(runs, "perfect", "part-tsp", 150, 460, 8, 7, n);
    add(runs, "perfect", "part-tsp0", 300, 430, 8, 7, n);
    add(runs, "perfect", "coop-frontier", n == 4 ? 350 : 290, 470, 8, 7, n);
    add(runs, "perfect", "lawnmower", 370, 380, 8, 7, n);
  }
  const auto claims = check_paper_claims(analyse_pairs(table(runs), "runs.csv"));
  EXPECT_EQ(verdict(claims, "C1"), "held");
  EXPECT_EQ(verdict(claims, "C2"), "held");
  EXPECT_EQ(verdict(claims, "C3"), "partly held (1 of 2)");  // at n = 8 Coop-Frontier is faster
  EXPECT_EQ(verdict(claims, "C4a"), "held");
  EXPECT_EQ(verdict(claims, "C4b"), "held");
  EXPECT_EQ(verdict(claims, "C5"), "held");
  EXPECT_EQ(verdict(claims, "C6"), "not testable");
  // Spread at n = 4: 370 − 150 = 220; at n = 8: 370 − 150 = 220 as well: not smaller.
  EXPECT_EQ(verdict(claims, "C7"), "not held");
  for (const auto& c : claims) {
    if (c.id == "C1") {
      EXPECT_EQ(c.evidence,
                "6 of 6 paired comparisons have the 95 % interval on the claimed side; weakest: "
                "part-tsp − coop-frontier (perfect, s2 = 7, n = 8): -140.0 [-140.0, -140.0] s, "
                "100 % wins");
    }
  }
}

TEST(Claims, CombinedScenarioClaimNotHeldWhenPartTspWins) {
  std::vector<RunRow> runs;
  add(runs, "combined", "part-tsp", 150, 400);
  add(runs, "combined", "coop-frontier", 200, 400);
  add(runs, "combined", "lawnmower", 370, 380);
  const auto claims = check_paper_claims(analyse_pairs(table(runs), "runs.csv"));
  EXPECT_EQ(verdict(claims, "C6"), "partly held (1 of 2)");
  EXPECT_EQ(verdict(claims, "C1"), "not testable");
}

}  // namespace
}  // namespace hullinspect::experiment
