// hullinspect plan: the mission as planned before take-off. The planner flies a world whose truth
// is the prior (the only corrosion known before take-off), so the result is the plan it would fly
// if the prior were right, with its expected T_c and T_m (docs/export.md). The prior is the
// user's --prior; without one it is empty (pure coverage) unless a synthetic scenario is asked
// for by name (--scenario or its parameters).

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "export_options.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/output_set.hpp"
#include "hullinspect/io/preflight_report.hpp"
#include "hullinspect/io/result_json.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/battery.hpp"
#include "mission_options.hpp"

namespace hullinspect::cli {

namespace {

struct PlanArgs {
  MissionArgs mission;
  bool json = false;
  std::string trace_path;
  ExportArgs output;
  std::string report_dir;  // --report DIR: the pre-flight report of the export
  bool synthetic = false;  // --scenario or a scenario parameter was given
};

// The options that ask for a synthetic corrosion scenario.
constexpr std::array<const char*, 7> kScenarioOptions = {
    "--scenario", "--p-c", "--p-tp", "--p-fp", "--front-p-c", "--l-c", "--front-l-c"};

// What the prior of the plan is, for its summary line.
std::string prior_source(const PlanArgs& args) {
  if (!args.mission.prior.empty()) return "the prior " + args.mission.prior;
  if (args.synthetic) return "a synthetic prior (scenario " + args.mission.scenario + ")";
  return "an empty prior (pure coverage: no corrosion expected)";
}

// The batteries and sorties of the planned mission, for the pre-flight report's margins.
io::PreflightBattery planned_battery(const planners::MissionSpec& spec,
                                     const sim::MissionResult& result) {
  io::PreflightBattery battery;
  const auto steps = world::battery_steps(spec.params);
  if (!steps.limited) return battery;
  battery.limited = true;
  battery.endurance_s = world::battery_seconds(spec.params, steps.endurance);
  battery.reserve_s = world::battery_seconds(spec.params, steps.reserve);
  battery.plan_end_s = world::battery_seconds(spec.params, result.steps);
  for (const auto& u : result.uavs) {
    auto& sorties = battery.sorties.emplace_back();
    for (const auto& s : u.sorties) {
      sorties.push_back({world::battery_seconds(spec.params, s.takeoff),
                         s.landing >= 0
                             ? std::optional<double>(world::battery_seconds(spec.params, s.landing))
                             : std::nullopt,
                         s.site});
    }
  }
  return battery;
}

int plan(const PlanArgs& args) {
  io::OutputSet outputs;
  if (args.mission.hull != "default") outputs.add_input(args.mission.hull, "hull");
  outputs.add_output(args.trace_path, "trace");
  ExportArgs output = args.output;
  take_mission_launch(output, args.mission.launch);
  const auto export_request = resolve_export(output, "--export");
  if (export_request) declare_export_dir(outputs, *export_request);
  const std::filesystem::path report_dir = args.report_dir;
  if (!args.report_dir.empty()) {
    if (!export_request)
      throw ParameterError("report", "needs --export DIR (it reports the export)");
    outputs.add_output_dir(report_dir, "report");
    for (const char* name : {"preflight.md", "preflight.json", "preflight.svg"}) {
      outputs.add_output(report_dir / name, "report");
    }
  }
  outputs.check();
  const world::HullMask hull = load_mission_hull(args.mission);
  const planners::MissionSpec spec = build_spec(args.mission, hull);
  planners::validate(spec, hull);
  if (export_request) {  // its files are known now: one per UAV
    declare_export_files(outputs, *export_request, spec.params.uavs);
    outputs.check();
  }
  auto instance = planners::mission_instance(spec, hull);  // the user's --prior, if given
  if (args.mission.prior.empty() && !args.synthetic) {
    // No corrosion is known before take-off: clean hull cells, never a random map.
    for (int y = 0; y < instance.prior.height(); ++y) {
      for (int x = 0; x < instance.prior.width(); ++x) {
        if (instance.prior(x, y) > 0) instance.prior(x, y) = 0;
      }
    }
    instance.prior_true_positive_centres = 0;
    instance.prior_false_positive_centres = 0;
  }
  instance.truth = instance.prior;  // the world as known before take-off
  io::TraceRecorder recorder(instance, io::spec_json(spec, hull.source()));
  planners::MissionOptions options;
  options.observers.push_back(&recorder);
  planners::MissionSpec planned = spec;
  planned.failures = {};  // a plan is the flight without failures: none is known before take-off
  const sim::MissionResult result = planners::run_mission(planned, hull, instance, options);
  const auto trace = recorder.finish(result);
  if (!args.trace_path.empty()) outputs.write(args.trace_path, trace.dump() + "\n");
  ExportWritten written;
  if (export_request) written = write_export(trace, hull.source(), *export_request, outputs);
  if (!args.report_dir.empty()) {
    const auto plan_data = io::export_plan(trace, hull.source());
    const auto report =
        io::preflight_report(trace, plan_data, export_request->formats, export_request->settings,
                             written.geo, planned_battery(spec, result));
    outputs.write(report_dir / "preflight.json", report.dump(1) + "\n");
    outputs.write(report_dir / "preflight.md", io::preflight_markdown(report));
    outputs.write(report_dir / "preflight.svg",
                  io::preflight_svg(trace, plan_data, export_request->settings));
  }
  if (args.json) {
    auto j = io::result_json(spec, result);
    j["planned_on"] = "prior";
    j["prior"] = !args.mission.prior.empty() ? "file" : args.synthetic ? "synthetic" : "empty";
    std::cout << j.dump() << "\n";
    check_stdout();
    outputs.commit();
    return result.complete ? 0 : 3;
  }
  auto time = [&](const std::optional<int>& t) { return io::seconds_text(spec.params, t); };
  const auto total = result.totals();
  std::cout << fmt::format("{} with {}, s1 = {}, s2 = {}, seed {}: planned on {}{}\n",
                           spec.algorithm, plural(spec.params.uavs, "UAV"), spec.params.s1,
                           spec.params.s2, spec.seed, prior_source(args),
                           result.complete ? "" : " — INCOMPLETE (time limit reached)");
  std::cout << fmt::format(
      "  expected T_c = {}   T_m = {}   ({} prior-corroded of {} hull cells)\n", time(result.t_c),
      time(result.t_m), result.corroded_cells, result.hull_cells);
  std::cout << fmt::format("  moves {}, plane changes {}, hovers {}\n", total.moves,
                           total.plane_changes, total.hovers);
  if (export_request) {
    std::cout << fmt::format("  wrote {} {} file{} to {}\n", written.names.size(),
                             format_list(*export_request), written.names.size() == 1 ? "" : "s",
                             export_request->dir.string());
    for (const auto& note : written.notes) std::cout << "  note: " << note << "\n";
  }
  if (!args.report_dir.empty()) {
    std::cout << fmt::format("  wrote the pre-flight report to {}\n", args.report_dir);
  }
  check_stdout();
  outputs.commit();
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
  add_export_options(*cmd, args->output, "--export", false);
  cmd->add_option("--report", args->report_dir,
                  "Write the export's pre-flight report into DIR: preflight.md, .json and .svg "
                  "(sorties, waypoints, flight times, unreachable and unseen cells, warnings)")
      ->type_name("DIR");
  cmd->callback([args, cmd, &action] {
    args->synthetic = std::any_of(kScenarioOptions.begin(), kScenarioOptions.end(),
                                  [cmd](const char* o) { return cmd->count(o) > 0; });
    action = [args] { return plan(*args); };
  });
}

}  // namespace hullinspect::cli
