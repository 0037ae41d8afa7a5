// Cartesian expansion, stable run ids, paired seeds, hashes and shards.

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/hash.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/shard.hpp"

namespace hullinspect::experiment {
namespace {

const char* kConfig =
    "hull: rectangle\n"
    "grid: {width: 24, height: 8}\n"
    "scenarios: [perfect, imperfect]\n"
    "s2: [7, 9]\n"
    "uavs: [1, 2, 3]\n"
    "algorithms: [lawnmower, {name: lawnmower, label: lm-seed3, options: {partition-seed: 3}}]\n"
    "instances: [11, 5, 8, 2]\n";

ExperimentPlan plan_of(const std::string& yaml) {
  return ExperimentPlan(parse_config(yaml, "plan.yaml", "."));
}

TEST(Hash, Fnv1aTestVectors) {
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ULL);
  EXPECT_EQ(to_hex(0x0123456789abcdefULL), "0123456789abcdef");
  EXPECT_EQ(avalanche(0), 0u);
  // Strings differing in their last character get ids that differ in most hex digits.
  const std::string a = stable_id("run|seed=1");
  const std::string b = stable_id("run|seed=2");
  int same = 0;
  for (std::size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
  EXPECT_LT(same, 8);
}

TEST(ExperimentPlan, CartesianProductInCanonicalOrder) {
  const auto plan = plan_of(kConfig);
  ASSERT_EQ(plan.cells().size(), 2u * 2 * 3 * 2);
  ASSERT_EQ(plan.runs().size(), plan.cells().size() * 4);
  // Algorithm varies fastest, then fleet size, then s2, then scenario.
  const auto& c = plan.cells();
  EXPECT_EQ((std::vector<int>{c[0].scenario, c[0].s2, c[0].uavs, c[0].algorithm}),
            (std::vector<int>{0, 0, 0, 0}));
  EXPECT_EQ(c[1].algorithm, 1);
  EXPECT_EQ(c[2].uavs, 1);
  EXPECT_EQ(c[6].s2, 1);
  EXPECT_EQ(c[12].scenario, 1);
  std::set<std::tuple<int, int, int, int>> distinct;
  for (const auto& cell : c) distinct.emplace(cell.scenario, cell.s2, cell.uavs, cell.algorithm);
  EXPECT_EQ(distinct.size(), c.size());
  // Runs: by cell, then by seed in config order.
  for (std::size_t i = 0; i < plan.runs().size(); ++i) {
    EXPECT_EQ(plan.runs()[i].cell, static_cast<int>(i / 4));
    EXPECT_EQ(plan.runs()[i].seed_index, static_cast<int>(i % 4));
    EXPECT_EQ(plan.run_position(plan.runs()[i].id), static_cast<int>(i));
  }
}

TEST(ExperimentPlan, EveryCellRunsTheSameSeeds) {
  const auto plan = plan_of(kConfig);
  std::map<int, std::vector<std::uint64_t>> seeds_by_cell;
  for (const auto& run : plan.runs()) seeds_by_cell[run.cell].push_back(run.seed);
  for (const auto& [cell, seeds] : seeds_by_cell) {
    EXPECT_EQ(seeds, (std::vector<std::uint64_t>{11, 5, 8, 2})) << "cell " << cell;
  }
  // The mission of a run carries the cell's parameters and the run's seed.
  const auto& run = plan.runs()[4 * 7 + 2];  // cell 7: scenario 0, s2 9, uavs 1, lm-seed3
  const auto spec = plan.mission(run);
  EXPECT_EQ(spec.seed, 8u);
  EXPECT_EQ(spec.params.s2, 9);
  EXPECT_EQ(spec.params.uavs, 1);
  EXPECT_EQ(spec.algorithm, "lawnmower");
  EXPECT_EQ(spec.planner_options.at("partition-seed"), "3");
  EXPECT_DOUBLE_EQ(spec.corrosion.p_tp, 1.0);
}

TEST(ExperimentPlan, RunIdsAreStableAndUnique) {
  const auto a = plan_of(kConfig);
  const auto b = plan_of(kConfig);
  std::set<std::string> ids;
  for (std::size_t i = 0; i < a.runs().size(); ++i) {
    EXPECT_EQ(a.runs()[i].id, b.runs()[i].id);
    EXPECT_EQ(a.runs()[i].id.size(), 16u);
    ids.insert(a.runs()[i].id);
  }
  EXPECT_EQ(ids.size(), a.runs().size());
  // Golden values: a change here changes every results directory's keys (resume and merge across
  // versions); only change it on purpose.
  EXPECT_EQ(a.cells()[0].canonical,
            "hullinspect-run/1|hull=" + a.config().hull_hash +
                "|cell_size=0.5|scenario=perfect|zones=0:24:0.005:5|p_tp=1|p_fp=0|s1=5|s2=7|"
                "theta=90|uavs=1|start_z=2|time_limit=20000|algorithm=lawnmower|planner=lawnmower|"
                "options=partition-seed=0;partitioner=darp;partitioner.cc=0.01;"
                "partitioner.fairness-gain=1;partitioner.gain-growth=1.25;partitioner.gain-shrink="
                "0.7;partitioner.iteration-limit=2000;partitioner.max-discrepancy=2;"
                "partitioner.repair-fallback=true;partitioner.rl=0.0001;partitioner.work-budget="
                "200;prior-statistics=true;prior-weights=false");
  EXPECT_EQ(a.runs()[0].id, stable_id(a.cells()[0].canonical + "|seed=11"));
  EXPECT_EQ(a.config().hull_hash, "5f6762874a04fea0");
  // The id hashes the effective options, defaults included, so it changes on purpose whenever an
  // option is declared for the lawnmower or its partitioner: a new option names a new experiment.
  EXPECT_EQ(a.runs()[0].id, "d8c2fa84a8527fd1");
}

TEST(ExperimentPlan, IdsDependOnTheirOwnCellOnly) {
  const auto base = plan_of(kConfig);
  // More algorithms, fleet sizes and seeds and another name: the existing runs keep their ids.
  const auto bigger = plan_of(
      "name: renamed\n"
      "hull: rectangle\n"
      "grid: {width: 24, height: 8}\n"
      "scenarios: [imperfect, perfect]\n"
      "s2: [9, 7]\n"
      "uavs: [4, 1, 2, 3]\n"
      "algorithms: [{name: lawnmower, label: lm-seed3, options: {partition-seed: 3}}, lawnmower,\n"
      "             {name: lawnmower, label: lm-seed4, options: {partition-seed: 4}}]\n"
      "instances: [2, 5, 8, 11, 99]\n");
  std::set<std::string> bigger_ids;
  for (const auto& r : bigger.runs()) bigger_ids.insert(r.id);
  for (const auto& r : base.runs()) EXPECT_TRUE(bigger_ids.contains(r.id)) << r.id;
  // A parameter that changes results changes every id.
  const auto limited = plan_of(std::string(kConfig) + "time_limit: 500\n");
  for (std::size_t i = 0; i < base.runs().size(); ++i) {
    EXPECT_NE(limited.runs()[i].id, base.runs()[i].id);
  }
}

TEST(ExperimentPlan, ConfigReadBackFromJsonExpandsIdentically) {
  const auto plan = plan_of(kConfig);
  const ExperimentPlan back(config_from_json(config_json(plan.config()), "manifest.json"));
  ASSERT_EQ(back.runs().size(), plan.runs().size());
  for (std::size_t i = 0; i < plan.runs().size(); ++i)
    EXPECT_EQ(back.runs()[i].id, plan.runs()[i].id);
}

TEST(Shard, ParsesKOfN) {
  const Shard s = parse_shard("2/3");
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 3);
  EXPECT_EQ(s.text(), "2/3");
  for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "-1/2", "1/2/3", ""}) {
    try {
      parse_shard(bad);
      ADD_FAILURE() << bad;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.name(), "shard");
      EXPECT_EQ(e.problem(), std::string("must be K/N with 1 <= K <= N (got '") + bad + "')");
    }
  }
}

