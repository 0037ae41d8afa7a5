// hullinspect list: what can be chosen by name, with every declared option, default and range.

#include <fmt/format.h>

#include <iostream>

#include "commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/catalog.hpp"
#include "hullinspect/experiment/presets.hpp"

namespace hullinspect::cli {

namespace {

struct ListArgs {
  std::string kind;
  bool json = false;
  std::string show;
};

void print_text(const nlohmann::json& entries) {
  std::string kind;
  for (const auto& e : entries) {
    if (e["kind"] != kind) {
      kind = e["kind"].get<std::string>();
      std::cout << (kind == "tsp-solver" ? "TSP solvers" : kind + "s") << ":\n";
    }
    std::cout << fmt::format("  {}{}: {}\n", e["name"].get<std::string>(),
                             e["sees_truth"].get<bool>() ? " (sees the truth)" : "",
                             e["description"].get<std::string>());
    for (const auto& o : e["options"]) {
      const std::string type = o["type"];
      std::string detail = type;
      if (type != "options") detail += ", default " + o["default"].get<std::string>();
      if (type != "bool" && !o["range"].get<std::string>().empty()) {
        detail += ", " + o["range"].get<std::string>();
      }
      std::cout << fmt::format("      {} ({}): {}\n", o["name"].get<std::string>(), detail,
                               o["description"].get<std::string>());
    }
  }
}

int run_list(const ListArgs& args) {
  if (!args.show.empty()) {
    if (args.kind != "presets") {
      throw ParameterError("show", "applies only to `hullinspect list presets`");
    }
    std::cout << experiment::preset_text(args.show);
    return 0;
  }
  const auto entries = experiment::catalog_json(args.kind);
  if (args.json) {
    std::cout << entries.dump(2) << "\n";
  } else {
    print_text(entries);
  }
  return 0;
}

}  // namespace

void add_list_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<ListArgs>();
  CLI::App* cmd = app.add_subcommand(
      "list", "List planners, partitioners, TSP solvers, scenarios or presets with their options");
  cmd->footer(
      "Examples: hullinspect list planners\n"
      "          hullinspect list tsp-solvers --json\n"
      "          hullinspect list presets --show paper-quick");
  cmd->add_option("KIND", args->kind,
                  "planners, partitioners, tsp-solvers, scenarios or presets "
                  "(default: all)")
      ->check(CLI::IsMember({"planners", "partitioners", "tsp-solvers", "scenarios", "presets"}));
  cmd->add_flag("--json", args->json,
                "Print a JSON array of {kind, name, description, sees_truth, options: [{name, "
                "type, default, range, description}]}");
  cmd->add_option("--show", args->show, "With `presets`: print the named preset's YAML")
      ->type_name("NAME");
  cmd->callback([args, &action] { action = [args] { return run_list(*args); }; });
}

}  // namespace hullinspect::cli
