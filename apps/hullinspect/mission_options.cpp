#include "mission_options.hpp"

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/parameters.hpp"
#include "hullinspect/planners/planner.hpp"
#include "number_options.hpp"

namespace hullinspect::cli {

namespace {

std::vector<const planners::MissionOptionDecl*> declarations_where(
    const std::function<bool(const planners::MissionOptionDecl&)>& keep) {
  std::vector<const planners::MissionOptionDecl*> out;
  for (const auto& d : planners::mission_option_declarations()) {
    if (keep(d)) out.push_back(&d);
  }
  return out;
}

}  // namespace

std::vector<const planners::MissionOptionDecl*> declarations_named(
    std::initializer_list<std::string_view> keys) {
  std::vector<const planners::MissionOptionDecl*> out;
  for (const std::string_view key : keys) {
    const planners::MissionOptionDecl* d = planners::find_mission_option(key);
    if (d == nullptr) throw LogicError(fmt::format("no mission option '{}' is declared", key));
    out.push_back(d);
  }
  return out;
}

void add_declared_options(CLI::App& cmd, MissionArgs& input,
                          const std::vector<const planners::MissionOptionDecl*>& decls) {
  for (const planners::MissionOptionDecl* d : decls) {
    std::string names = "--" + d->key;
    if (!d->also.empty()) names += ",--" + d->also;
    if (!d->alias.empty()) names += ",-" + d->alias;
    CLI::Option* option = nullptr;
    if (d->kind == planners::InputKind::kFlag) {
      option = cmd.add_flag_callback(
          names, [d, &input] { planners::set_mission_option(input, d->key, "true"); }, d->help);
    } else {
      // Read each value through the declaration; its ParameterError becomes CLI11's parse error
      // for the option, which main() prints as "--KEY: problem (see --help)".
      auto read = [d, &input](const std::vector<std::string>& values) {
        for (const auto& v : values) {
          try {
            planners::set_mission_option(input, d->key, v);
          } catch (const ParameterError& e) {
            throw CLI::ValidationError("--" + d->key, e.problem());
          }
        }
      };
      option = d->kind == planners::InputKind::kRepeated
                   ? cmd.add_option_function<std::vector<std::string>>(names, read, d->help)
                   : cmd.add_option_function<std::string>(
                         names, [read](const std::string& v) { read({v}); }, d->help);
      option->type_name(d->value_name);
      // The declaration parses its value within the option's own range: the generic INT/FLOAT
      // check of require_exact_numbers() (which names the type's whole range) stays off it.
      option->check(declared_value_marker());
      if (!d->shown_default.empty()) option->default_str(d->shown_default);
    }
    if (!d->group.empty()) option->group(d->group);
  }
  for (const planners::MissionOptionDecl* d : decls) {
    if (d->excludes.empty()) continue;
    CLI::Option* other = cmd.get_option_no_throw("--" + d->excludes);
    if (other != nullptr) cmd.get_option("--" + d->key)->excludes(other);
  }
}

void add_mission_options(CLI::App& cmd, MissionArgs& a) {
  std::string planner_help;
  for (const auto& info : planners::planner_registry()) {
    planner_help += fmt::format("  {}: {}\n{}", info.name, info.description,
                                describe_params(info.options, "    "));
  }
  add_declared_options(cmd, a, declarations_where([](const auto&) { return true; }));
  cmd.footer("Planners and their options (-O KEY=VALUE):\n" + planner_help);
}

void add_mesh_options(CLI::App& cmd, MissionArgs& a) {
  add_declared_options(cmd, a, planners::mesh_option_declarations());
}

void add_no_fly_options(CLI::App& cmd, MissionArgs& a) {
  add_declared_options(cmd, a, declarations_where([](const planners::MissionOptionDecl& d) {
                         return d.key == "no-fly" || d.key == "no-fly-box";
                       }));
}

}  // namespace hullinspect::cli
