// hullinspect tsp: solve one segment-TSP instance file and print the solution as one JSON object.

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/tsp_json.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"
#include "number_options.hpp"

namespace hullinspect::cli {

namespace {

struct TspArgs {
  std::string solver{tsp::kDefaultTspSolver};
  double time_limit = 0;
  std::vector<std::string> options;
  std::string file;
};

int run_tsp(const TspArgs& args) {
  OptionMap options;
  for (const auto& kv : args.options) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw ParameterError("option", fmt::format("expects KEY=VALUE (got '{}')", kv));
    }
    options[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  if (args.time_limit < 0) {
    throw ParameterError("time_limit",
                         fmt::format("must be >= 0 seconds (got {})", args.time_limit));
  }
  if (args.time_limit > 0) options["time-limit"] = fmt::format("{}", args.time_limit);
  std::unique_ptr<tsp::TspSolver> solver;
  try {
    solver = tsp::make_tsp_solver(args.solver, options);
  } catch (const ParameterError& e) {
    // Name the option the user typed: --solver, --time-limit, or --option for the others.
    if (e.name() == "tsp-solver") throw ParameterError("solver", e.problem());
    if (e.name().ends_with(".time-limit")) throw ParameterError("time_limit", e.problem());
    throw ParameterError("option", e.what());
  }
  const tsp::SegmentTsp problem = io::read_tsp_instance(args.file);
  const tsp::TspSolution solution = solver->solve(problem);
  std::cout << io::tsp_solution_json(solution).dump() << "\n";
  return 0;
}

}  // namespace

void add_tsp_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<TspArgs>();
  CLI::App* cmd =
      app.add_subcommand("tsp", "Solve one segment-TSP instance (JSON) and print the tour");
  std::string solvers;
  std::string names;
  for (const auto& info : tsp::tsp_solver_registry()) {
    solvers += fmt::format("  {}: {}\n{}", info.name, info.description,
                           describe_params(info.options, "    "));
    names += (names.empty() ? "" : ", ") + info.name;
  }
  cmd->footer(
      "Solvers and their options (-O KEY=VALUE):\n" + solvers +
      "Instance: {\"start\":[x,y],\"segments\":[[[x1,y1],[x2,y2]], ...]} (docs/tsp.md).\n"
      "Output: {\"length\":L,\"optimal\":bool,\"order\":[{\"segment\":i,\"reversed\":bool}, ...],"
      "\"seconds\":s}\n"
      "Exit status: 0 solved, 2 invalid input, 1 other failure.\n"
      "Example: hullinspect tsp --solver exact --time-limit 5 bench/tsp_instances/g020_00.json");
  cmd->add_option("--solver,-s", args->solver, "TSP solver: " + names)
      ->capture_default_str();
  cmd->add_option("--time-limit", args->time_limit,
                  "Seconds before exact/dfj-iterative return their best tour unproven (0 = none)")
      ->check(real_in(0, 1e9))
      ->capture_default_str();
  cmd->add_option("--option,-O", args->options,
                  "Any other solver option as key=value (repeatable; listed below)");
  cmd->add_option("FILE", args->file, "Instance file (JSON)")->required();
  cmd->callback([args, &action] { action = [args] { return run_tsp(*args); }; });
}

}  // namespace hullinspect::cli
