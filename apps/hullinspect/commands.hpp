#pragma once
// Each subcommand lives in its own file and registers itself on the CLI11 app: it declares its
// options and sets `action` to the function that runs when the subcommand is chosen. Actions
// return the exit status; library errors propagate to main(), which prints one line and exits.

#include <CLI/CLI.hpp>

#include <functional>

namespace hullinspect::cli {

using CommandAction = std::function<int()>;

void add_run_command(CLI::App& app, CommandAction& action);
void add_partition_command(CLI::App& app, CommandAction& action);
void add_tsp_command(CLI::App& app, CommandAction& action);
void add_experiment_commands(CLI::App& app, CommandAction& action);  // experiment, merge, report
void add_view_command(CLI::App& app, CommandAction& action);
void add_list_command(CLI::App& app, CommandAction& action);
void add_hull_command(CLI::App& app, CommandAction& action);    // hull import
void add_export_command(CLI::App& app, CommandAction& action);  // docs/export.md
void add_plan_command(CLI::App& app, CommandAction& action);    // docs/export.md
void add_trace_command(CLI::App& app, CommandAction& action);   // trace check

/// Exit status for invalid input (bad option values, unreadable or malformed files).
inline constexpr int kExitBadInput = 2;
/// Exit status for a failure that is not the user's input (a planner bug, a full disk).
inline constexpr int kExitFailure = 1;

/// Flushes standard output and throws when a write to it failed (a full disk, `> /dev/full`, a
/// closed pipe). Commands call it after printing their result and before committing their files, so
/// a command whose printed result was lost leaves no files behind (exit 1).
void check_stdout();

/// "--p-tp" for the parameter "p_tp"; "--algorithm" for "algorithm"; "--r1" for "part-tsp.r1".
std::string option_name(const std::string& parameter);

}  // namespace hullinspect::cli
