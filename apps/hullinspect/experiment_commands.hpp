#pragma once
// The experiment subcommands (registered together by add_experiment_commands): experiment, merge,
// report.

#include "commands.hpp"

namespace hullinspect::cli {

void add_experiment_command(CLI::App& app, CommandAction& action);
void add_merge_command(CLI::App& app, CommandAction& action);
void add_report_command(CLI::App& app, CommandAction& action);

}  // namespace hullinspect::cli
