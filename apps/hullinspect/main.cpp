// hullinspect: plan and simulate multi-UAV two-resolution hull inspection missions.

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <iostream>

#include "commands.hpp"
#include "hullinspect/core/errors.hpp"

namespace hullinspect::cli {

std::string option_name(const std::string& parameter) { return hullinspect::option_name(parameter); }

}  // namespace hullinspect::cli

int main(int argc, char** argv) {
  using namespace hullinspect;
  CLI::App app{"hullinspect: multi-UAV two-resolution hull inspection planner and simulator"};
  app.set_version_flag("--version", std::string("hullinspect ") + HULLINSPECT_VERSION);
  app.require_subcommand(1);
  cli::CommandAction action;
  cli::add_run_command(app, action);
  cli::add_partition_command(app, action);
  cli::add_tsp_command(app, action);
  cli::add_experiment_commands(app, action);
  cli::add_view_command(app, action);
  cli::add_list_command(app, action);
  cli::add_hull_command(app, action);
  cli::add_export_command(app, action);
  cli::add_plan_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string message = e.what();
    if (auto nl = message.find('\n'); nl != std::string::npos) message.resize(nl);
    // CLI11 says "Could not convert: --uavs,-n = abc"; name the option first like our own errors.
    const std::string prefix = "Could not convert: ";
    if (message.rfind(prefix, 0) == 0) {
      const auto eq = message.find(" = ");
      std::string option = message.substr(prefix.size(), eq - prefix.size());
      option = option.substr(0, option.find(','));
      const std::string value = eq == std::string::npos ? "" : message.substr(eq + 3);
      message = option + ": '" + value + "' is not a valid value";
    }
    std::cerr << "hullinspect: " << message << " (see --help)\n";
    return cli::kExitBadInput;
  }
  try {
    return action ? action() : 0;
  } catch (const ParameterError& e) {
    std::cerr << "hullinspect: " << user_message(e) << "\n";
    return cli::kExitBadInput;
  } catch (const InputError& e) {
    std::cerr << "hullinspect: " << e.what() << "\n";
    return cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "hullinspect: " << e.what() << "\n";
    return cli::kExitFailure;
  }
}
