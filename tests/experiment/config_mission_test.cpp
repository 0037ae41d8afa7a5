// The mission options of experiment configs are read through the same declarations as the command
// line and Python (planners/mission_input.hpp): the same values give the same mission, and a
// refused value gives the declaration's message at the key's line.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "experiment_test_support.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/planners/mission_input.hpp"

namespace hullinspect::experiment {
namespace {

ExperimentConfig parse(const std::string& yaml) {
  return parse_config(yaml, "m.yaml", "/cfg");
}

std::string error_of(const std::string& yaml) {
  return testing::config_error(yaml, "m.yaml");
}

TEST(ConfigMissionKeys, TheSameValuesGiveTheMissionTheCommandLineGives) {
  const ExperimentPlan plan(
      parse("instances: 1\ns1: 3\ns2: 9\nuavs: 3\ntheta: 80\nstart_z: 1\ntime_limit: 9000\n"
            "separation: 2\nspeed: 2\nclimb-speed: 0.5\n"
            "launch: {sites: [[0, 0]], transfer: 5, takeoff-time: 3}\n"
            "battery: {endurance: 1800, reserve: 60, swap-time: 30}\n"));
  const world::MissionParams from_config = plan.mission(plan.runs().front()).params;

  planners::MissionInput words;
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"s1", "3"},
                                                        {"s2", "9"},
                                                        {"uavs", "3"},
                                                        {"theta", "80"},
                                                        {"start-z", "1"},
                                                        {"time-limit", "9000"},
                                                        {"separation", "2"},
                                                        {"speed", "2"},
                                                        {"climb-speed", "0.5"},
                                                        {"launch", "0,0"},
                                                        {"launch-transfer", "5"},
                                                        {"takeoff-time", "3"},
                                                        {"endurance", "1800"},
                                                        {"reserve", "60"},
                                                        {"swap-time", "30"}}) {
    planners::set_mission_option(words, key, value);
  }
  const world::MissionParams from_words = planners::build_spec(words, world::default_hull()).params;
  EXPECT_EQ(from_config.s1, from_words.s1);
  EXPECT_EQ(from_config.s2, from_words.s2);
  EXPECT_EQ(from_config.uavs, from_words.uavs);
  EXPECT_EQ(from_config.theta_deg, from_words.theta_deg);
  EXPECT_EQ(from_config.start_z, from_words.start_z);
  EXPECT_EQ(from_config.time_limit, from_words.time_limit);
  EXPECT_EQ(from_config.separation, from_words.separation);
  EXPECT_EQ(from_config.speed_m_s, from_words.speed_m_s);
  EXPECT_EQ(from_config.climb_speed_m_s, from_words.climb_speed_m_s);
  EXPECT_EQ(from_config.launch_sites, from_words.launch_sites);
  EXPECT_EQ(from_config.launch_transfer_s, from_words.launch_transfer_s);
  EXPECT_EQ(from_config.takeoff_time_s, from_words.takeoff_time_s);
  EXPECT_EQ(from_config.endurance_s, from_words.endurance_s);
  EXPECT_EQ(from_config.reserve_s, from_words.reserve_s);
  EXPECT_EQ(from_config.swap_time_s, from_words.swap_time_s);
  EXPECT_EQ(from_config.strict_separation, from_words.strict_separation);
  EXPECT_EQ(from_config.deconflict, from_words.deconflict);
}

TEST(ConfigMissionKeys, EveryDeclaredConfigKeyIsAccepted) {
  // A config map accepts every key a declaration gives it, in its section.
  for (const auto& d : planners::mission_option_declarations()) {
    if (d.config_key.empty()) continue;
    const auto dot = d.config_key.find('.');
    const std::string yaml = dot == std::string::npos
                                 ? d.config_key + ": [nothing]\n"
                                 : d.config_key.substr(0, dot) + ":\n  " +
                                       d.config_key.substr(dot + 1) + ": [nothing]\n";
    const std::string error = error_of(yaml);
    EXPECT_EQ(error.find("unknown key"), std::string::npos) << d.config_key << ": " << error;
    EXPECT_NE(error.find(d.config_key + ": "), std::string::npos) << d.config_key << ": " << error;
  }
}

TEST(ConfigMissionKeys, ARefusedValueHasTheDeclarationsMessageAtItsLine) {
  // The problem is the one `hullinspect run --KEY VALUE` prints; the key is the config's.
  const auto cli_problem = [](const std::string& key, const std::string& value) {
    planners::MissionInput input;
    try {
      planners::set_mission_option(input, key, value);
    } catch (const ParameterError& e) {
      return e.problem();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error_of("instances: 1\ns1: 5.5\n"), "m.yaml:2: s1: " + cli_problem("s1", "5.5"));
  EXPECT_EQ(error_of("start_z: two\n"), "m.yaml:1: start_z: " + cli_problem("start-z", "two"));
  EXPECT_EQ(error_of("s2: [7, nine]\n"), "m.yaml:1: s2: " + cli_problem("s2", "nine"));
  EXPECT_EQ(error_of("launch: {sites: [[0, 0]]}\nbattery:\n  endurance: 600\n  reserve: soon\n"),
            "m.yaml:4: battery.reserve: " + cli_problem("reserve", "soon"));
  EXPECT_EQ(error_of("frame-spacing: 0\n"),
            "m.yaml:1: frame-spacing: " + cli_problem("frame-spacing", "0"));
}

TEST(ConfigMissionKeys, ARangeIsCheckedOnceWithTheMissionNamingTheConfigKeyAndLine) {
  // The same check as `run --start-z 3` or `--endurance 0`, at the line of the key that set it.
  EXPECT_EQ(error_of("instances: 1\nstart_z: 3\n"), "m.yaml:2: start_z: must be 1 or 2 (got 3)");
  EXPECT_EQ(error_of("instances: 1\nlaunch:\n  sites: [[0, 0]]\n  transfer: -5\n"),
            "m.yaml:4: launch.transfer: must be a number of seconds in [0, 20000] (the time "
            "limit) (got -5)");
  const std::string zero = error_of(
      "instances: 1\nlaunch: {sites: [[0, 0]]}\nbattery:\n  swap-time: 10\n  endurance: 0\n");
  EXPECT_EQ(zero.rfind("m.yaml:5: battery.endurance: must be a number of seconds in (0, ", 0), 0u)
      << zero;
}

}  // namespace
}  // namespace hullinspect::experiment
