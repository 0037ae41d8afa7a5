// The parameter system: declared options parse, range-check, refuse unknown keys with a hint,
// write back every effective option, and every registry entry's declaration is consistent.

#include <gtest/gtest.h>

#include <set>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/parameters.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"
#include "hullinspect/world/scenario.hpp"

namespace hullinspect {
namespace {

struct Demo {
  int count = 3;
  double rate = 0.25;
  bool fast = false;
  std::string mode = "a";
  OptionMap inner;
};

Params<Demo> demo_params() {
  Params<Demo> p("demo");
  p.integer("count", &Demo::count, 1, 9, "how many")
      .number("rate", &Demo::rate, 0.0, 1.0, "how often")
      .flag("fast", &Demo::fast, "hurry")
      .choice(
          "mode", &Demo::mode,
          [] {
            return std::vector<std::string>{"a", "b"};
          },
          "which")
      .nested(
          "inner", &Demo::inner,
          [](const Demo&, const OptionMap& m) {
            OptionMap out = {{"depth", "1"}};
            for (const auto& [k, v] : m) {
              if (k != "depth") throw_unknown_param("inner", k, {"depth"});
              out[k] = v;
            }
            return out;
          },
          "inner options");
  return p;
}

std::string error_of(const OptionMap& options) {
  try {
    demo_params().read(options);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, DefaultsComeFromTheStructAndAreListed) {
  const auto specs = demo_params().specs();
  ASSERT_EQ(specs.size(), 5u);
  EXPECT_EQ(specs[0].name, "count");
  EXPECT_EQ(specs[0].default_value, "3");
  EXPECT_EQ(specs[0].range, "[1, 9]");
  EXPECT_EQ(specs[1].default_value, "0.25");
  EXPECT_EQ(specs[2].default_value, "false");
  EXPECT_EQ(specs[3].range, "a|b");
  EXPECT_EQ(specs[4].name, "inner.<key>");
  EXPECT_EQ(param_type_name(specs[3].type), "enum");
}

TEST(Parameters, ReadsTypedValuesAndWritesEveryEffectiveOption) {
  const Demo d = demo_params().read(
      {{"count", "7"}, {"rate", "0.5"}, {"fast", "yes"}, {"mode", "b"}, {"inner.depth", "4"}});
  EXPECT_EQ(d.count, 7);
  EXPECT_EQ(d.rate, 0.5);
  EXPECT_TRUE(d.fast);
  EXPECT_EQ(d.mode, "b");
  EXPECT_EQ(d.inner, (OptionMap{{"depth", "4"}}));
  EXPECT_EQ(demo_params().resolve({}), (OptionMap{{"count", "3"},
                                                  {"rate", "0.25"},
                                                  {"fast", "false"},
                                                  {"mode", "a"},
                                                  {"inner.depth", "1"}}));
  // Resolving is idempotent, so recorded options read back to the same options.
  const auto once = demo_params().resolve({{"rate", "0.1"}});
  EXPECT_EQ(demo_params().resolve(once), once);
}

TEST(Parameters, BadValuesAndUnknownKeysNameTheOption) {
  EXPECT_EQ(error_of({{"count", "10"}}), "demo.count: must be an integer in [1, 9] (got '10')");
  EXPECT_EQ(error_of({{"count", "2x"}}), "demo.count: must be an integer in [1, 9] (got '2x')");
  EXPECT_EQ(error_of({{"rate", "nan"}}), "demo.rate: must be a number in [0, 1] (got 'nan')");
  EXPECT_EQ(error_of({{"fast", "maybe"}}), "demo.fast: must be true or false (got 'maybe')");
  EXPECT_EQ(error_of({{"mode", "c"}}), "demo.mode: unknown name 'c' (known: a, b)");
  EXPECT_EQ(error_of({{"cuont", "1"}}),
            "demo.cuont: unknown option (did you mean count?) (known: count, rate, fast, mode, "
            "inner.<key>)");
  EXPECT_EQ(error_of({{"inner.dpth", "1"}}),
            "inner.dpth: unknown option (did you mean depth?) (known: depth)");
}

TEST(Parameters, OldSnakeCaseSpellingsAreRefusedWithAHint) {
  try {
    tsp::make_tsp_solver("exact", {{"time_limit", "1"}});
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()),
              "exact.time_limit: unknown option (did you mean time-limit?) (known: time-limit, "
              "dp-max-segments, kicks, max-segments, work-budget)");
  }
  try {
    planners::make_planner("part-tsp", {{"tsp.dp_max_segments", "12"}});
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean dp-max-segments?"), std::string::npos)
        << e.what();
  }
}

TEST(Parameters, PartitionerOptionsReachPartitionedPlanners) {
  const auto o = planners::resolve_planner_options("lawnmower", {{"partitioner.cc", "0.02"}});
  EXPECT_EQ(o.at("partitioner.cc"), "0.02");
  EXPECT_EQ(o.at("partitioner.iteration-limit"), "2000");
  const auto p = planners::resolve_planner_options("part-tsp", {{"partitioner", "stripes"}});
  EXPECT_FALSE(p.contains("partitioner.cc"));  // stripes has no options
  EXPECT_EQ(p.at("tsp.dp-max-segments"), "8");
  EXPECT_THROW(
      planners::make_planner("part-tsp", {{"partitioner", "stripes"}, {"partitioner.cc", "0.1"}}),
      ParameterError);
}

// Every registered entry: unique kebab-case names, defaults that parse back to themselves.
template <class Product>
void check_registry(const Registry<Product>& registry) {
  for (const auto& entry : registry.entries()) {
    SCOPED_TRACE(entry.name);
    EXPECT_FALSE(entry.description.empty());
    std::set<std::string> names;
    for (const auto& s : entry.options) {
      EXPECT_TRUE(names.insert(s.name).second) << s.name;
      EXPECT_EQ(s.name.find('_'), std::string::npos) << s.name << " is not kebab-case";
      EXPECT_FALSE(s.description.empty()) << s.name;
    }
    const OptionMap defaults = entry.resolve({});
    EXPECT_EQ(entry.resolve(defaults), defaults);
    for (const auto& s : entry.options) {
      if (s.type != ParamType::kNested) {
        EXPECT_EQ(defaults.at(s.name), s.default_value) << s.name;
      }
    }
  }
}

TEST(Parameters, EveryRegistryDeclaresConsistentOptions) {
  check_registry(planners::planners());
  check_registry(partition::partitioners());
  check_registry(tsp::tsp_solvers());
  check_registry(world::scenarios());
}

TEST(Parameters, UnknownNamesSuggestTheClosest) {
  try {
    planners::make_planner("part_tsp");
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()),
              "algorithm: unknown algorithm 'part_tsp' (did you mean part-tsp?) (known: "
              "lawnmower, part-tsp, part-tsp0, coop-frontier, sweep-inspect, oracle-part-tsp)");
  }
}

TEST(Parameters, ScenarioPcSetsBothHalvesUnlessTheFrontIsGiven) {
  const auto inhom = world::scenario("inhomogeneous", {{"p-c", "0.003"}});
  EXPECT_EQ(inhom.p_c, 0.003);
  EXPECT_EQ(inhom.front_p_c, 0.003);
  const auto split = world::scenario("perfect", {{"p-c", "0.003"}, {"front-p-c", "0.01"}});
  EXPECT_EQ(split.front_p_c, 0.01);
  EXPECT_EQ(split.corrosion(100).zones.size(), 2u);
  EXPECT_EQ(world::scenario("imperfect").p_tp, 0.6);
}

}  // namespace
}  // namespace hullinspect
