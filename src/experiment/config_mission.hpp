#pragma once
// The mission options of experiment configs (docs/experiments.md): every declared mission option
// with a config key (planners/mission_input.hpp: "s1", "start_z", "battery.endurance", …) is read
// through its declaration into the config's MissionInput, with the type, default and one-line
// message it has on the command line and in Python. Ranges that depend on other values are
// checked once, when each mission of the experiment is validated, naming the key's line.

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/experiment/config.hpp"
#include "yaml_fields.hpp"

namespace hullinspect::experiment::detail {

/// `known` followed by the declared config keys of `section` ("" = the top level, "battery",
/// "launch") that it does not list, in declaration order: the keys a config map accepts.
std::vector<std::string> with_declared_keys(std::initializer_list<std::string_view> known,
                                            std::string_view section);

/// Reads every declared mission option `root` sets (except the axes, s2 and uavs) into
/// c.mission and records its line in c.lines under its config key. A refused value is
/// "FILE:LINE: KEY: problem" with the declaration's problem.
void read_mission_keys(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c);

/// One value of an axis (an item of `s2:` or `uavs:`) read through the declaration of `key`
/// into `into`; a refused value names `key` and the item's line.
void read_axis_item(const YamlFields& f, const YAML::Node& item, const std::string& key,
                    planners::MissionInput& into);

/// The config key and line of the mission option a validation error names ("endurance" →
/// "battery.endurance"), or `name` itself and its recorded line when no declaration has one.
std::pair<std::string, int> config_key_of(const ExperimentConfig& c, const std::string& name);

}  // namespace hullinspect::experiment::detail
