#include "commands.hpp"

namespace hullinspect::cli {

// Placeholder until the partition command lands; keeps the subcommand list in one place.
void add_partition_command(CLI::App&, CommandAction&) {}

}  // namespace hullinspect::cli
