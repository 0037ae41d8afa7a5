#include "hullinspect/experiment/catalog.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/presets.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"
#include "hullinspect/world/scenario.hpp"

namespace hullinspect::experiment {

namespace {

using nlohmann::json;

json options_json(const std::vector<ParamSpec>& specs) {
  json out = json::array();
  for (const auto& s : specs) {
    out.push_back({{"name", s.name},
                   {"type", std::string(param_type_name(s.type))},
                   {"default", s.default_value},
                   {"range", s.range},
                   {"description", s.description}});
  }
  return out;
}

template <class Product>
void add_entries(json& out, const char* kind, const Registry<Product>& registry) {
  for (const auto& e : registry.entries()) {
    out.push_back({{"kind", kind},
                   {"name", e.name},
                   {"description", e.description},
                   {"sees_truth", e.sees_truth},
                   {"options", options_json(e.options)}});
  }
}

void add_presets(json& out) {
  for (const auto& name : preset_names()) {
    std::string description;
    const YAML::Node root = YAML::Load(std::string(preset_text(name)));
    if (root["description"]) description = root["description"].as<std::string>();
    out.push_back({{"kind", "preset"},
                   {"name", name},
                   {"description", description},
                   {"sees_truth", false},
                   {"options", json::array()}});
  }
}

}  // namespace

const std::vector<std::string>& catalog_kinds() {
  static const std::vector<std::string> kinds = {"planners", "partitioners", "tsp-solvers",
                                                 "scenarios", "presets"};
  return kinds;
}

json catalog_json(std::string_view kind) {
  json out = json::array();
  const bool all = kind.empty();
  bool known = all;
  for (const auto& k : catalog_kinds()) known = known || k == kind;
  if (!known) {
    throw ParameterError("kind", fmt::format("unknown kind '{}' (known: {})", kind,
                                             fmt::join(catalog_kinds(), ", ")));
  }
  if (all || kind == "planners") add_entries(out, "planner", planners::planners());
  if (all || kind == "partitioners") add_entries(out, "partitioner", partition::partitioners());
  if (all || kind == "tsp-solvers") add_entries(out, "tsp-solver", tsp::tsp_solvers());
  if (all || kind == "scenarios") add_entries(out, "scenario", world::scenarios());
  if (all || kind == "presets") add_presets(out);
  return out;
}

}  // namespace hullinspect::experiment
