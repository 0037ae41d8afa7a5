#include "commands.hpp"
#include "hullinspect/io/atomic_file.hpp"
#include "mission_options.hpp"

namespace hullinspect::cli {

// Placeholder until the viewer lands: --html writes nothing useful yet.
void write_viewer_html(const nlohmann::json& trace, const std::string& path) {
  io::write_file_atomic(path, "<!doctype html><pre>" + trace.dump() + "</pre>\n");
}

void add_view_command(CLI::App&, CommandAction&) {}

}  // namespace hullinspect::cli
