// hullinspect export: a mission trace's flown trajectories as waypoint files (docs/export.md).

#include <fmt/format.h>

#include <iostream>

#include "commands.hpp"
#include "export_options.hpp"
#include "hullinspect/files/output_set.hpp"
#include "hullinspect/io/trace_reader.hpp"

namespace hullinspect::cli {

namespace {

struct ExportCommandArgs {
  std::string trace_path;
  ExportArgs output;
};

int export_trace(const ExportCommandArgs& args) {
  io::OutputSet outputs;  // first: it guards every file read from here on (the --geo file too)
  const auto request = resolve_export(args.output, "--out");
  outputs.add_input(args.trace_path, "trace");
  declare_export_dir(outputs, *request);
  outputs.check();  // the directory, before reading the trace
  const auto trace = io::read_trace(args.trace_path);
  // The values per UAV in a frame: uav_fields names them (checked by read_trace).
  const auto fields = trace.contains("uav_fields") ? trace["uav_fields"].size() : 5;
  const auto uavs = trace.at("frames").at(0).at("u").size() / fields;
  declare_export_files(outputs, *request, static_cast<int>(uavs));
  outputs.check();
  const auto written = write_export(trace, args.trace_path, *request, outputs);
  const auto& names = written.names;
  std::cout << fmt::format("wrote {} {} file{} to {}: {}\n", names.size(), format_list(*request),
                           names.size() == 1 ? "" : "s", request->dir.string(),
                           fmt::join(names, ", "));
  for (const auto& note : written.notes) std::cout << "note: " << note << "\n";
  check_stdout();
  outputs.commit();
  return 0;
}

}  // namespace

void add_export_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<ExportCommandArgs>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Write a mission trace's trajectories as flight files (csv, qgc, wpl, path, litchi, dji-kmz, "
      "kml)");
  cmd->footer(
      "Exit status: 0 written, 2 invalid input (nothing written), 1 other failure.\n"
      "Example: hullinspect export mission.json --format qgc --origin 53.54,9.97,0 --heading 90 "
      "--out plans");
  cmd->add_option("trace", args->trace_path, "Trace written by `hullinspect run --trace FILE`")
      ->required()
      ->type_name("TRACE");
  add_export_options(*cmd, args->output, "--out", true);
  cmd->get_option("--out")->required();
  cmd->callback([args, &action] { action = [args] { return export_trace(*args); }; });
}

}  // namespace hullinspect::cli
