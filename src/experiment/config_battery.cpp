#include "config_battery.hpp"

namespace hullinspect::experiment::detail {

void read_battery(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c) {
  const YAML::Node node = root["battery"];
  if (!node) return;
  f.expect_map(node, "battery", {"endurance", "reserve", "swap-time"});
  // Errors found when the cells are validated name these lines.
  c.lines["battery"] = YamlFields::line(node);
  for (const char* key : {"endurance", "reserve", "swap-time"}) {
    c.lines[key] = node[key] ? YamlFields::line(node[key]) : YamlFields::line(node);
  }
  if (!node["endurance"]) f.fail(node, "battery.endurance", "expected the seconds of flight");
  c.endurance = f.as_number(node["endurance"], "battery.endurance", 0, 1e7);
  if (node["reserve"]) c.reserve = f.as_number(node["reserve"], "battery.reserve", 0, 1e7);
  if (node["swap-time"]) {
    c.swap_time = f.as_number(node["swap-time"], "battery.swap-time", 0, 1e7);
  }
  if (*c.endurance <= 0) f.fail(node["endurance"], "battery.endurance", "must be above 0 s");
  if (c.reserve && *c.reserve >= *c.endurance) {
    f.fail(node["reserve"], "battery.reserve", "must be below the endurance");
  }
  if (c.launch_sites.empty()) {
    f.fail(node, "battery", "needs a launch site (launch: sites) where the UAVs swap batteries");
  }
}

}  // namespace hullinspect::experiment::detail
