// A config's YAML spellings of the non-finite reals (.nan, .inf, -.inf, any letter case) are
// refused with the message the command line's nan, inf and -inf get: the option's range, never
// "not a valid value".

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"

namespace hullinspect::experiment {
namespace {

/// The one-line error of the experiment `yaml` describes (parsed, then its missions validated),
/// or "" when it is accepted.
std::string refusal(const std::string& yaml) {
  try {
    ExperimentPlan plan(parse_config(yaml, "c.yaml", "/cfg"));
    return "";
  } catch (const Error& e) {
    return e.what();
  }
}

// Each config holds one real option whose range the mission's validation checks; {} is its value.
const std::vector<std::string> kConfigs = {
    "speed: {}\n",
    "climb-speed: {}\n",
    "launch: {{sites: [[0, 0]], transfer: {}}}\n",
    "launch: {{sites: [[0, 0]], takeoff-time: {}}}\n",
    "launch: {{sites: [[0, 0]]}}\nbattery: {{endurance: {}}}\n",
    "launch: {{sites: [[0, 0]]}}\nbattery: {{endurance: 100000, reserve: {}}}\n",
    "launch: {{sites: [[0, 0]]}}\nbattery: {{endurance: 100000, swap-time: {}}}\n",
};

// A YAML spelling and the C literal the command line reads for the same value.
const std::vector<std::pair<std::string, std::string>> kSpellings = {
    {".nan", "nan"}, {".NaN", "nan"},   {".inf", "inf"},   {"+.inf", "inf"},
    {".Inf", "inf"}, {"-.inf", "-inf"}, {"-.INF", "-inf"},
};

TEST(ExperimentConfigNonFinite, YamlSpellingsGetTheCommandLinesRangeMessage) {
  const std::string base = "uavs: [2]\ninstances: 1\n";
  for (const std::string& config : kConfigs) {
    for (const auto& [yaml, literal] : kSpellings) {
      SCOPED_TRACE(fmt::format(fmt::runtime(config), yaml));
      const std::string message = refusal(base + fmt::format(fmt::runtime(config), yaml));
      EXPECT_EQ(message, refusal(base + fmt::format(fmt::runtime(config), literal)));
      EXPECT_NE(message.find("must be"), std::string::npos) << message;
      EXPECT_EQ(message.find("must be a number (got"), std::string::npos) << message;
    }
  }
}

TEST(ExperimentConfigNonFinite, TextThatIsNoNumberIsStillRefusedAsSuch) {
  // Only the exact YAML spellings are numbers: ".nanx" and "..inf" stay text.
  for (const std::string bad : {".nanx", "..inf", ".in", "nan."}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(refusal("speed: " + bad + "\n"),
              fmt::format("c.yaml:1: speed: must be a number (got '{}')", bad));
  }
}

}  // namespace
}  // namespace hullinspect::experiment
