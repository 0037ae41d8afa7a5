// Every integer option of every command, given a value that is no integer of its range ("x",
// "1.5", "1e3", 10^11), is refused with a message naming the option's own range, never the whole
// range of the C++ type that holds it ([-2147483648, 2147483647]) nor "not a valid value". The
// options are read from each command's --help, so a new option is walked without being listed.

#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

struct ValueOption {
  std::string name;  // the long name, "--uavs"
  std::string type;  // as --help shows it: INT, UINT, N, ...
};

// The options of `command` that take a value, from its --help: a line "  -n,--uavs INT=4  Fleet…"
// names the option, then its type (flags have none).
std::vector<ValueOption> value_options(const std::vector<std::string>& command) {
  auto args = command;
  args.push_back("--help");
  const auto help = run_cli(args);
  EXPECT_EQ(help.status, 0) << help.err;
  std::vector<ValueOption> out;
  std::istringstream lines(help.out);
  const std::regex option_line(R"(^  (-\S+)( (\S+))?(  |$))");
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, option_line) || !m[3].matched) continue;
    std::string names = m[1].str();
    if (names.find("--help") != std::string::npos) continue;
    const auto comma = names.rfind(',');
    if (comma != std::string::npos) names = names.substr(comma + 1);
    std::string type = m[3].str();
    type = type.substr(0, type.find_first_of("=:"));
    out.push_back({names, type});
  }
  return out;
}

// Integer types on the command line: CLI11's own, and the declared integer options' names.
bool is_integer_type(const std::string& type) {
  for (const char* t : {"INT", "UINT", "N", "H", "STEPS", "SEED"}) {
    if (type == t) return true;
  }
  return false;
}

TEST(IntegerOptionRange, EveryIntegerOptionNamesItsOwnRange) {
  const std::vector<std::vector<std::string>> commands = {
      {"run"},    {"plan"}, {"partition"}, {"tsp"},  {"experiment"},     {"merge"},
      {"report"}, {"view"}, {"export"},    {"list"}, {"hull", "import"}, {"trace", "check"}};
  // Part-TSP takes every planner option that has a command-line name (--r1, --partition-seed).
  const std::vector<std::string> planner = {"-a", "part-tsp"};
  const std::regex range(R"(: --[-a-z0-9]+: .*must be an integer in \[(-?\d+), (\d+)\])");
  int walked = 0;
  for (const auto& command : commands) {
    for (const auto& option : value_options(command)) {
      if (!is_integer_type(option.type)) continue;
      for (const std::string value : {"x", "1.5", "1e3", "99999999999999999999999"}) {
        SCOPED_TRACE(command[0] + " " + option.name + " " + value);
        auto args = command;
        if (command[0] == "run" || command[0] == "plan") {
          args.insert(args.end(), planner.begin(), planner.end());
        }
        args.push_back(option.name);
        args.push_back(value);
        const auto r = run_cli(args);
        EXPECT_EQ(r.status, 2);
        std::smatch m;
        if (!std::regex_search(r.err, m, range)) {
          ADD_FAILURE() << "no range in: " << r.err;
          continue;
        }
        EXPECT_EQ(r.err.rfind("hullinspect: " + option.name + ": ", 0), 0u) << r.err;
        // A seed may be any unsigned 64-bit integer; no other option spans a type's range.
        const bool whole_uint64 = m[1] == "0" && m[2] == "18446744073709551615";
        EXPECT_TRUE(option.type == "UINT" || !whole_uint64) << r.err;
        EXPECT_NE(m[1], "-2147483648") << r.err;
      }
      ++walked;
    }
  }
  // run/plan/partition's uavs, s1, s2..., experiment's jobs, instances, report's dpi, export's
  // max-waypoints: the walk must have found them.
  EXPECT_GE(walked, 25);
}

}  // namespace
}  // namespace hullinspect::testing