TEST(Shard, ShardsPartitionTheRunsEvenly) {
  const auto plan = plan_of(kConfig);  // 96 runs
  std::vector<int> owners(plan.runs().size(), 0);
  std::vector<int> sizes;
  for (int k = 1; k <= 5; ++k) {
    const Shard shard{k, 5};
    int size = 0;
    for (int p = 0; p < static_cast<int>(plan.runs().size()); ++p) {
      if (shard.contains(p)) {
        ++owners[static_cast<std::size_t>(p)];
        ++size;
      }
    }
    sizes.push_back(size);
  }
  for (int o : owners) EXPECT_EQ(o, 1);
  EXPECT_LE(
      *std::max_element(sizes.begin(), sizes.end()) - *std::min_element(sizes.begin(), sizes.end()),
      1);
}

TEST(Shard, FromSlurmJobArrays) {
  std::map<std::string, std::string> env;
  const EnvLookup lookup = [&](const char* name) -> const char* {
    auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  };
  EXPECT_FALSE(shard_from_slurm(lookup).has_value());
  env = {
      {"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "4"}, {"SLURM_ARRAY_TASK_MIN", "0"}};
  EXPECT_EQ(shard_from_slurm(lookup)->text(), "1/4");
  env = {{"SLURM_ARRAY_TASK_ID", "10"},
         {"SLURM_ARRAY_TASK_COUNT", "10"},
         {"SLURM_ARRAY_TASK_MIN", "1"}};
  EXPECT_EQ(shard_from_slurm(lookup)->text(), "10/10");  // --array=1-10
  env = {{"SLURM_ARRAY_TASK_ID", "4"},
         {"SLURM_ARRAY_TASK_COUNT", "3"},
         {"SLURM_ARRAY_TASK_MIN", "0"},
         {"SLURM_ARRAY_TASK_STEP", "2"}};
  EXPECT_EQ(shard_from_slurm(lookup)->text(), "3/3");  // --array=0-4:2
  env = {{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "3"}};
  EXPECT_THROW(shard_from_slurm(lookup), ParameterError);
}

}  // namespace
}  // namespace hullinspect::experiment

