// hullinspect run: one mission, printed as a summary or one JSON object, optionally traced.

#include <fmt/format.h>

#include <iostream>
#include <optional>

#include "commands.hpp"
#include "export_options.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/files/output_set.hpp"
#include "hullinspect/io/result_json.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/io/viewer_html.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/battery.hpp"
#include "hullinspect/world/scenario.hpp"
#include "mission_options.hpp"

namespace hullinspect::cli {

namespace {

struct RunArgs {
  MissionArgs mission;
  bool json = false;
  std::string trace_path;
  std::string html_path;
  ExportArgs output;  // --export DIR --format F (docs/export.md)
};

void print_summary(const planners::MissionSpec& spec, const sim::MissionResult& r) {
  const auto total = r.totals();
  std::cout << fmt::format("{} with {}, s1 = {}, s2 = {}, seed {}: {}\n", spec.algorithm,
                           plural(spec.params.uavs, "UAV"), spec.params.s1, spec.params.s2,
                           spec.seed,
                           r.complete       ? "complete"
                           : r.stopped_idle ? "INCOMPLETE (no working UAV has work left)"
                           : r.failed_uavs == spec.params.uavs ? "INCOMPLETE (every UAV failed)"
                                                               : "INCOMPLETE (time limit reached)");
  if (r.failed_uavs > 0) {
    std::string which;
    for (std::size_t k = 0; k < r.uavs.size(); ++k) {
      if (r.uavs[k].failed_at >= 0) {
        which +=
            fmt::format("{}UAV {} at t = {}", which.empty() ? "" : ", ", k, r.uavs[k].failed_at);
      }
    }
    std::cout << fmt::format("  failed: {}\n", which);
  }
  auto time = [&](const std::optional<int>& t) { return io::seconds_text(spec.params, t); };
  std::cout << fmt::format("  T_c = {}   T_m = {}   ({} corroded of {} hull cells)\n", time(r.t_c),
                           time(r.t_m), r.corroded_cells, r.hull_cells);
  if (r.unreachable_cells > 0 || r.unreachable_z2_cells > 0) {
    std::cout << fmt::format(
        "  no-fly zones: {} hull cells cannot be inspected, {} cannot be seen at all "
        "(docs/model.md: what cannot reach its final state is not counted)\n",
        r.unreachable_cells, r.unreachable_z2_cells);
  }
  if (r.min_battery()) {
    // Batteries (docs/model.md, "Batteries and sorties"), beside the bound they force.
    std::cout << fmt::format(
        "  batteries: {} sorties, {} swaps, {} crashes, least left airborne {} s; lower bound "
        "T_c >= {} s, T_m >= {} s\n",
        r.sorties(), total.swaps, r.battery_crashes,
        world::battery_seconds(spec.params, *r.min_battery()), spec.params.seconds(r.bound_t_c),
        spec.params.seconds(r.bound_t_m));
  }
  if (r.min_separation) {
    std::cout << fmt::format("  separation {}: {} conflicts, smallest separation flown {}\n",
                             spec.params.separation, r.separation_conflicts, *r.min_separation);
  }
  std::cout << fmt::format(
      "  moves {}, plane changes {}, hovers {}, redundant observations {} of {}\n", total.moves,
      total.plane_changes, total.hovers, r.redundant_observations, r.observations);
  std::cout << fmt::format("  planner time {:.2f} ms", r.planner_seconds * 1e3);
  if (r.planner.tsp_solves > 0) {
    std::cout << fmt::format(", {} TSP solves ({:.2f} ms, max {:.3f} ms)", r.planner.tsp_solves,
                             r.planner.tsp_seconds * 1e3, r.planner.tsp_max_seconds * 1e3);
  }
  if (r.planner.replans > 0) std::cout << fmt::format(", {} re-plans", r.planner.replans);
  std::cout << "\n";
}

int run(const RunArgs& args) {
  io::OutputSet outputs;
  if (args.mission.hull != "default") outputs.add_input(args.mission.hull, "hull");
  outputs.add_output(args.trace_path, "trace");
  outputs.add_output(args.html_path, "html");
  ExportArgs output = args.output;
  take_mission_launch(output, args.mission.launch);
  auto export_request = resolve_export(output, "--export");
  if (export_request) declare_export_dir(outputs, *export_request);
  outputs.check();
  const world::HullMask hull = load_mission_hull(args.mission);
  const planners::MissionSpec spec = build_spec(args.mission, hull);
  const auto starts = planners::validate(spec, hull);
  if (export_request) {  // its files are known now: one per UAV
    declare_export_files(outputs, *export_request, spec.params.uavs);
    outputs.check();
  }
  const auto instance = planners::mission_instance(spec, hull);
  const bool tracing = !args.trace_path.empty() || !args.html_path.empty() || export_request;
  std::optional<io::TraceRecorder> recorder;
  planners::MissionOptions options;
  if (tracing) {
    recorder.emplace(instance, io::spec_json(spec, hull.source()));
    options.observers.push_back(&*recorder);
  }
  const sim::MissionResult result = planners::run_mission(spec, hull, instance, starts, options);
  if (tracing) {
    const auto trace = recorder->finish(result);
    if (!args.trace_path.empty()) outputs.write(args.trace_path, trace.dump() + "\n");
    if (!args.html_path.empty()) outputs.write(args.html_path, io::viewer_html(trace));
    if (export_request) take_mission_sorties(*export_request, spec, result);
    if (export_request) write_export(trace, hull.source(), *export_request, outputs);
  }
  if (args.json) {
    std::cout << io::result_json(spec, result).dump() << "\n";
  } else {
    print_summary(spec, result);
  }
  check_stdout();
  outputs.commit();
  return result.complete ? 0 : 3;
}

}  // namespace

void add_run_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate one mission and print its result");
  cmd->footer(
      "Exit status: 0 complete, 3 incomplete (time limit), 2 invalid input, 1 other failure.\n"
      "Example: hullinspect run --algorithm lawnmower --uavs 4 --s2 9 --seed 7 --json");
  add_mission_options(*cmd, args->mission);
  cmd->add_flag("--json", args->json,
                "Print one JSON object (algorithm, uavs, s1, s2, seed, complete, T_c, T_m, moves, "
                "plane_changes, hovers, redundant_observations, planner_seconds, …)");
  cmd->add_option("--trace", args->trace_path,
                  "Write the mission trace (JSON, see docs/formats.md) to FILE")
      ->type_name("FILE");
  cmd->add_option("--html", args->html_path,
                  "Write a self-contained HTML replay of the mission to FILE")
      ->type_name("FILE");
  add_export_options(*cmd, args->output, "--export", false);
  cmd->callback([args, &action] { action = [args] { return run(*args); }; });
}

}  // namespace hullinspect::cli
