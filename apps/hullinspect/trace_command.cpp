// hullinspect trace check: reads a mission trace and checks every rule of the mission it records
// from the trace alone (docs/trace-format.md "Rules").

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "commands.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/io/trace_rules.hpp"

namespace hullinspect::cli {

namespace {

int check_trace(const std::string& path) {
  const auto trace = io::read_trace(path);
  io::check_trace_safety(trace, path);
  const auto& r = trace["result"];
  // Versions before 3 may lack uav_fields: the paper's five values per UAV.
  const std::size_t fields = trace.contains("uav_fields") ? trace["uav_fields"].size() : 5;
  std::string summary =
      fmt::format("{}: every rule kept: {}, {}", path,
                  plural(static_cast<long long>(trace["frames"][0]["u"].size() / fields), "UAV"),
                  plural(r["steps"].get<long long>(), "step"));
  if (r.contains("sorties"))
    summary += fmt::format(", {}", plural(r["sorties"].get<long long>(), "sortie"));
  if (r.contains("battery_crashes")) summary += ", no battery crash";
  // Versions before 3 count conflicts without recording the D they were counted at.
  if (r.contains("separation_conflicts") && trace.contains("separation")) {
    summary += fmt::format(", no two UAVs closer than {}",
                           plural(trace["separation"].get<long long>(), "cell"));
  }
  std::cout << summary << "\n";
  check_stdout();
  return 0;
}

}  // namespace

void add_trace_command(CLI::App& app, CommandAction& action) {
  CLI::App* trace = app.add_subcommand("trace", "Work with mission traces");
  trace->require_subcommand(1);
  auto path = std::make_shared<std::string>();
  CLI::App* check = trace->add_subcommand(
      "check",
      "Check from a trace alone every rule of the mission it records: moves, no-fly positions, "
      "take-offs and landings at a launch site, battery swaps, no crash, the reserve at every "
      "landing, the separation (docs/trace-format.md)");
  check->footer(
      "Exit status: 0 every rule kept, 2 unreadable or malformed trace or a rule broken (one line "
      "naming the frame, the UAV and the rule), 1 other failure.\n"
      "Example: hullinspect run -n 2 --launch 57,0 --launch 172,0 --endurance 400 --trace m.json "
      "&& hullinspect trace check m.json");
  check->add_option("trace", *path, "Trace written by `hullinspect run --trace FILE`")
      ->required()
      ->type_name("TRACE");
  check->callback([path, &action] { action = [path] { return check_trace(*path); }; });
}

}  // namespace hullinspect::cli
