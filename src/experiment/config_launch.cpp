#include "config_launch.hpp"

#include <fmt/format.h>

#include "config_mission.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/launch_sites.hpp"

namespace hullinspect::experiment::detail {

void read_launch(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c) {
  const YAML::Node node = root["launch"];
  if (!node) return;
  c.lines["launch"] = YamlFields::line(node);
  f.expect_map(node, "launch", with_declared_keys({"sites"}, "launch"));
  const YAML::Node sites = node["sites"];
  if (!sites || !sites.IsSequence() || sites.size() == 0) {
    f.fail(sites ? sites : node, "launch.sites", "expected a list of [x, y] cells");
  }
  world::MissionParams p;
  p.no_fly = c.no_fly;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const std::string key = fmt::format("launch.sites[{}]", i);
    const YAML::Node s = sites[i];
    if (!s.IsSequence() || s.size() != 2) f.fail(s, key, "expected [x, y] in cells");
    p.launch_sites = {{f.as_int(s[0], key, 0, 1 << 20), f.as_int(s[1], key, 0, 1 << 20)}};
    try {
      world::validate_launch_sites(p, *c.hull);
    } catch (const ParameterError& e) {
      f.fail(s, key, e.problem());
    }
    c.launch_sites.push_back(p.launch_sites.front());
  }
  // The times (transfer, takeoff-time) are mission options, read with the others and checked
  // against the time limit when the cells are validated.
}

}  // namespace hullinspect::experiment::detail
