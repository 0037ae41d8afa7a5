// Experiment configs: defaults, the resolved scenarios and sweeps, presets, and a table of bad
// configs with their exact messages (file:line: key: problem).

#include <gtest/gtest.h>
#include <unistd.h>

#include "experiment_test_support.hpp"
#include "source_dir.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/presets.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/hull.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::experiment {
namespace {

ExperimentConfig parse(const std::string& yaml) {
  return parse_config(yaml, "bad.yaml", "/cfg");
}

/// The error a config produces when parsed and expanded (cells validated), or "" if none.
std::string error_of(const std::string& yaml) {
  return testing::config_error(yaml, "bad.yaml");
}

std::string known_algorithms() {
  std::string names;
  for (const auto& p : planners::planner_registry()) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

TEST(ExperimentConfig, EmptyConfigGivesTheSpecDefaults) {
  const auto c = parse("");
  EXPECT_EQ(c.hull->width(), 230);
  EXPECT_EQ(c.hull->height(), 30);
  ASSERT_EQ(c.scenarios.size(), 1u);
  EXPECT_EQ(c.scenarios[0].name, "perfect");
  EXPECT_EQ(c.mission.s1, 5);
  EXPECT_EQ(c.s2, std::vector<int>{7});
  EXPECT_EQ(c.uavs, std::vector<int>{4});
  EXPECT_DOUBLE_EQ(c.mission.theta, 90.0);
  ASSERT_EQ(c.algorithms.size(), 1u);
  EXPECT_EQ(c.algorithms[0].label, "lawnmower");
  ASSERT_EQ(c.seeds.size(), 50u);  // model.md §6: 50 instances
  EXPECT_EQ(c.seeds.front(), 1u);
  EXPECT_EQ(c.seeds.back(), 50u);
  EXPECT_EQ(c.mission.time_limit, 20000);
  EXPECT_EQ(c.curve.step, 5);
  EXPECT_EQ(c.curve.end, 1500);
  EXPECT_EQ(c.name, "bad");
}

TEST(ExperimentConfig, ScalarsAndListsAndSeeds) {
  const auto c = parse(
      "s2: 9\nuavs: [3, 6]\ninstances: [7, 3, 11]\nalgorithms:\n  - name: lawnmower\n"
      "    label: lm\n    options: {partition-seed: 4}\n");
  EXPECT_EQ(c.s2, std::vector<int>{9});
  EXPECT_EQ(c.uavs, (std::vector<int>{3, 6}));
  EXPECT_EQ(c.seeds, (std::vector<std::uint64_t>{7, 3, 11}));
  ASSERT_EQ(c.algorithms.size(), 1u);
  EXPECT_EQ(c.algorithms[0].label, "lm");
  EXPECT_EQ(c.algorithms[0].planner, "lawnmower");
  EXPECT_EQ(c.algorithms[0].options.at("partition-seed"), "4");
  const auto counted = parse("instances: 3\nfirst_seed: 100\n");
  EXPECT_EQ(counted.seeds, (std::vector<std::uint64_t>{100, 101, 102}));
}

TEST(ExperimentConfig, CustomScenariosResolveToZones) {
  const auto c = parse(
      "hull: rectangle\ngrid: {width: 40, height: 10}\n"
      "scenarios:\n"
      "  - inhomogeneous\n"
      "  - {name: heavy, p_c: 0.02, l_c: 7, p_tp: 0.5}\n"
      "  - {name: halves, base: imperfect, front_p_c: 0.01}\n"
      "  - name: zoned\n"
      "    zones: [{x_begin: 0, x_end: 10, p_c: 0.1, l_c: 1}, {x_begin: 10, x_end: 40, p_c: 0, "
      "l_c: 3}]\n");
  ASSERT_EQ(c.scenarios.size(), 4u);
  const auto& inh = c.scenarios[0].corrosion;
  ASSERT_EQ(inh.zones.size(), 2u);
  EXPECT_EQ(inh.zones[0].x_end, 20);
  EXPECT_DOUBLE_EQ(inh.zones[0].p_c, 0.0025);
  EXPECT_EQ(inh.zones[1].l_c, 7);
  const auto& heavy = c.scenarios[1].corrosion;
  ASSERT_EQ(heavy.zones.size(), 1u);  // homogeneous: one zone
  EXPECT_DOUBLE_EQ(heavy.zones[0].p_c, 0.02);
  EXPECT_EQ(heavy.zones[0].l_c, 7);
  EXPECT_DOUBLE_EQ(heavy.p_tp, 0.5);
  EXPECT_DOUBLE_EQ(heavy.p_fp, 0.0);
  const auto& halves = c.scenarios[2].corrosion;
  ASSERT_EQ(halves.zones.size(), 2u);
  EXPECT_DOUBLE_EQ(halves.zones[0].p_c, 0.005);
  EXPECT_DOUBLE_EQ(halves.zones[1].p_c, 0.01);
  EXPECT_DOUBLE_EQ(halves.p_tp, 0.6);  // from the base
  EXPECT_DOUBLE_EQ(halves.p_fp, 0.003);
  EXPECT_EQ(c.scenarios[3].corrosion.zones.size(), 2u);
}

TEST(ExperimentConfig, SweepsExpandIntoNamedScenarios) {
  const auto c = parse(
      "scenarios: [combined]\nsweeps:\n"
      "  - {parameter: p_tp, values: [1.0, 0.4]}\n"
      "  - {parameter: front_back_p_c, base: perfect, values: [[0.01, 0.0025], [0.005, 0.005]]}\n");
  ASSERT_EQ(c.scenarios.size(), 5u);
  EXPECT_EQ(c.scenarios[0].name, "combined");
  EXPECT_EQ(c.scenarios[0].sweep, "");
  EXPECT_EQ(c.scenarios[1].name, "p_tp=1.0");
  EXPECT_EQ(c.scenarios[1].sweep, "p_tp");
  EXPECT_EQ(c.scenarios[1].sweep_value, "1.0");
  EXPECT_DOUBLE_EQ(c.scenarios[2].corrosion.p_tp, 0.4);
  const auto& fb = c.scenarios[3];
  EXPECT_EQ(fb.name, "front_back_p_c=0.01/0.0025");
  ASSERT_EQ(fb.corrosion.zones.size(), 2u);
  EXPECT_DOUBLE_EQ(fb.corrosion.zones[0].p_c, 0.0025);   // back
  EXPECT_DOUBLE_EQ(fb.corrosion.zones[1].p_c, 0.01);     // front
  EXPECT_EQ(fb.corrosion.zones[1].l_c, 5);               // l_c of the base, both halves
  EXPECT_EQ(c.scenarios[4].corrosion.zones.size(), 1u);  // equal halves collapse to one zone
}

TEST(ExperimentConfig, PresetsMatchSpecSection6) {
  EXPECT_EQ(preset_names(),
            (std::vector<std::string>{"beyond", "fig8", "obstacles", "paper", "paper-quick"}));
  const auto paper = load_preset("paper");
  ASSERT_EQ(paper.scenarios.size(), 4u);
  EXPECT_EQ(paper.scenarios[1].name, "imperfect");
  EXPECT_EQ(paper.s2, (std::vector<int>{7, 9, 11}));
  EXPECT_EQ(paper.uavs, (std::vector<int>{4, 5, 6, 7, 8}));
  ASSERT_EQ(paper.algorithms.size(), 4u);
  EXPECT_EQ(paper.algorithms[0].planner, "lawnmower");
  EXPECT_EQ(paper.algorithms[1].planner, "part-tsp");
  EXPECT_EQ(paper.algorithms[2].planner, "part-tsp0");
  EXPECT_EQ(paper.algorithms[3].planner, "coop-frontier");
  EXPECT_EQ(paper.seeds.size(), 50u);
  const auto quick = load_preset("paper-quick");
  EXPECT_EQ(quick.uavs, (std::vector<int>{4, 8}));
  EXPECT_EQ(quick.seeds.size(), 10u);
  EXPECT_EQ(quick.s2, paper.s2);
  const auto fig8 = load_preset("fig8");
  ASSERT_EQ(fig8.scenarios.size(), 13u);  // combined + 3 sweeps of 4 values
  EXPECT_EQ(fig8.scenarios[0].name, "combined");
  EXPECT_EQ(fig8.scenarios[4].name, "p_tp=0.4");
  EXPECT_EQ(fig8.scenarios[8].name, "p_fp=0.005");
  EXPECT_EQ(fig8.scenarios[12].name, "front_back_p_c=0.01/0");

  // Expanding needs every named planner; the ones registered in this build must validate.
  for (const auto& name : preset_names()) {
    auto config = load_preset(name);
    std::vector<std::string> available;
    for (const auto& a : config.algorithms) {
      for (const auto& p : planners::planner_registry()) {
        if (p.name == a.planner) available.push_back(a.label);
      }
    }
    ASSERT_FALSE(available.empty());
    const std::size_t per_algorithm =
        config.scenarios.size() * config.s2.size() * config.uavs.size() * config.seeds.size();
    restrict_algorithms(config, available);
    const ExperimentPlan plan(std::move(config));
    EXPECT_EQ(plan.runs().size(), per_algorithm * available.size()) << name;
  }
}

TEST(ExperimentConfig, RestrictAndOverride) {
  auto c = parse("algorithms: [lawnmower, {name: lawnmower, label: other}]\n");
  restrict_algorithms(c, {"other"});
  ASSERT_EQ(c.algorithms.size(), 1u);
  EXPECT_EQ(c.algorithms[0].label, "other");
  EXPECT_THROW(restrict_algorithms(c, {"lawnmower"}), ParameterError);
  set_instance_count(c, 4);
  EXPECT_EQ(c.seeds, (std::vector<std::uint64_t>{1, 2, 3, 4}));
}

TEST(ExperimentConfig, FirstSeedShiftsTheSeedsAndKeepsTheirCount) {
  auto c = parse("instances: 3\nfirst_seed: 10\n");
  set_first_seed(c, 1'000'000);
  EXPECT_EQ(c.seeds, (std::vector<std::uint64_t>{1'000'000, 1'000'001, 1'000'002}));
  // After --instances N: N seeds from the first.
  set_instance_count(c, 2);
  set_first_seed(c, 7);
  EXPECT_EQ(c.seeds, (std::vector<std::uint64_t>{7, 8}));
  // A listed set of seeds becomes as many consecutive ones.
  auto listed = parse("instances: [5, 3, 9]\n");
  set_first_seed(listed, 20);
  EXPECT_EQ(listed.seeds, (std::vector<std::uint64_t>{20, 21, 22}));
  // The last seed may be 2^64 - 1, not beyond.
  set_first_seed(c, UINT64_MAX - 1);
  EXPECT_EQ(c.seeds, (std::vector<std::uint64_t>{UINT64_MAX - 1, UINT64_MAX}));
  try {
    set_first_seed(c, UINT64_MAX);
    ADD_FAILURE() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.name(), "first-seed");
    EXPECT_EQ(e.problem(),
              "leaves no room for 2 instance seeds below 2^64 (got 18446744073709551615)");
  }
  EXPECT_EQ(c.seeds, (std::vector<std::uint64_t>{UINT64_MAX - 1, UINT64_MAX}));  // unchanged
}

TEST(ExperimentConfig, ResolvedJsonRoundTripsWithTheSameFingerprint) {
  const auto c = parse(
      "scenarios: [imperfect]\nsweeps: [{parameter: p_fp, values: [0.001, 0.003]}]\n"
      "s2: [7, 11]\nuavs: [2]\nalgorithms: [{name: lawnmower, options: {partition-seed: 2}}]\n"
      "instances: [5, 9]\ncurve: {step: 10, end: 300}\n");
  const auto back = config_from_json(config_json(c), "manifest.json");
  EXPECT_EQ(config_fingerprint(back), config_fingerprint(c));
  EXPECT_EQ(config_json(back), config_json(c));
  auto renamed = c;
  renamed.name = "another name";
  EXPECT_EQ(config_fingerprint(renamed), config_fingerprint(c));
  auto changed = c;
  changed.mission.time_limit = 100;
  EXPECT_NE(config_fingerprint(changed), config_fingerprint(c));
}

struct BadConfig {
  std::string yaml;
  std::string message;  // exact, or a prefix when it ends with "…"
};

TEST(ExperimentConfig, BadConfigsNameFileLineAndKey) {
  const std::vector<BadConfig> cases = {
      {"s1: 5\ngrdi: {}\n",
       "bad.yaml:2: grdi: unknown key (known: name, description, hull, grid, scenarios, sweeps, "
       "s1, "
       "s2, theta, uavs, start_z, algorithms, instances, first_seed, time_limit, curve, prior, "
       "truth, prior-defects, truth-defects, frame-spacing, no-fly, launch, separation, speed, "
       "climb-speed, battery)"},
      {"grid:\n  width: 230\n  depth: 3\n",
       "bad.yaml:3: grid.depth: unknown key (known: width, height, cell_size)"},
      {"- 1\n- 2\n", "bad.yaml:1: config: must be a map (got a list)"},
      {"s1: 5\ns1: 7\n", "bad.yaml:2: s1: appears twice"},
      {"s2: seven\n", "bad.yaml:1: s2: must be an integer in [3, 8193] (got 'seven')"},
      {"s2: [7, 9.5]\n", "bad.yaml:1: s2: must be an integer in [3, 8193] (got '9.5')"},
      {"uavs:\n  - 4\n  - 0\n", "bad.yaml:3: uavs: must be at least 1 (got 0)"},
      {"s2: [7, 7]\n", "bad.yaml:1: s2: lists 7 twice"},
      {"s2:\n  - 7\n  - 8\n", "bad.yaml:3: s2: must be an odd integer greater than s1 = 5 (got 8)"},
      {"s1: 9\n", "bad.yaml:1: s2: must be an odd integer greater than s1 = 9 (got 7)"},
      {"theta: 180\n", "bad.yaml:1: theta: must be in (0, 180) degrees, exclusive (got 180)"},
      {"theta: wide\n",
       "bad.yaml:1: theta: must be a finite number of magnitude at most 1e15 (got 'wide')"},
      {"start_z: 3\n", "bad.yaml:1: start_z: must be 1 or 2 (got 3)"},
      {"time_limit: 0\n", "bad.yaml:1: time_limit: must be at least 1 step (got 0)"},
      {"instances: 0\n", "bad.yaml:1: instances: must be an integer in [1, 1000000] (got 0)"},
      {"instances: [1, -2]\n",
       "bad.yaml:1: instances: must be a non-negative integer seed below 2^64 (got '-2')"},
      {"instances: [3, 3]\n", "bad.yaml:1: instances: lists seed 3 twice"},
      {"instances: [3]\nfirst_seed: 2\n",
       "bad.yaml:2: first_seed: applies only when 'instances' is a count"},
      {"curve: {step: 0}\n",
       "bad.yaml:1: curve.step: must be an integer in [1, 1000000000] (got 0)"},
      {"hull: nothere.txt\n", "bad.yaml:1: hull: /cfg/nothere.txt: cannot open the hull file"},
      {"hull: rectangle\n", "bad.yaml:1: hull: 'rectangle' needs grid.width and grid.height"},
      {"grid: {width: 100}\n", "bad.yaml:1: grid.width: is 100 but the hull mask is 230 wide"},
      {"hull: rectangle\ngrid: {width: 4, height: 2}\nuavs: [2, 9]\n",
       "bad.yaml:3: uavs: must be at most the 8 hull cells (got 9)"},
      {"scenarios: [perfect, bogus]\n",
       "bad.yaml:1: scenarios[1]: unknown scenario 'bogus' (built in: perfect, imperfect, "
       "inhomogeneous, combined; or give a map with 'name' and parameters)"},
      {"scenarios: [perfect, perfect]\n",
       "bad.yaml:1: scenarios[1]: scenario name 'perfect' is used twice"},
      {"scenarios:\n  - name: x\n    p_tp: 1.5\n",
       "bad.yaml:3: scenarios[0].p_tp: must be a number in [0, 1] (got 1.5)"},
      {"scenarios:\n  - name: x\n    l_c: 4\n",
       "bad.yaml:3: scenarios[0].l_c: must be odd (got 4)"},
      {"scenarios:\n  - {p_c: 0.1}\n",
       "bad.yaml:2: scenarios[0]: a custom scenario needs a 'name'"},
      {"scenarios:\n  - {name: x, colour: red}\n",
       "bad.yaml:2: scenarios[0].colour: unknown key (known: name, base, zones, p_c, l_c, "
       "back_p_c, "
       "back_l_c, front_p_c, front_l_c, p_tp, p_fp, failures, no-fly)"},
      {"scenarios:\n  - name: x\n    zones: [{x_begin: 0, x_end: 100, p_c: 0.1, l_c: 3}]\n",
       "bad.yaml:3: scenarios[0].zones: must cover the grid's columns 0 to 230 (they end at 100)"},
      {"scenarios:\n  - name: x\n    p_c: 0.1\n    zones: [{x_begin: 0, x_end: 230, p_c: 0.1, "
       "l_c: 3}]\n",
       "bad.yaml:3: scenarios[0].p_c: cannot be combined with 'zones'"},
      {"sweeps:\n  - {parameter: p_zz, values: [1]}\n",
       "bad.yaml:2: sweeps[0].parameter: unknown sweep parameter 'p_zz' (known: p_tp, p_fp, p_c, "
       "l_c, back_p_c, front_p_c, back_l_c, front_l_c, front_back_p_c)"},
      {"sweeps:\n  - parameter: front_back_p_c\n    values: [[0.01, 0.002], [0.01]]\n",
       "bad.yaml:3: sweeps[0].values[1]: must be a pair [front p_c, back p_c]"},
      {"sweeps:\n  - parameter: p_fp\n    values:\n      - 0\n      - 2\n",
       "bad.yaml:5: sweeps[0].values[1]: must be a number in [0, 1] (got 2)"},
      {"sweeps:\n  - {parameter: p_tp, base: nowhere, values: [1]}\n",
       "bad.yaml:2: sweeps[0].base: unknown base scenario 'nowhere' (built in: perfect, imperfect, "
       "inhomogeneous, combined; or a scenario listed earlier under 'scenarios')"},
      {"algorithms:\n  - lawnmower\n  - warp-drive\n",
       "bad.yaml:3: algorithm: unknown algorithm 'warp-drive' (known: " + known_algorithms() + ")"},
      {"algorithms:\n  - {name: lawnmower, label: \"a,b\"}\n",
       "bad.yaml:2: algorithms[0].label: 'a,b' must not contain commas, quotes or line breaks (it "
       "names a CSV value)"},
      {"algorithms: [lawnmower, lawnmower]\n",
       "bad.yaml:1: algorithms[1]: label 'lawnmower' is used twice (give each entry its own "
       "'label')"},
      {"algorithms:\n  - name: lawnmower\n    options: {warp: 9}\n",
       "bad.yaml:2: lawnmower.warp: unknown option (known: …"},
      {"algorithms:\n  - name: lawnmower\n    options: {partition-seed: [1]}\n",
       "bad.yaml:3: algorithms[0].options.partition-seed: must be a single value"},
      {"s2: [7, 9\n", "bad.yaml:2: invalid YAML: …"},
      // Values that a replaced map would ignore (the files need not exist: refused first).
      {"prior: p.txt\nsweeps: [{parameter: p_tp, values: [0.5, 1]}]\n",
       "bad.yaml:2: sweeps[0].parameter: has no effect with 'prior:' (the prior file replaces the "
       "map it would shape); remove one of them"},
      {"prior: p.txt\nscenarios: [{name: a, p_c: 0.1, p_fp: 0.2}]\n",
       "bad.yaml:2: scenarios[0].p_fp: has no effect with 'prior:' (the prior file replaces the "
       "map "
       "it would shape); remove one of them"},
      {"truth: t.txt\nscenarios:\n  - {name: a, p_tp: 0.5}\n  - {name: b, p_c: 0.1}\n",
       "bad.yaml:4: scenarios[1].p_c: has no effect with 'truth:' (the truth file replaces the map "
       "it would shape); remove one of them"},
      {"truth: t.txt\nsweeps: [{parameter: front_back_p_c, values: [[0.1, 0.2]]}]\n",
       "bad.yaml:2: sweeps[0].parameter: has no effect with 'truth:' (the truth file replaces the "
       "map it would shape); remove one of them"},
      {"hull: {mesh: hull.stl}\ngrid: {width: 7}\n",
       "bad.yaml:2: grid.width: cannot be set for a mesh hull (its grid comes from the mesh; set "
       "hull.cell-size instead)"},
  };
  for (const auto& c : cases) {
    const std::string got = error_of(c.yaml);
    const std::string ellipsis = "…";
    if (c.message.ends_with(ellipsis)) {
      const std::string prefix = c.message.substr(0, c.message.size() - ellipsis.size());
      EXPECT_TRUE(got.starts_with(prefix)) << "config:\n" << c.yaml << "got: " << got;
    } else {
      EXPECT_EQ(got, c.message) << "config:\n" << c.yaml;
    }
  }
}

TEST(ExperimentConfig, DefectListsBecomeThePriorAndTruth) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("hullinspect_config_defects_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "plate.txt") << "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n";
  std::ofstream(dir / "survey.csv") << "frame,z_m,side,w_m,h_m\n2,0.5,starboard,1,0.5\n";
  const ExperimentConfig c = parse_config(
      "hull: plate.txt\nprior-defects: survey.csv\ntruth-defects: survey.csv\nframe-spacing: 0.5\n",
      "c.yaml", dir);
  ASSERT_TRUE(c.maps.prior && c.maps.truth);
  int corroded = 0;
  for (int i = 0; i < c.maps.prior->cells.size(); ++i) corroded += c.maps.prior->cells[i] == 1;
  EXPECT_EQ(corroded, 2);  // x ∈ [0.5, 1.5) at row 0: columns 1 and 2
  // As the config names it (found from its directory), identified by the map it gives.
  EXPECT_EQ(config_json(c)["prior_defects"], "survey.csv");
  EXPECT_EQ(config_json(c)["prior_hash"].get<std::string>().size(), 16u);
  EXPECT_EQ(config_json(c)["prior_hash"], config_json(c)["truth_hash"]);
  EXPECT_EQ(config_fingerprint(config_from_json(config_json(c), "manifest.json")),
            config_fingerprint(c));
  EXPECT_EQ(config_json(c)["frame_spacing"], 0.5);

  try {
    parse_config("hull: plate.txt\nprior: plate.txt\nprior-defects: survey.csv\n", "c.yaml", dir);
    ADD_FAILURE() << "a prior given twice was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "c.yaml:3: prior-defects: give either prior or prior-defects, not both");
  }
  std::filesystem::remove_all(dir);
}

TEST(ExperimentConfig, UnknownPresetListsTheKnownOnes) {
  try {
    load_preset("papr");
    FAIL() << "expected an error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.name(), "preset");
    EXPECT_EQ(e.problem(),
              "unknown preset 'papr' (known: beyond, fig8, obstacles, paper, paper-quick)");
  }
}

TEST(ExperimentConfig, EveryBenchConfigLoadsAndExpands) {
  // docs/sweep-inspect.md, part-tsp.md and results.md quote commands on these configs; an option
  // renamed or removed must fail here, not when a user runs them.
  const std::filesystem::path dir =
      std::filesystem::path(HULLINSPECT_SOURCE_DIR) / "bench" / "configs";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 4u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const ExperimentConfig config = load_config(file);
    const ExperimentPlan plan(config);
    EXPECT_GT(plan.runs().size(), 0u);
    EXPECT_EQ(plan.runs().size() % config.seeds.size(), 0u);
  }
}

