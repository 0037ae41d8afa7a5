#include "config_no_fly.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/hash.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::experiment::detail {

namespace {

// The cells a box in metres touches: [floor(lo / cell), ceil(hi / cell) − 1], at least one cell.
std::pair<int, int> cell_span(double lo, double hi, double cell) {
  const int first = static_cast<int>(std::floor(lo / cell + 1e-9));
  const int last = std::max(first, static_cast<int>(std::ceil(hi / cell - 1e-9)) - 1);
  return {first, last};
}

}  // namespace

NoFlyZones read_no_fly_zones(const YamlFields& f, const YAML::Node& node, const std::string& key,
                             const std::filesystem::path& base_dir, const ExperimentConfig& c) {
  f.expect_map(node, key, {"file", "boxes-m"});
  std::filesystem::path file;
  nlohmann::json spec = nlohmann::json::object();
  if (node["file"]) {
    const std::string text = f.as_string(node["file"], key + ".file");
    if (text.empty()) f.fail(node["file"], key + ".file", "must name a mask file");
    file = std::filesystem::path(text);
    if (file.is_relative()) file = base_dir / file;
    spec["file"] = text;
  }
  std::vector<world::CellBox> boxes;
  if (const auto list = node["boxes-m"]) {
    if (!list.IsSequence()) {
      f.fail(list, key + ".boxes-m", "expected a list of [x0, y0, x1, y1] boxes in metres");
    }
    nlohmann::json boxes_json = nlohmann::json::array();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string box_key = fmt::format("{}.boxes-m[{}]", key, i);
      const YAML::Node b = list[i];
      if (!b.IsSequence() || b.size() != 4) {
        f.fail(b, box_key, "expected [x0, y0, x1, y1] in metres");
      }
      double v[4];
      for (std::size_t k = 0; k < 4; ++k) v[k] = f.as_number(b[k], box_key, 0, 1e9);
      if (v[2] < v[0] || v[3] < v[1]) f.fail(b, box_key, "needs x0 <= x1 and y0 <= y1");
      const auto [x0, x1] = cell_span(v[0], v[2], c.cell_size);
      const auto [y0, y1] = cell_span(v[1], v[3], c.cell_size);
      if (x1 >= c.hull->width() || y1 >= c.hull->height()) {
        f.fail(b, box_key,
               fmt::format("reaches cell ({}, {}), outside the {} × {} grid of {} m cells", x1, y1,
                           c.hull->width(), c.hull->height(), c.cell_size));
      }
      boxes.push_back({x0, y0, x1, y1});
      boxes_json.push_back({v[0], v[1], v[2], v[3]});
    }
    spec["boxes-m"] = std::move(boxes_json);
  }
  NoFlyZones zones;
  try {
    zones.mask =
        std::make_shared<const world::NoFlyMask>(world::make_no_fly_mask(*c.hull, file, boxes));
  } catch (const Error& e) {
    f.fail(node, key, e.what());
  }
  std::string cells;
  for (auto v : zones.mask->values()) cells += static_cast<char>('0' + v);
  spec["hash"] = stable_id(cells);
  zones.spec = std::move(spec);
  return zones;
}

void read_no_fly(const YamlFields& f, const YAML::Node& root, const std::filesystem::path& base_dir,
                 ExperimentConfig& c) {
  const YAML::Node node = root["no-fly"];
  if (!node) return;
  c.lines["no-fly"] = YamlFields::line(node);
  NoFlyZones zones = read_no_fly_zones(f, node, "no-fly", base_dir, c);
  c.no_fly = std::move(zones.mask);
  c.no_fly_spec = std::move(zones.spec);
}

void read_scenario_no_fly(const YamlFields& f, const YAML::Node& scenarios,
                          const std::filesystem::path& base_dir, ExperimentConfig& c) {
  if (!scenarios || !scenarios.IsSequence()) return;
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const YAML::Node item = scenarios[i];
    if (!item.IsMap() || !item["no-fly"]) continue;
    const std::string key = fmt::format("scenarios[{}].no-fly", i);
    if (c.no_fly) {
      f.fail(item["no-fly"], key,
             "cannot be combined with the top-level 'no-fly' (give the zones in one place)");
    }
    NoFlyZones zones = read_no_fly_zones(f, item["no-fly"], key, base_dir, c);
    ScenarioSpec& spec = c.scenarios.at(i);  // plain scenarios come first, one per item
    spec.no_fly = std::move(zones.mask);
    spec.no_fly_spec = std::move(zones.spec);
  }
}

}  // namespace hullinspect::experiment::detail
