#include "hullinspect/experiment/config.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <set>

#include "config_battery.hpp"
#include "config_launch.hpp"
#include "config_mission.hpp"
#include "config_no_fly.hpp"
#include "config_scenarios.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/hash.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/defect_map.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "yaml_fields.hpp"

namespace hullinspect::experiment {

namespace {

using detail::YamlFields;

constexpr int kMaxInstances = 1000000;
constexpr int kMaxCurvePoints = 100000;

std::shared_ptr<const world::HullMask> rectangle(int width, int height) {
  grid::Grid<std::uint8_t> mask(width, height, 1);
  return std::make_shared<const world::HullMask>(std::move(mask),
                                                 fmt::format("rectangle {}x{}", width, height));
}

std::filesystem::path resolved(const std::string& path, const std::filesystem::path& base_dir) {
  std::filesystem::path p(path);
  return p.is_relative() ? base_dir / p : p;
}

/// `hull: {mesh: FILE, side: …, cell-size: …, scale: …, axes: …, waterline: …, min-coverage: …,
/// keep-largest: …}` (docs/hulls.md): the mesh imported with those options.
void read_mesh_hull(const YamlFields& f, const YAML::Node& h, const std::filesystem::path& base_dir,
                    ExperimentConfig& c) {
  f.expect_map(
      h, "hull",
      {"mesh", "side", "cell-size", "scale", "axes", "waterline", "min-coverage", "keep-largest"});
  if (!h["mesh"]) f.fail(h, "hull", "a hull map needs 'mesh' (a mesh file or dtc)");
  const std::string mesh = f.as_string(h["mesh"], "hull.mesh");
  const bool named = world::is_named_mesh_hull(mesh);
  if (!named && !world::is_mesh_path(mesh)) {
    f.fail(h["mesh"], "hull.mesh",
           "expected a mesh file (.stl, .obj, .ply, optionally .gz) or dtc");
  }
  // A named hull starts from its own options; the keys given override them.
  world::MeshImportOptions o = named ? world::dtc_options() : world::MeshImportOptions{};
  try {
    if (h["side"]) o.side = world::parse_hull_side(f.as_string(h["side"], "hull.side"));
    if (h["axes"]) o.axes = world::AxisMap::parse(f.as_string(h["axes"], "hull.axes"));
  } catch (const ParameterError& e) {
    f.fail(h[e.name()], "hull." + e.name(), e.problem());
  }
  if (h["cell-size"]) o.cell_size = f.as_number(h["cell-size"], "hull.cell-size", 1e-6, 1e6);
  if (h["scale"]) o.scale = f.as_number(h["scale"], "hull.scale", 1e-12, 1e12);
  if (h["waterline"]) o.waterline = f.as_number(h["waterline"], "hull.waterline", -1e9, 1e9);
  if (h["min-coverage"]) {
    o.min_coverage = f.as_number(h["min-coverage"], "hull.min-coverage", 1e-9, 1);
  }
  if (h["keep-largest"]) {
    const std::string v = f.as_string(h["keep-largest"], "hull.keep-largest");
    if (v != "true" && v != "false") {
      f.fail(h["keep-largest"], "hull.keep-largest", "expected true or false");
    }
    o.keep_largest = v == "true";
  }
  c.hull_spec = fmt::format(
      "mesh:{} side={} cell-size={} scale={} axes={} waterline={} min-coverage={} "
      "keep-largest={}",
      mesh, world::to_string(o.side), o.cell_size, o.scale, o.axes.to_string(),
      o.waterline ? fmt::format("{}", *o.waterline) : std::string("none"), o.min_coverage,
      o.keep_largest);
  try {
    world::HullMask hull = named ? world::import_named_mesh_hull(mesh, o).hull
                                 : world::import_mesh_file(resolved(mesh, base_dir), o).hull;
    // The geometry records the mesh as the config names it, not as found from the directory the
    // command ran in, so that the hull's hash (and the fingerprint and run ids) do not depend on
    // how the config's path was spelled (k3.yaml, ./k3.yaml, /abs/k3.yaml).
    world::HullGeometry geometry = *hull.geometry();
    geometry.mesh = mesh;
    hull.attach_geometry(std::move(geometry));
    c.hull = std::make_shared<const world::HullMask>(std::move(hull));
  } catch (const InputError& e) {
    f.fail(h["mesh"], "hull.mesh", e.what());
  }
}

// The stable id of a map's cells (-1 not hull, 0 clean, 1 corroded), row by row.
std::string map_hash(const world::CorrosionMap& map) {
  std::string cells;
  for (const auto v : map.cells.values()) cells += static_cast<char>('1' + v);
  return stable_id(cells);
}

void read_user_maps(const YamlFields& f, const YAML::Node& root,
                    const std::filesystem::path& base_dir, ExperimentConfig& c) {
  // Each file is recorded as the config names it and found from the config's directory, so that
  // the fingerprint does not depend on how the config's own path was spelled.
  const auto name = [&](const char* key) {
    return root[key] ? f.as_string(root[key], key) : std::string();
  };
  const auto path = [&](const std::string& named) {
    return named.empty() ? named : resolved(named, base_dir).string();
  };
  c.prior_path = name("prior");
  c.truth_path = name("truth");
  try {
    c.maps.prior = world::load_user_maps(path(c.prior_path), "", *c.hull).prior;
  } catch (const InputError& e) {
    f.fail(root["prior"], "prior", e.what());
  }
  try {
    c.maps.truth = world::load_user_maps("", path(c.truth_path), *c.hull).truth;
  } catch (const InputError& e) {
    f.fail(root["truth"], "truth", e.what());
  }
  c.prior_defects_path = name("prior-defects");
  c.truth_defects_path = name("truth-defects");
  world::FrameSpacing frames;  // frame-spacing: read with the mission options
  frames.frame_spacing_m = c.mission.frame_spacing;
  const auto defects = [&](const char* key, const char* mask_key, const std::string& file,
                           std::shared_ptr<const world::CorrosionMap>& map) {
    if (file.empty()) return;
    if (root[mask_key]) {
      f.fail(root[key], key, fmt::format("give either {} or {}, not both", mask_key, key));
    }
    try {
      map = std::make_shared<const world::CorrosionMap>(
          world::load_defect_map(path(file), *c.hull, frames));
    } catch (const InputError& e) {
      f.fail(root[key], key, e.what());
    }
  };
  defects("prior-defects", "prior", c.prior_defects_path, c.maps.prior);
  defects("truth-defects", "truth", c.truth_defects_path, c.maps.truth);
  // The maps' contents identify the experiment, so a file changed under the same name is another.
  if (c.maps.prior) c.prior_hash = map_hash(*c.maps.prior);
  if (c.maps.truth) c.truth_hash = map_hash(*c.maps.truth);
}

/// `prior:` replaces the generated C′ and `truth:` the generated C (docs/model.md): a scenario or
/// sweep parameter that only shapes a replaced map would label runs with a value that had no
/// effect.
void refuse_replaced_parameters(const YamlFields& f, const YAML::Node& root) {
  const bool prior = static_cast<bool>(root["prior"]);
  const bool truth = static_cast<bool>(root["truth"]);
  const auto replaced_by = [&](std::string_view key) -> std::string_view {
    if (prior && (key == "p_tp" || key == "p_fp")) return "prior";
    const bool corrosion = key == "zones" || key.ends_with("p_c") || key.ends_with("l_c");
    if (truth && corrosion) return "truth";
    return {};
  };
  const auto fail = [&](const YAML::Node& node, const std::string& key, std::string_view map) {
    f.fail(node, key,
           fmt::format("has no effect with '{}:' (the {} file replaces the map it would shape); "
                       "remove one of them",
                       map, map));
  };
  if (!prior && !truth) return;
  if (const auto scenarios = root["scenarios"]; scenarios && scenarios.IsSequence()) {
    for (std::size_t i = 0; i < scenarios.size(); ++i) {
      if (!scenarios[i].IsMap()) continue;
      for (const auto& entry : scenarios[i]) {
        const auto key = entry.first.as<std::string>();
        if (const auto map = replaced_by(key); !map.empty()) {
          fail(entry.second, fmt::format("scenarios[{}].{}", i, key), map);
        }
      }
    }
  }
  if (const auto sweeps = root["sweeps"]; sweeps && sweeps.IsSequence()) {
    for (std::size_t i = 0; i < sweeps.size(); ++i) {
      const auto parameter = sweeps[i].IsMap() ? sweeps[i]["parameter"] : YAML::Node();
      if (!parameter || !parameter.IsScalar()) continue;
      if (const auto map = replaced_by(parameter.Scalar()); !map.empty()) {
        fail(parameter, fmt::format("sweeps[{}].parameter", i), map);
      }
    }
  }
}

void read_hull(const YamlFields& f, const YAML::Node& root, const std::filesystem::path& base_dir,
               ExperimentConfig& c) {
  int width = 0;
  int height = 0;
  if (const auto g = root["grid"]) {
    f.expect_map(g, "grid", {"width", "height", "cell_size"});
    if (g["width"]) width = f.as_int(g["width"], "grid.width", 1, world::kMaxGridSide);
    if (g["height"]) height = f.as_int(g["height"], "grid.height", 1, world::kMaxGridSide);
    if (g["cell_size"]) c.cell_size = f.as_number(g["cell_size"], "grid.cell_size", 1e-6, 1e6);
    c.lines["grid.width"] = g["width"] ? YamlFields::line(g["width"]) : YamlFields::line(g);
    c.lines["grid.height"] = g["height"] ? YamlFields::line(g["height"]) : YamlFields::line(g);
  }
  const YAML::Node h = root["hull"];
  const int hull_line = h ? YamlFields::line(h) : 0;
  if (h && h.IsMap()) {
    // A mesh hull's grid and cell size come from the mesh: a grid: key would be ignored.
    for (const char* key : {"width", "height", "cell_size"}) {
      if (const auto g = root["grid"]; g && g[key]) {
        f.fail(g[key], std::string("grid.") + key,
               "cannot be set for a mesh hull (its grid comes from the mesh; set hull.cell-size "
               "instead)");
      }
    }
    read_mesh_hull(f, h, base_dir, c);
  } else if (h) {
    c.hull_spec = f.as_string(h, "hull");
  }
  if (c.hull) {
    // A mesh hull map, loaded above.
  } else if (c.hull_spec == "rectangle") {
    if (width == 0 || height == 0) {
      f.fail_at(hull_line, "hull", "'rectangle' needs grid.width and grid.height");
    }
    c.hull = rectangle(width, height);
  } else {
    try {
      // The names the CLI's --hull takes (default, dtc) are names, not files beside the config.
      std::filesystem::path path(c.hull_spec);
      if (!world::is_hull_name(c.hull_spec) && path.is_relative()) path = base_dir / path;
      c.hull = std::make_shared<const world::HullMask>(world::load_hull(path));
    } catch (const InputError& e) {
      f.fail_at(hull_line, "hull", e.what());
    }
    if (width != 0 && width != c.hull->width()) {
      f.fail_at(c.lines["grid.width"], "grid.width",
                fmt::format("is {} but the hull mask is {} wide", width, c.hull->width()));
    }
    if (height != 0 && height != c.hull->height()) {
      f.fail_at(c.lines["grid.height"], "grid.height",
                fmt::format("is {} but the hull mask is {} high", height, c.hull->height()));
    }
  }
  // A hull with geometry is identified by its geometry too; plain masks keep their old ids.
  c.hull_hash =
      stable_id(c.hull->geometry() ? world::to_hull_json(*c.hull) : world::to_text_mask(*c.hull));
  if (const auto g = root["grid"];
      c.hull->geometry() && g && g["cell_size"] && c.cell_size != c.hull->geometry()->cell_size) {
    f.fail(g["cell_size"], "grid.cell_size",
           fmt::format("is {} but the hull's geometry has cells of {} m", c.cell_size,
                       c.hull->geometry()->cell_size));
  }
  if (c.hull->geometry()) c.cell_size = c.hull->geometry()->cell_size;
  c.hull_width = c.hull->width();
  c.hull_height = c.hull->height();
  c.hull_cells = c.hull->cell_count();
}

/// An axis of the grid (`s2:`, `uavs:`): a value or a list of distinct values, each read through
/// the mission option's declaration; their ranges are checked when the cells are validated.
std::vector<int> axis(const YamlFields& f, const YAML::Node& node, const std::string& key,
                      int planners::MissionInput::*field, ExperimentConfig& c) {
  std::vector<int> values;
  const auto items = f.as_list(node, key);
  for (std::size_t i = 0; i < items.size(); ++i) {
    planners::MissionInput item;
    detail::read_axis_item(f, items[i], key, item);
    const int v = item.*field;
    if (std::find(values.begin(), values.end(), v) != values.end()) {
      f.fail(items[i], key, fmt::format("lists {} twice", v));
    }
    c.lines[fmt::format("{}[{}]", key, i)] = YamlFields::line(items[i]);
    values.push_back(v);
  }
  return values;
}

std::vector<AlgorithmSpec> read_algorithms(const YamlFields& f, const YAML::Node& node) {
  std::vector<AlgorithmSpec> out;
  const auto items = f.as_list(node, "algorithms");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const YAML::Node& a = items[i];
    const std::string key = fmt::format("algorithms[{}]", i);
    AlgorithmSpec spec;
    spec.line = YamlFields::line(a);
    if (a.IsScalar()) {
      spec.planner = f.as_label(a, key);
    } else {
      f.expect_map(a, key, {"name", "label", "options"});
      if (!a["name"]) f.fail(a, key, "an algorithm entry needs a 'name' (the planner)");
      spec.planner = f.as_label(a["name"], key + ".name");
      if (a["label"]) spec.label = f.as_label(a["label"], key + ".label");
      if (const auto o = a["options"]) {
        if (!o.IsMap()) f.fail(o, key + ".options", "must be a map of option: value");
        for (const auto& entry : o) {
          const std::string name = f.as_string(entry.first, key + ".options");
          const std::string path = fmt::format("{}.options.{}", key, name);
          if (!entry.second.IsScalar()) f.fail(entry.second, path, "must be a single value");
          if (spec.options.contains(name)) f.fail(entry.first, path, "appears twice");
          spec.options[name] = entry.second.Scalar();
        }
      }
    }
    if (spec.label.empty()) spec.label = spec.planner;
    for (const auto& other : out) {
      if (other.label == spec.label) {
        f.fail(
            a, key,
            fmt::format("label '{}' is used twice (give each entry its own 'label')", spec.label));
      }
    }
    out.push_back(std::move(spec));
  }
  return out;
}

void read_instances(const YamlFields& f, const YAML::Node& root, ExperimentConfig& c) {
  const YAML::Node n = root["instances"];
  const YAML::Node first = root["first_seed"];
  if (n && n.IsSequence()) {
    if (first) f.fail(first, "first_seed", "applies only when 'instances' is a count");
    std::set<std::uint64_t> seen;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const std::uint64_t seed = f.as_seed(n[i], "instances");
      if (!seen.insert(seed).second)
        f.fail(n[i], "instances", fmt::format("lists seed {} twice", seed));
      c.seeds.push_back(seed);
    }
    if (c.seeds.empty()) f.fail(n, "instances", "must not be an empty list");
    return;
  }
  const int count = n ? f.as_int(n, "instances", 1, kMaxInstances) : 50;
  const std::uint64_t start = first ? f.as_seed(first, "first_seed") : 1;
  if (start > UINT64_MAX - static_cast<std::uint64_t>(count)) {
    f.fail(first, "first_seed", "leaves no room for the instance seeds below 2^64");
  }
  for (int i = 0; i < count; ++i) c.seeds.push_back(start + static_cast<std::uint64_t>(i));
}

