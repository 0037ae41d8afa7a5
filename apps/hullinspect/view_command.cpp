// hullinspect view: turns a mission trace into a self-contained HTML replay (docs/viewer.md).

#include <fmt/format.h>

#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/output_set.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/io/viewer_html.hpp"
#include "mission_options.hpp"

namespace hullinspect::cli {

namespace {

struct ViewArgs {
  std::string trace_path;
  std::string out_path;  // empty: the trace's path with the extension .html
};

int view(const ViewArgs& args) {
  std::filesystem::path out = args.out_path;
  if (out.empty()) out = std::filesystem::path(args.trace_path).replace_extension(".html");
  io::OutputSet outputs;
  outputs.add_input(args.trace_path, "trace");
  outputs.add_output(out, "out");
  outputs.check();
  const auto trace = io::read_trace(args.trace_path);
  const std::string html = io::viewer_html(trace);
  outputs.write(out, html);
  outputs.commit();
  std::cout << fmt::format("wrote {} ({:.1f} MB, {} steps): open it in a web browser\n",
                           out.string(), static_cast<double>(html.size()) / 1e6,
                           trace["result"]["steps"].get<long>());
  return 0;
}

}  // namespace

void add_view_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd =
      app.add_subcommand("view", "Write a self-contained HTML replay (viewer) of a mission trace");
  cmd->footer(
      "Exit status: 0 written, 2 unreadable or malformed trace, 1 other failure.\n"
      "Example: hullinspect run -n 8 --trace mission.json && hullinspect view mission.json "
      "--out mission.html");
  cmd->add_option("trace", args->trace_path, "Trace written by `hullinspect run --trace FILE`")
      ->required()
      ->type_name("TRACE");
  cmd->add_option("--out,-o", args->out_path,
                  "HTML file to write (default: TRACE with the extension .html)")
      ->type_name("FILE");
  cmd->callback([args, &action] { action = [args] { return view(*args); }; });
}

}  // namespace hullinspect::cli
