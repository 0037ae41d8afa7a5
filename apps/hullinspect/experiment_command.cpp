#include "commands.hpp"

namespace hullinspect::cli {

// Placeholder until the experiment runner lands.
void add_experiment_commands(CLI::App&, CommandAction&) {}

}  // namespace hullinspect::cli