TEST(ExperimentConfig, TheTuningConfigOnFiftySeedsHoldsThePaperPresetsMissions) {
  // docs/sweep-inspect.md reports Sweep-Inspect's targets on the `paper` preset's cells and seeds
  // as bench/configs/beyond_tuning_seeds.yaml run with `--instances 50`: every run of the preset
  // (same cell, same seed, hence the same stable id) must be one of its runs.
  const ExperimentPlan paper(load_preset("paper"));
  ExperimentConfig config = load_config(std::filesystem::path(HULLINSPECT_SOURCE_DIR) / "bench" /
                                        "configs" / "beyond_tuning_seeds.yaml");
  set_instance_count(config, 50);
  const ExperimentPlan grid(config);
  std::set<std::string> grid_ids;
  for (const auto& run : grid.runs()) grid_ids.insert(run.id);
  const auto missing = std::count_if(paper.runs().begin(), paper.runs().end(),
                                     [&](const RunKey& run) { return !grid_ids.contains(run.id); });
  EXPECT_EQ(missing, 0);
  // The rest: the preset's 4 scenarios × 4 planners become 8 scenarios (each also with one
  // failure) × 5 planners (Sweep-Inspect added).
  EXPECT_EQ(grid.runs().size(), paper.runs().size() / 16 * 40);
}

}  // namespace
}  // namespace hullinspect::experiment

