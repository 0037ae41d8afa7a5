#include "config_scenarios.hpp"

#include <fmt/format.h>

#include <map>
#include <optional>
#include <set>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/scenario.hpp"

namespace hullinspect::experiment::detail {

namespace {

constexpr int kMaxLc = 999;

/// A scenario being built: zones along x plus the prior's rates. "Halves" edits (front_/back_ keys)
/// need the zones to be one zone or model.md §2.s two halves split at a/2.
struct Draft {
  world::CorrosionParams corrosion;
  int width = 0;

  bool halves() const {
    const auto& z = corrosion.zones;
    return z.size() == 1 || (z.size() == 2 && z[0].x_end == width / 2);
  }
  void split() {
    if (corrosion.zones.size() == 1) {
      auto back = corrosion.zones[0];
      auto front = back;
      back.x_end = width / 2;
      front.x_begin = width / 2;
      corrosion.zones = {back, front};
    }
  }
  /// Two equal halves become one zone again, so that a homogeneous scenario has one form.
  void normalise() {
    auto& z = corrosion.zones;
    if (z.size() == 2 && z[0].x_end == width / 2 && z[0].p_c == z[1].p_c && z[0].l_c == z[1].l_c) {
      z = {world::CorrosionZone{0, width, z[0].p_c, z[0].l_c}};
    }
  }
};

std::string builtin_names() {
  std::string names;
  for (const auto& s : world::scenarios().names()) names += (names.empty() ? "" : ", ") + s;
  return names;
}

class ScenarioParser {
 public:
  ScenarioParser(const YamlFields& fields, int width) : f_(fields), width_(width) {}

  void plain(const YAML::Node& node, const std::string& key) {
    if (node.IsScalar()) {
      const std::string name = f_.as_label(node, key);
      Draft d = builtin(node, key, name);
      add(node, key, ScenarioSpec{name, "", "", d.corrosion, {}, YamlFields::line(node), {}, {}},
          d);
      return;
    }
    f_.expect_map(node, key,
                  {"name", "base", "zones", "p_c", "l_c", "back_p_c", "back_l_c", "front_p_c",
                   "front_l_c", "p_tp", "p_fp", "failures", "no-fly"});
    if (!node["name"]) f_.fail(node, key, "a custom scenario needs a 'name'");
    const std::string name = f_.as_label(node["name"], key + ".name");
    Draft d = node["base"] ? base(node["base"], key + ".base") : builtin(node, key, "perfect");
    if (node["zones"]) {
      for (const char* k : {"p_c", "l_c", "back_p_c", "back_l_c", "front_p_c", "front_l_c"}) {
        if (node[k]) f_.fail(node[k], key + "." + k, "cannot be combined with 'zones'");
      }
      d.corrosion.zones = zones(node["zones"], key + ".zones");
    }
    if (node["p_c"]) set_p_c(d, node["p_c"], key + ".p_c", 0, width_);
    if (node["l_c"]) set_l_c(d, node["l_c"], key + ".l_c", 0, width_);
    for (const char* k : {"back_p_c", "back_l_c", "front_p_c", "front_l_c"}) {
      if (!node[k]) continue;
      const std::string path = key + "." + k;
      if (!d.halves()) f_.fail(node[k], path, "needs a base scenario with back/front halves");
      d.split();
      const bool front = k[0] == 'f';
      const int from = front ? width_ / 2 : 0;
      const int to = front ? width_ : width_ / 2;
      if (std::string_view(k).ends_with("p_c")) {
        set_p_c(d, node[k], path, from, to);
      } else {
        set_l_c(d, node[k], path, from, to);
      }
    }
    if (node["p_tp"]) d.corrosion.p_tp = f_.as_number(node["p_tp"], key + ".p_tp", 0, 1);
    if (node["p_fp"]) d.corrosion.p_fp = f_.as_number(node["p_fp"], key + ".p_fp", 0, 1);
    d.normalise();
    ScenarioSpec spec{name, "", "", d.corrosion, {}, YamlFields::line(node), {}, {}};
    if (node["failures"]) spec.failures = failures(node["failures"], key + ".failures");
    add(node, key, std::move(spec), d);
  }

