// `hullinspect list`: every registry entry with its declared options, as text and JSON.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hullinspect/experiment/presets.hpp"
#include "hullinspect/planners/planner.hpp"
#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

TEST(ListCommand, JsonListsEveryPlannerWithItsDeclaredOptions) {
  const auto r = run_cli({"list", "planners", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto entries = nlohmann::json::parse(r.out);
  // The built-in planners, then the user planners of examples/planners/ linked into the CLI.
  std::vector<std::string> names;
  for (const auto& e : entries) names.push_back(e["name"].get<std::string>());
  std::vector<std::string> expected;
  for (const auto& p : planners::planner_registry()) expected.push_back(p.name);
  expected.push_back("nearest-first");
  EXPECT_EQ(names, expected);
  const auto& part_tsp = entries.at(1);
  EXPECT_EQ(part_tsp["kind"], "planner");
  EXPECT_EQ(part_tsp["name"], "part-tsp");
  EXPECT_EQ(part_tsp["sees_truth"], false);
  const auto& r1 = part_tsp["options"].at(0);
  EXPECT_EQ(r1,
            (nlohmann::json{{"name", "r1"},
                            {"type", "int"},
                            {"default", "2"},
                            {"range", "[0, 1048576]"},
                            {"description", "steps since the last detection before descending"}}));
  EXPECT_EQ(part_tsp["options"].at(2)["range"], "exact|dfj-iterative|cbc-cut|heuristic");
}

TEST(ListCommand, EveryKindIsListed) {
  const auto r = run_cli({"list", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::set<std::string> kinds;
  for (const auto& e : nlohmann::json::parse(r.out)) kinds.insert(e["kind"].get<std::string>());
  EXPECT_EQ(kinds,
            (std::set<std::string>{"planner", "partitioner", "tsp-solver", "scenario", "preset"}));
  const auto text = run_cli({"list", "scenarios"});
  EXPECT_NE(text.out.find("  imperfect: homogeneous corrosion, prior with false negatives and "
                          "positives\n      p-c (double, default 0.005, [0, 1]): "),
            std::string::npos)
      << text.out;
}

TEST(ListCommand, ShowsAPresetsYaml) {
  const auto r = run_cli({"list", "presets", "--show", "paper-quick"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, std::string(experiment::preset_text("paper-quick")));
  const auto bad = run_cli({"list", "presets", "--show", "nope"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err.rfind("hullinspect: --preset: unknown preset 'nope' (known: ", 0), 0u)
      << bad.err;
}

}  // namespace
}  // namespace hullinspect::testing