namespace hullinspect::experiment {
namespace {

TEST(ExperimentConfigLaunch, SitesAndTimesReachEveryMissionAndTheRunIds) {
  const std::string base = "uavs: [2]\ninstances: 1\n";
  const ExperimentPlan paper(parse(base));
  const ExperimentPlan sites(
      parse(base + "launch: {sites: [[0, 0], [229, 29]], transfer: 30, takeoff-time: 4}\n"));
  ASSERT_EQ(sites.runs().size(), 1u);
  const auto spec = sites.mission(sites.runs()[0]);
  EXPECT_EQ(spec.params.launch_sites, (std::vector<grid::Cell>{{0, 0}, {229, 29}}));
  EXPECT_EQ(spec.params.launch_transfer_s, 30);
  EXPECT_EQ(spec.params.takeoff_time_s, 4);
  EXPECT_TRUE(paper.mission(paper.runs()[0]).params.launch_sites.empty());
  // A run with launch sites is another run; without them the run keeps its id.
  EXPECT_NE(sites.runs()[0].id, paper.runs()[0].id);
  EXPECT_FALSE(config_json(paper.config()).contains("launch"));
  const auto back = config_from_json(config_json(sites.config()), "manifest.json");
  EXPECT_EQ(config_json(back), config_json(sites.config()));
  EXPECT_EQ(back.launch_sites, sites.config().launch_sites);
}

}  // namespace
}  // namespace hullinspect::experiment

namespace hullinspect::experiment {
namespace {

// `hull:` takes the names the CLI's --hull takes, never as files beside the config.
TEST(ExperimentConfigHull, NamesAreTheCliHullNames) {
  const auto c = parse("hull: default\n");
  EXPECT_EQ(c.hull->source(), world::default_hull().source());
  EXPECT_EQ(c.hull_cells, world::default_hull().cell_count());
  std::string why;
  if (!hullinspect::testing::installed_dtc(why))
    GTEST_SKIP() << "the DTC is not installed (" << why << ")";
  const auto dtc = parse("hull: dtc\n");
  const world::HullMask cli = world::load_hull("dtc");
  EXPECT_EQ(dtc.hull->source(), "dtc");
  EXPECT_EQ(dtc.hull_width, cli.width());
  EXPECT_EQ(dtc.hull_height, cli.height());
  EXPECT_EQ(dtc.hull_cells, cli.cell_count());
}

TEST(ExperimentConfigHull, AnUnknownNameIsRefusedAsSuch) {
  EXPECT_EQ(error_of("hull: dtx\n"),
            "bad.yaml:1: hull: /cfg/dtx: no such hull file, and not a hull name (default, dtc)");
}

}  // namespace
}  // namespace hullinspect::experiment
