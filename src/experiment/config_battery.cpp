#include "config_battery.hpp"

#include "config_mission.hpp"

namespace hullinspect::experiment::detail {

void read_battery(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c) {
  const YAML::Node node = root["battery"];
  if (!node) return;
  f.expect_map(node, "battery", with_declared_keys({}, "battery"));
  // Its times are mission options, read with the others; an error found when the cells are
  // validated names their lines, or this one.
  c.lines["battery"] = YamlFields::line(node);
  if (!node["endurance"]) f.fail(node, "battery.endurance", "expected the seconds of flight");
  if (c.launch_sites.empty()) {
    f.fail(node, "battery", "needs a launch site (launch: sites) where the UAVs swap batteries");
  }
}

}  // namespace hullinspect::experiment::detail
