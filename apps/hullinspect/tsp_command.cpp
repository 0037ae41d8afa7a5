#include "commands.hpp"

namespace hullinspect::cli {

// Placeholder until the tsp command lands; keeps the subcommand list in one place.
void add_tsp_command(CLI::App&, CommandAction&) {}

}  // namespace hullinspect::cli
