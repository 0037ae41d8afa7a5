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

void read_no_fly(const YamlFields& f, const YAML::Node& root, const std::filesystem::path& base_dir,
                 ExperimentConfig& c) {
  const YAML::Node node = root["no-fly"];
  if (!node) return;
  f.expect_map(node, "no-fly", {"file", "boxes-m"});
  c.lines["no-fly"] = YamlFields::line(node);
  std::filesystem::path file;
  nlohmann::json spec = nlohmann::json::object();
  if (node["file"]) {
    const std::string text = f.as_string(node["file"], "no-fly.file");
    if (text.empty()) f.fail(node["file"], "no-fly.file", "must name a mask file");
    file = std::filesystem::path(text);
    if (file.is_relative()) file = base_dir / file;
    spec["file"] = text;
  }
  std::vector<world::CellBox> boxes;
  if (const auto list = node["boxes-m"]) {
    if (!list.IsSequence()) {
      f.fail(list, "no-fly.boxes-m", "expected a list of [x0, y0, x1, y1] boxes in metres");
    }
    nlohmann::json boxes_json = nlohmann::json::array();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string key = fmt::format("no-fly.boxes-m[{}]", i);
      const YAML::Node b = list[i];
      if (!b.IsSequence() || b.size() != 4) f.fail(b, key, "expected [x0, y0, x1, y1] in metres");
      double v[4];
      for (std::size_t k = 0; k < 4; ++k) v[k] = f.as_number(b[k], key, 0, 1e9);
      if (v[2] < v[0] || v[3] < v[1]) f.fail(b, key, "needs x0 <= x1 and y0 <= y1");
      const auto [x0, x1] = cell_span(v[0], v[2], c.cell_size);
      const auto [y0, y1] = cell_span(v[1], v[3], c.cell_size);
      if (x1 >= c.hull->width() || y1 >= c.hull->height()) {
        f.fail(b, key,
               fmt::format("reaches cell ({}, {}), outside the {} × {} grid of {} m cells", x1, y1,
                           c.hull->width(), c.hull->height(), c.cell_size));
      }
      boxes.push_back({x0, y0, x1, y1});
      boxes_json.push_back({v[0], v[1], v[2], v[3]});
    }
    spec["boxes-m"] = std::move(boxes_json);
  }
  try {
    c.no_fly =
        std::make_shared<const world::NoFlyMask>(world::make_no_fly_mask(*c.hull, file, boxes));
  } catch (const Error& e) {
    f.fail(node, "no-fly", e.what());
  }
  std::string cells;
  for (auto v : c.no_fly->values()) cells += static_cast<char>('0' + v);
  spec["hash"] = stable_id(cells);
  c.no_fly_spec = std::move(spec);
}

}  // namespace hullinspect::experiment::detail
