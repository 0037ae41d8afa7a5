#include "config_speed.hpp"

namespace hullinspect::experiment::detail {

void read_speed(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c) {
  for (const char* key : {"speed", "climb-speed"}) {
    const YAML::Node node = root[key];
    if (!node) continue;
    c.lines[key] = YamlFields::line(node);
    const double v = f.as_number(node, key, world::kMinSpeedMs, world::kMaxSpeedMs);
    (std::string_view(key) == "speed" ? c.speed : c.climb_speed) = v;
  }
}

}  // namespace hullinspect::experiment::detail
