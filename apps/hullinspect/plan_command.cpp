// hullinspect plan: the mission as planned before take-off. The planner flies a world whose truth
// is the prior (the only corrosion known before take-off), so the result is the plan it would fly
// if the prior were right, with its expected T_c and T_m (docs/export.md).

#include <fmt/format.h>

#include <iostream>
#include <optional>

#include "commands.hpp"
#include "export_options.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/output_set.hpp"
#include "hullinspect/io/result_json.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "mission_options.hpp"

namespace hullinspect::cli {

namespace {

struct PlanArgs {
  MissionArgs mission;
  bool json = false;
  std::string trace_path;
  ExportArgs output;
};

int plan(const PlanArgs& args) {
  io::OutputSet outputs;
  if (args.mission.hull != "default") outputs.add_input(args.mission.hull, "hull");
  outputs.add_output(args.trace_path, "trace");
  const auto export_request = resolve_export(args.output, "--export");
  if (export_request) declare_export_dir(outputs, *export_request);
  outputs.check();
  const world::HullMask hull = load_mission_hull(args.mission);
  const planners::MissionSpec spec = build_spec(args.mission, hull);
  planners::validate(spec, hull);
  if (export_request) {  // its files are known now: one per UAV
    declare_export_files(outputs, *export_request, spec.params.uavs);
    outputs.check();
  }
  auto instance = world::generate_instance(hull, spec.corrosion, spec.seed);
  world::apply(spec.maps, instance);  // the user's --prior, if given
  instance.truth = instance.prior;    // the world as known before take-off
  auto planner = planners::make_planner(spec.algorithm, spec.planner_options);
  io::TraceRecorder recorder(instance, io::spec_json(spec, hull.source()));
  planners::MissionOptions options;
  options.observers.push_back(&recorder);
  options.corrosion = planners::prior_statistics(spec);
  const sim::MissionResult result =
      planners::run_mission(hull, instance, spec.params, *planner, options);
  const auto trace = recorder.finish(result);
  if (!args.trace_path.empty()) outputs.write(args.trace_path, trace.dump() + "\n");
  std::vector<std::string> written;
  if (export_request) written = write_export(trace, *export_request, outputs);
  outputs.commit();
  if (args.json) {
    auto j = io::result_json(spec, result);
    j["planned_on"] = "prior";
    std::cout << j.dump() << "\n";
    return result.complete ? 0 : 3;
  }
  auto time = [](const std::optional<int>& t) {
    return t ? fmt::format("{} s", *t) : std::string("—");
  };
  const auto total = result.totals();
  std::cout << fmt::format("{} with {}, s1 = {}, s2 = {}, seed {}: planned on the prior{}\n",
                           spec.algorithm, plural(spec.params.uavs, "UAV"), spec.params.s1,
                           spec.params.s2, spec.seed,
                           result.complete ? "" : " — INCOMPLETE (time limit reached)");
  std::cout << fmt::format(
      "  expected T_c = {}   T_m = {}   ({} prior-corroded of {} hull cells)\n", time(result.t_c),
      time(result.t_m), result.corroded_cells, result.hull_cells);
  std::cout << fmt::format("  moves {}, plane changes {}, hovers {}\n", total.moves,
                           total.plane_changes, total.hovers);
  if (export_request) {
    std::cout << fmt::format("  wrote {} {} file{} to {}\n", written.size(), args.output.format,
                             written.size() == 1 ? "" : "s", export_request->dir.string());
  }
  return result.complete ? 0 : 3;
}

}  // namespace

void add_plan_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<PlanArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plan",
      "The mission as planned before take-off (truth = prior): expected T_c/T_m, waypoints");
  cmd->footer(
      "An online planner changes this plan in flight as it senses (docs/export.md).\n"
      "Exit status: 0 complete, 3 incomplete (time limit), 2 invalid input, 1 other failure.\n"
      "Example: hullinspect plan -a part-tsp -n 4 --export plans --format csv");
  add_mission_options(*cmd, args->mission);
  cmd->add_flag("--json", args->json,
                "Print one JSON object (as `run --json`, plus planned_on: prior)");
  cmd->add_option("--trace", args->trace_path, "Write the planned mission's trace (JSON) to FILE")
      ->type_name("FILE");
  add_export_options(*cmd, args->output, "--export");
  cmd->callback([args, &action] { action = [args] { return plan(*args); }; });
}

}  // namespace hullinspect::cli