  void sweep(const YAML::Node& node, const std::string& key) {
    f_.expect_map(node, key, {"parameter", "name", "base", "values"});
    if (!node["parameter"]) f_.fail(node, key, "a sweep needs a 'parameter'");
    if (!node["values"]) f_.fail(node, key, "a sweep needs 'values'");
    const std::string parameter = f_.as_string(node["parameter"], key + ".parameter");
    static const std::set<std::string> known = {"p_tp",     "p_fp",      "p_c",
                                                "l_c",      "back_p_c",  "front_p_c",
                                                "back_l_c", "front_l_c", "front_back_p_c"};
    if (!known.contains(parameter)) {
      f_.fail(node["parameter"], key + ".parameter",
              fmt::format("unknown sweep parameter '{}' (known: p_tp, p_fp, p_c, l_c, back_p_c, "
                          "front_p_c, back_l_c, front_l_c, front_back_p_c)",
                          parameter));
    }
    const std::string name = node["name"] ? f_.as_label(node["name"], key + ".name") : parameter;
    const Draft start =
        node["base"] ? base(node["base"], key + ".base") : builtin(node, key, "perfect");
    const auto values = f_.as_list(node["values"], key + ".values");
    for (std::size_t i = 0; i < values.size(); ++i) {
      const YAML::Node& v = values[i];
      const std::string path = fmt::format("{}.values[{}]", key, i);
      Draft d = start;
      std::string text;
      if (parameter == "front_back_p_c") {
        if (!v.IsSequence() || v.size() != 2) {
          f_.fail(v, path, "must be a pair [front p_c, back p_c]");
        }
        if (!d.halves()) f_.fail(v, path, "needs a base scenario with back/front halves");
        d.split();
        set_p_c(d, v[0], path, width_ / 2, width_);
        set_p_c(d, v[1], path, 0, width_ / 2);
        text = fmt::format("{}/{}", v[0].Scalar(), v[1].Scalar());
      } else {
        text = f_.as_string(v, path);
        if (parameter == "p_tp") d.corrosion.p_tp = f_.as_number(v, path, 0, 1);
        if (parameter == "p_fp") d.corrosion.p_fp = f_.as_number(v, path, 0, 1);
        if (parameter == "p_c") set_p_c(d, v, path, 0, width_);
        if (parameter == "l_c") set_l_c(d, v, path, 0, width_);
        if (parameter.starts_with("back_") || parameter.starts_with("front_")) {
          if (!d.halves()) f_.fail(v, path, "needs a base scenario with back/front halves");
          d.split();
          const bool front = parameter[0] == 'f';
          const int from = front ? width_ / 2 : 0;
          const int to = front ? width_ : width_ / 2;
          if (parameter.ends_with("p_c")) {
            set_p_c(d, v, path, from, to);
          } else {
            set_l_c(d, v, path, from, to);
          }
        }
      }
      d.normalise();
      const std::string scenario_name = fmt::format("{}={}", name, text);
      if (auto problem = label_problem(scenario_name); !problem.empty()) f_.fail(v, path, problem);
      add(v, path,
          ScenarioSpec{scenario_name, name, text, d.corrosion, {}, YamlFields::line(v), {}, {}}, d);
    }
  }

  std::vector<ScenarioSpec> take() { return std::move(specs_); }

 private:
  Draft builtin(const YAML::Node& node, const std::string& key, const std::string& name) const {
    if (world::scenarios().contains(name)) {
      return Draft{world::scenario(name).corrosion(width_), width_};
    }
    f_.fail(node, key,
            fmt::format("unknown scenario '{}' (built in: {}; or give a map with 'name' "
                        "and parameters)",
                        name, builtin_names()));
  }

  Draft base(const YAML::Node& node, const std::string& key) const {
    const std::string name = f_.as_string(node, key);
    if (auto it = drafts_.find(name); it != drafts_.end()) return it->second;
    if (world::scenarios().contains(name)) {
      return Draft{world::scenario(name).corrosion(width_), width_};
    }
    f_.fail(node, key,
            fmt::format("unknown base scenario '{}' (built in: {}; or a scenario listed "
                        "earlier under 'scenarios')",
                        name, builtin_names()));
  }

  void set_p_c(Draft& d, const YAML::Node& v, const std::string& key, int from, int to) const {
    const double p = f_.as_number(v, key, 0, 1);
    for (auto& z : d.corrosion.zones) {
      if (z.x_begin >= from && z.x_end <= to) z.p_c = p;
    }
  }

