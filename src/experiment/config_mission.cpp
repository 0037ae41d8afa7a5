#include "config_mission.hpp"

#include <algorithm>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/mission_input.hpp"

namespace hullinspect::experiment::detail {

namespace {

/// "battery" of "battery.endurance"; "" for a top-level key.
std::string_view section_of(std::string_view config_key) {
  const auto dot = config_key.find('.');
  return dot == std::string_view::npos ? std::string_view() : config_key.substr(0, dot);
}

std::string_view leaf_of(std::string_view config_key) {
  const auto dot = config_key.find('.');
  return dot == std::string_view::npos ? config_key : config_key.substr(dot + 1);
}

/// The node of `config_key` in `root`, or an undefined node (also when its section is not a map:
/// the section's own reader refuses that).
YAML::Node find(const YAML::Node& root, std::string_view config_key) {
  const std::string_view section = section_of(config_key);
  if (section.empty()) return root[std::string(config_key)];
  const YAML::Node parent = root[std::string(section)];
  if (!parent || !parent.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  return parent[std::string(leaf_of(config_key))];
}

const char* shape(const YAML::Node& node) {
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "nothing";
}

/// The library names some parameters with '_' ("start_z"), the declarations with '-'.
std::string dashed(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

}  // namespace

std::vector<std::string> with_declared_keys(std::initializer_list<std::string_view> known,
                                            std::string_view section) {
  std::vector<std::string> out(known.begin(), known.end());
  for (const auto& d : planners::mission_option_declarations()) {
    if (d.config_key.empty() || section_of(d.config_key) != section) continue;
    const std::string leaf(leaf_of(d.config_key));
    if (std::find(out.begin(), out.end(), leaf) == out.end()) out.push_back(leaf);
  }
  return out;
}

void read_mission_keys(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c) {
  for (const auto& d : planners::mission_option_declarations()) {
    if (d.config_key.empty() || d.config_axis) continue;
    const YAML::Node node = find(root, d.config_key);
    if (!node) continue;
    c.lines[d.config_key] = YamlFields::line(node);
    if (!node.IsScalar()) {
      f.fail(node, d.config_key, std::string("must be a single value (got ") + shape(node) + ")");
    }
    try {
      planners::set_mission_option(c.mission, d.key, node.Scalar());
    } catch (const ParameterError& e) {
      f.fail(node, d.config_key, e.problem());
    }
  }
}

void read_axis_item(const YamlFields& f, const YAML::Node& item, const std::string& key,
                    planners::MissionInput& into) {
  if (!item.IsScalar()) {
    f.fail(item, key, std::string("must be a single value (got ") + shape(item) + ")");
  }
  try {
    planners::set_mission_option(into, key, item.Scalar());
  } catch (const ParameterError& e) {
    f.fail(item, key, e.problem());
  }
}

std::pair<std::string, int> config_key_of(const ExperimentConfig& c, const std::string& name) {
  const planners::MissionOptionDecl* d = planners::find_mission_option(dashed(name));
  if (d == nullptr || d->config_key.empty()) return {name, c.line_of(name)};
  int line = c.line_of(d->config_key);
  if (line == 0) line = c.line_of(std::string(section_of(d->config_key)));
  return {d->config_key, line};
}

}  // namespace hullinspect::experiment::detail