namespace hullinspect::experiment {
namespace {

// Every algorithm's effective options (defaults included) are what the plan, the
// manifest and runs.csv record, so spelling out a default names the same experiment.
TEST(ExperimentPlan, RecordsEffectiveOptionsWithDefaults) {
  const auto plan = plan_of(
      "hull: rectangle\ngrid: {width: 24, height: 8}\n"
      "algorithms: [lawnmower, {name: part-tsp, label: pt, options: {r1: 3, tsp.kicks: 4}}]\n"
      "instances: 1\n");
  const auto& lawnmower = plan.config().algorithms[0].options;
  EXPECT_EQ(lawnmower.at("partition-seed"), "0");
  EXPECT_EQ(lawnmower.at("partitioner"), "darp");
  EXPECT_EQ(lawnmower.at("partitioner.iteration-limit"), "2000");
  const auto& pt = plan.config().algorithms[1].options;
  EXPECT_EQ(pt.at("r1"), "3");
  EXPECT_EQ(pt.at("r2"), "0");
  EXPECT_EQ(pt.at("tsp.kicks"), "4");
  EXPECT_EQ(pt.at("tsp.dp-max-segments"), "8");
  const auto json = config_json(plan.config());
  EXPECT_EQ(json["algorithms"][1]["options"]["tsp-solver"], "exact");
  // An explicit default and an omitted one give the same cells.
  const auto explicit_default = plan_of(
      "hull: rectangle\ngrid: {width: 24, height: 8}\n"
      "algorithms: [lawnmower, {name: part-tsp, label: pt, options: {r1: 3, r2: 0, tsp.kicks: "
      "4}}]\n"
      "instances: 1\n");
  EXPECT_EQ(explicit_default.cells()[1].id, plan.cells()[1].id);
  // Old spellings are refused with the line and a hint.
  try {
    plan_of(
        "hull: rectangle\ngrid: {width: 24, height: 8}\n"
        "algorithms:\n  - {name: part-tsp, options: {tsp.dp_max_segments: 4}}\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "plan.yaml:4: exact.dp_max_segments: unknown option (did you mean "
              "dp-max-segments?) (known: time-limit, dp-max-segments, kicks, max-segments, "
              "work-budget)");
  }
}

}  // namespace
}  // namespace hullinspect::experiment