  void set_l_c(Draft& d, const YAML::Node& v, const std::string& key, int from, int to) const {
    const int l = odd(v, key);
    for (auto& z : d.corrosion.zones) {
      if (z.x_begin >= from && z.x_end <= to) z.l_c = l;
    }
  }

  /// failures: {at: [UAV@STEP, …], rate: P, one_within: H} (docs/failures.md).
  world::FailurePlan failures(const YAML::Node& node, const std::string& key) const {
    f_.expect_map(node, key, {"at", "rate", "one_within"});
    world::FailurePlan plan;
    if (node["at"]) {
      const auto items = f_.as_list(node["at"], key + ".at");
      for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string path = fmt::format("{}.at[{}]", key, i);
        try {
          plan.at.push_back(world::parse_uav_failure(f_.as_string(items[i], path)));
        } catch (const ParameterError& e) {
          f_.fail(items[i], path, e.problem());
        }
      }
    }
    if (node["rate"]) plan.rate = f_.as_number(node["rate"], key + ".rate", 0, 1);
    if (node["one_within"]) {
      plan.one_within = f_.as_int(node["one_within"], key + ".one_within", 0, 1 << 30);
    }
    return plan;
  }

  int odd(const YAML::Node& v, const std::string& key) const {
    const int l = f_.as_int(v, key, 1, kMaxLc);
    if (l % 2 == 0) f_.fail(v, key, fmt::format("must be odd (got {})", l));
    return l;
  }

  std::vector<world::CorrosionZone> zones(const YAML::Node& node, const std::string& key) const {
    if (!node.IsSequence() || node.size() == 0) {
      f_.fail(node, key, "must be a non-empty list of zones {x_begin, x_end, p_c, l_c}");
    }
    std::vector<world::CorrosionZone> out;
    int next = 0;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const YAML::Node z = node[i];
      const std::string path = fmt::format("{}[{}]", key, i);
      f_.expect_map(z, path, {"x_begin", "x_end", "p_c", "l_c"});
      for (const char* k : {"x_begin", "x_end", "p_c", "l_c"}) {
        if (!z[k]) f_.fail(z, path, fmt::format("a zone needs '{}'", k));
      }
      world::CorrosionZone zone;
      zone.x_begin = f_.as_int(z["x_begin"], path + ".x_begin", next, next);
      zone.x_end = f_.as_int(z["x_end"], path + ".x_end", zone.x_begin + 1, width_);
      zone.p_c = f_.as_number(z["p_c"], path + ".p_c", 0, 1);
      zone.l_c = odd(z["l_c"], path + ".l_c");
      next = zone.x_end;
      out.push_back(zone);
    }
    if (next != width_) {
      f_.fail(node, key,
              fmt::format("must cover the grid's columns 0 to {} (they end at {})", width_, next));
    }
    return out;
  }

  void add(const YAML::Node& node, const std::string& key, ScenarioSpec spec, const Draft& d) {
    for (const auto& s : specs_) {
      if (s.name == spec.name) {
        f_.fail(node, key, fmt::format("scenario name '{}' is used twice", spec.name));
      }
    }
    if (spec.sweep.empty()) drafts_[spec.name] = d;
    specs_.push_back(std::move(spec));
  }

  const YamlFields& f_;
  int width_;
  std::vector<ScenarioSpec> specs_;
  std::map<std::string, Draft> drafts_;
};

}  // namespace

std::vector<ScenarioSpec> parse_scenarios(const YamlFields& fields, const YAML::Node& scenarios,
                                          const YAML::Node& sweeps, int grid_width) {
  ScenarioParser parser(fields, grid_width);
  if (scenarios) {
    const auto items = fields.as_list(scenarios, "scenarios");
    for (std::size_t i = 0; i < items.size(); ++i) {
      parser.plain(items[i], fmt::format("scenarios[{}]", i));
    }
  }
  if (sweeps) {
    if (!sweeps.IsSequence() || sweeps.size() == 0) {
      fields.fail(sweeps, "sweeps", "must be a non-empty list of sweeps");
    }
    for (std::size_t i = 0; i < sweeps.size(); ++i) {
      parser.sweep(sweeps[i], fmt::format("sweeps[{}]", i));
    }
  }
  auto specs = parser.take();
  if (specs.empty()) {
    specs.push_back(ScenarioSpec{
        "perfect", "", "", world::scenario("perfect").corrosion(grid_width), {}, 0, {}, {}});
  }
  return specs;
}

}  // namespace hullinspect::experiment::detail