void remember_line(ExperimentConfig& c, const YAML::Node& root, const char* key) {
  if (root[key]) c.lines[key] = YamlFields::line(root[key]);
}

}  // namespace

std::vector<int> CurveGrid::times() const {
  std::vector<int> t;
  for (int v = 0; v <= end; v += step) t.push_back(v);
  return t;
}

world::MissionParams ExperimentConfig::timing() const {
  world::MissionParams p;
  p.cell_size_m = cell_size;
  p.speed_m_s = mission.speed;
  p.climb_speed_m_s = mission.climb_speed;
  return p;
}

int ExperimentConfig::line_of(const std::string& key) const {
  auto it = lines.find(key);
  return it == lines.end() ? 0 : it->second;
}

ExperimentConfig parse_config(std::string_view yaml, const std::string& source,
                              const std::filesystem::path& base_dir) {
  YamlFields f(source);
  YAML::Node root;
  try {
    root = YAML::Load(std::string(yaml));
  } catch (const YAML::Exception& e) {
    throw InputError(source, e.mark.line >= 0 ? e.mark.line + 1 : 0,
                     fmt::format("invalid YAML: {}", e.msg));
  }
  ExperimentConfig c;
  c.source = source;
  c.name = std::filesystem::path(source).stem().string();
  if (!root || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  // The mission options among these keys are also declared (planners/mission_input.cpp): a key
  // declared there and missing here is accepted after them.
  f.expect_map(root, "",
               detail::with_declared_keys(
                   {"name",          "description", "hull",      "grid",          "scenarios",
                    "sweeps",        "s1",          "s2",        "theta",         "uavs",
                    "start_z",       "algorithms",  "instances", "first_seed",    "time_limit",
                    "curve",         "prior",       "truth",     "prior-defects", "truth-defects",
                    "frame-spacing", "no-fly",      "launch",    "separation",    "speed",
                    "climb-speed",   "battery"},
                   ""));
  for (const char* key : {"s2", "uavs", "hull"}) remember_line(c, root, key);
  if (root["name"]) c.name = f.as_label(root["name"], "name");
  if (root["description"]) c.description = f.as_string(root["description"], "description");
  detail::read_mission_keys(f, root, c);
  refuse_replaced_parameters(f, root);
  read_hull(f, root, base_dir, c);
  detail::read_no_fly(f, root, base_dir, c);
  read_user_maps(f, root, base_dir, c);
  c.scenarios = detail::parse_scenarios(f, root["scenarios"], root["sweeps"], c.hull->width());
  detail::read_scenario_no_fly(f, root["scenarios"], base_dir, c);
  if (root["s2"]) c.s2 = axis(f, root["s2"], "s2", &planners::MissionInput::s2, c);
  if (root["uavs"]) c.uavs = axis(f, root["uavs"], "uavs", &planners::MissionInput::uavs, c);
  detail::read_launch(f, root, c);
  detail::read_battery(f, root, c);
  if (root["algorithms"]) {
    c.algorithms = read_algorithms(f, root["algorithms"]);
  } else {
    const std::string algorithm = planners::MissionSpec{}.algorithm;  // the one default planner
    c.algorithms = {AlgorithmSpec{algorithm, algorithm, {}, 0}};
  }
  read_instances(f, root, c);
  if (const auto curve = root["curve"]) {
    f.expect_map(curve, "curve", {"step", "end"});
    if (curve["step"]) c.curve.step = f.as_int(curve["step"], "curve.step", 1, 1000000000);
    if (curve["end"]) c.curve.end = f.as_int(curve["end"], "curve.end", 0, 1000000000);
    if (c.curve.end / c.curve.step + 1 > kMaxCurvePoints) {
      f.fail(curve, "curve",
             fmt::format("gives {} sample times; at most {} are accepted",
                         c.curve.end / c.curve.step + 1, kMaxCurvePoints));
    }
  }
  return c;
}

// An experiment config larger than this is refused before it is read whole.
constexpr std::size_t kMaxConfigBytes = std::size_t{16} << 20;

ExperimentConfig load_config(const std::filesystem::path& path) {
  const std::string text = io::read_file(path, kMaxConfigBytes);
  return parse_config(text, path.string(), path.parent_path());
}

void restrict_algorithms(ExperimentConfig& config, const std::vector<std::string>& labels) {
  std::vector<AlgorithmSpec> kept;
  for (const auto& label : labels) {
    auto it = std::find_if(config.algorithms.begin(), config.algorithms.end(),
                           [&](const AlgorithmSpec& a) { return a.label == label; });
    if (it == config.algorithms.end()) {
      std::string names;
      for (const auto& a : config.algorithms) names += (names.empty() ? "" : ", ") + a.label;
      throw ParameterError("algorithms",
                           fmt::format("'{}' is not in the config (it has: {})", label, names));
    }
  }
  for (const auto& a : config.algorithms) {
    if (std::find(labels.begin(), labels.end(), a.label) != labels.end()) kept.push_back(a);
  }
  config.algorithms = std::move(kept);
}

void set_instance_count(ExperimentConfig& config, int count) {
  if (count < 1) {
    throw ParameterError("instances", fmt::format("must be at least 1 (got {})", count));
  }
  config.seeds.clear();
  for (int i = 1; i <= count; ++i) config.seeds.push_back(static_cast<std::uint64_t>(i));
}

void set_first_seed(ExperimentConfig& config, std::uint64_t first) {
  const std::size_t count = config.seeds.size();
  if (count > 0 && first > UINT64_MAX - (count - 1)) {
    throw ParameterError(
        "first-seed",
        fmt::format("leaves no room for {} instance seeds below 2^64 (got {})", count, first));
  }
  for (std::size_t i = 0; i < count; ++i) config.seeds[i] = first + i;
}

nlohmann::json config_json(const ExperimentConfig& c) {
  using nlohmann::json;
  json j;
  j["name"] = c.name;
  j["description"] = c.description;
  j["hull"] = {{"spec", c.hull_spec},
               {"width", c.hull_width},
               {"height", c.hull_height},
               {"cells", c.hull_cells},
               {"hash", c.hull_hash}};
  j["cell_size"] = c.cell_size;
  if (!c.no_fly_spec.is_null()) j["no_fly"] = c.no_fly_spec;  // absent without: ids unchanged
  // Only when given, so configs without user maps keep their fingerprints.
  if (!c.prior_path.empty()) j["prior"] = c.prior_path;
  if (!c.truth_path.empty()) j["truth"] = c.truth_path;
  if (!c.prior_defects_path.empty()) j["prior_defects"] = c.prior_defects_path;
  if (!c.truth_defects_path.empty()) j["truth_defects"] = c.truth_defects_path;
  if (!c.prior_hash.empty()) j["prior_hash"] = c.prior_hash;
  if (!c.truth_hash.empty()) j["truth_hash"] = c.truth_hash;
  if (c.mission.frame_spacing) j["frame_spacing"] = *c.mission.frame_spacing;
  json scenarios = json::array();
  for (const auto& s : c.scenarios) {
    json zones = json::array();
    for (const auto& z : s.corrosion.zones) {
      zones.push_back({{"x_begin", z.x_begin}, {"x_end", z.x_end}, {"p_c", z.p_c}, {"l_c", z.l_c}});
    }
    json scenario = {{"name", s.name}, {"sweep", s.sweep},         {"sweep_value", s.sweep_value},
                     {"zones", zones}, {"p_tp", s.corrosion.p_tp}, {"p_fp", s.corrosion.p_fp}};
    if (!s.failures.empty()) {
      json at = json::array();
      for (const auto& f : s.failures.at) at.push_back({f.uav, f.time});
      scenario["failures"] = {
          {"at", at}, {"rate", s.failures.rate}, {"one_within", s.failures.one_within}};
    }
    if (!s.no_fly_spec.is_null()) scenario["no_fly"] = s.no_fly_spec;  // only when given
    scenarios.push_back(std::move(scenario));
  }
  j["scenarios"] = scenarios;
  j["s1"] = c.mission.s1;
  j["s2"] = c.s2;
  j["theta"] = c.mission.theta;
  j["uavs"] = c.uavs;
  j["start_z"] = c.mission.start_z;
  if (c.mission.separation > 0)
    j["separation"] = c.mission.separation;  // only when given: manifests unchanged
  json algorithms = json::array();
  for (const auto& a : c.algorithms) {
    algorithms.push_back({{"label", a.label}, {"planner", a.planner}, {"options", a.options}});
  }
  j["algorithms"] = algorithms;
  j["seeds"] = c.seeds;
  j["time_limit"] = c.mission.time_limit;
  if (!c.launch_sites.empty()) {  // only then, so that every other manifest keeps its bytes
    json sites = json::array();
    for (const auto& s : c.launch_sites) sites.push_back({s.x, s.y});
    j["launch"] = {{"sites", sites}, {"transfer", c.mission.launch_transfer}};
    if (c.mission.takeoff_time) j["launch"]["takeoff_time"] = *c.mission.takeoff_time;
  }
  if (c.mission.endurance) {  // only then, so that every other manifest keeps its bytes
    j["battery"] = {{"endurance", *c.mission.endurance}, {"swap_time", c.mission.swap_time}};
    if (c.mission.reserve) j["battery"]["reserve"] = *c.mission.reserve;
  }
  if (c.mission.speed) j["speed"] = *c.mission.speed;  // only when given: manifests unchanged
  if (c.mission.climb_speed) j["climb_speed"] = *c.mission.climb_speed;
  j["curve"] = {{"step", c.curve.step}, {"end", c.curve.end}};
  return j;
}

ExperimentConfig config_from_json(const nlohmann::json& j, const std::string& source) {
  try {
    ExperimentConfig c;
    c.source = source;
    c.name = j.at("name").get<std::string>();
    c.description = j.at("description").get<std::string>();
    const auto& h = j.at("hull");
    c.hull_spec = h.at("spec").get<std::string>();
    c.hull_width = h.at("width").get<int>();
    c.hull_height = h.at("height").get<int>();
    c.hull_cells = h.at("cells").get<int>();
    c.hull_hash = h.at("hash").get<std::string>();
    c.cell_size = j.at("cell_size").get<double>();
    if (j.contains("no_fly")) c.no_fly_spec = j.at("no_fly");
    if (j.contains("prior")) c.prior_path = j.at("prior").get<std::string>();
    if (j.contains("truth")) c.truth_path = j.at("truth").get<std::string>();
    if (j.contains("prior_defects"))
      c.prior_defects_path = j.at("prior_defects").get<std::string>();
    if (j.contains("truth_defects"))
      c.truth_defects_path = j.at("truth_defects").get<std::string>();
    if (j.contains("prior_hash")) c.prior_hash = j.at("prior_hash").get<std::string>();
    if (j.contains("truth_hash")) c.truth_hash = j.at("truth_hash").get<std::string>();
    if (j.contains("frame_spacing")) c.mission.frame_spacing = j.at("frame_spacing").get<double>();
    for (const auto& s : j.at("scenarios")) {
      ScenarioSpec spec;
      spec.name = s.at("name").get<std::string>();
      spec.sweep = s.at("sweep").get<std::string>();
      spec.sweep_value = s.at("sweep_value").get<std::string>();
      for (const auto& z : s.at("zones")) {
        spec.corrosion.zones.push_back({z.at("x_begin").get<int>(), z.at("x_end").get<int>(),
                                        z.at("p_c").get<double>(), z.at("l_c").get<int>()});
      }
      spec.corrosion.p_tp = s.at("p_tp").get<double>();
      spec.corrosion.p_fp = s.at("p_fp").get<double>();
      if (s.contains("failures")) {
        const auto& f = s.at("failures");
        for (const auto& a : f.at("at"))
          spec.failures.at.push_back({a.at(0).get<int>(), a.at(1).get<int>()});
        spec.failures.rate = f.at("rate").get<double>();
        spec.failures.one_within = f.at("one_within").get<int>();
      }
      if (s.contains("no_fly")) spec.no_fly_spec = s.at("no_fly");
      c.scenarios.push_back(std::move(spec));
    }
    c.mission.s1 = j.at("s1").get<int>();
    c.s2 = j.at("s2").get<std::vector<int>>();
    c.mission.theta = j.at("theta").get<double>();
    c.uavs = j.at("uavs").get<std::vector<int>>();
    c.mission.start_z = j.at("start_z").get<int>();
    if (j.contains("separation")) c.mission.separation = j.at("separation").get<int>();
    for (const auto& a : j.at("algorithms")) {
      c.algorithms.push_back({a.at("label").get<std::string>(), a.at("planner").get<std::string>(),
                              a.at("options").get<OptionMap>(), 0});
    }
    c.seeds = j.at("seeds").get<std::vector<std::uint64_t>>();
    c.mission.time_limit = j.at("time_limit").get<int>();
    if (j.contains("launch")) {
      const auto& l = j.at("launch");
      for (const auto& s : l.at("sites"))
        c.launch_sites.push_back({s.at(0).get<int>(), s.at(1).get<int>()});
      c.mission.launch_transfer = l.at("transfer").get<double>();
      if (l.contains("takeoff_time")) c.mission.takeoff_time = l.at("takeoff_time").get<double>();
    }
    if (j.contains("battery")) {
      const auto& b = j.at("battery");
      c.mission.endurance = b.at("endurance").get<double>();
      c.mission.swap_time = b.at("swap_time").get<double>();
      if (b.contains("reserve")) c.mission.reserve = b.at("reserve").get<double>();
    }
    if (j.contains("speed")) c.mission.speed = j.at("speed").get<double>();
    if (j.contains("climb_speed")) c.mission.climb_speed = j.at("climb_speed").get<double>();
    c.curve.step = j.at("curve").at("step").get<int>();
    c.curve.end = j.at("curve").at("end").get<int>();
    if (c.curve.step < 1) throw InputError(source, 0, "config.curve.step must be at least 1");
    return c;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source, 0, fmt::format("the recorded config is malformed: {}", e.what()));
  }
}

std::string config_fingerprint(const ExperimentConfig& config) {
  auto j = config_json(config);
  // The name and description do not change any result.
  j.erase("name");
  j.erase("description");
  return stable_id(j.dump());
}

}  // namespace hullinspect::experiment
