// The mission options of `run` and `plan` are the library's declarations
// (planners/mission_input.hpp): every declared option is on the command line with its shown
// default, and a value a declaration refuses is the CLI's parse error word for word — the message
// the Python module shows too.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/mission_input.hpp"
#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

// The --help line that declares `--key`: its first word is the option's names ("-n,--uavs"), one of
// them --key.
std::string help_line(const std::string& help, const std::string& key) {
  std::istringstream lines(help);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string names;
    words >> names;
    std::istringstream parts(names);
    for (std::string part; std::getline(parts, part, ',');) {
      if (part == "--" + key) return line;
    }
  }
  return "";
}

TEST(MissionDeclarations, EveryDeclaredOptionIsOnTheRunAndPlanCommandLines) {
  for (const char* command : {"run", "plan"}) {
    const auto help = run_cli({command, "--help"});
    ASSERT_EQ(help.status, 0) << help.err;
    for (const auto& d : planners::mission_option_declarations()) {
      SCOPED_TRACE(std::string(command) + " --" + d.key);
      const std::string line = help_line(help.out, d.key);
      ASSERT_NE(line, "") << help.out;
      if (d.kind != planners::InputKind::kFlag) {
        EXPECT_NE(line.find(d.value_name), std::string::npos) << line;
      }
      if (!d.shown_default.empty()) {
        EXPECT_NE(line.find(d.value_name + "=" + d.shown_default), std::string::npos) << line;
      }
      if (!d.alias.empty()) {
        EXPECT_NE(line.find("-" + d.alias + ","), std::string::npos) << line;
      }
    }
  }
}

TEST(MissionDeclarations, PartitionSharesTheFleetHullStartAndFootprintDeclarations) {
  const auto help = run_cli({"partition", "--help"});
  ASSERT_EQ(help.status, 0) << help.err;
  for (const char* key : {"uavs", "hull", "start", "s1", "s2"}) {
    SCOPED_TRACE(std::string("partition --") + key);
    const planners::MissionOptionDecl* d = planners::find_mission_option(key);
    ASSERT_NE(d, nullptr);
    const std::string line = help_line(help.out, key);
    ASSERT_NE(line, "") << help.out;
    EXPECT_NE(line.find(d->value_name), std::string::npos) << line;
    // The declaration's own help, not a text of the command's.
    EXPECT_NE(help.out.find(d->help.substr(0, 30)), std::string::npos) << help.out;
  }
}

TEST(MissionDeclarations, ARefusedValueIsTheCommandLinesParseError) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"uavs", "abc"},        {"s2", "1.5"},         {"seed", "-1"},
      {"theta", "nan"},       {"fail-rate", "x"},    {"fail-one-within", "abc"},
      {"frame-spacing", "0"}, {"cell-size", "1e400"}};
  for (const auto& [key, value] : bad) {
    SCOPED_TRACE(key + " " + value);
    planners::MissionInput input;
    std::string problem;
    try {
      planners::set_mission_option(input, key, value);
      ADD_FAILURE() << "accepted";
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.name(), key);
      problem = e.problem();
    }
    const auto r = run_cli({"run", "--" + key, value});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "hullinspect: --" + key + ": " + problem + " (see --help)\n");
  }
}

TEST(MissionDeclarations, DefaultsAreTheSpecsAndKeysAreKnown) {
  const planners::MissionInput input;
  const planners::MissionSpec spec;
  EXPECT_EQ(input.algorithm, spec.algorithm);
  EXPECT_EQ(input.seed, spec.seed);
  EXPECT_EQ(input.s2, spec.params.s2);
  EXPECT_EQ(input.uavs, spec.params.uavs);
  ASSERT_NE(planners::find_mission_option("sides"), nullptr);  // --side's other spelling
  EXPECT_EQ(planners::find_mission_option("sides")->key, "side");
  planners::MissionInput given;
  planners::set_mission_option(given, "include", "transom,transom");  // split at ','
  EXPECT_EQ(given.mesh.include, (std::vector<std::string>{"transom", "transom"}));
  try {
    planners::set_mission_option(given, "time_limit", "9");
    ADD_FAILURE() << "accepted an unknown key";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean time-limit?"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hullinspect::testing
