// hullinspect: plan and simulate multi-UAV two-resolution hull inspection missions.

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/pending_temporaries.hpp"
#include "number_options.hpp"

namespace hullinspect::cli {

std::string option_name(const std::string& parameter) {
  return hullinspect::option_name(parameter);
}

void check_stdout() {
  std::cout.flush();
  const bool ok = std::cout.good() && std::fflush(stdout) == 0 && std::ferror(stdout) == 0;
  const int err = errno;
  if (!ok) throw Error(std::string("cannot write to standard output: ") + std::strerror(err));
}

namespace {

// Every message is one line: control characters from input bytes (a YAML key with a newline, a
// CLI value) are shown escaped.
std::string one_line(std::string_view message) {
  std::string out;
  for (const char ch : message) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += ch;
    }
  }
  return out;
}

// A command's result on stdout is output like any file: a failed write or flush (a full disk,
// `> /dev/full`, a closed pipe) is an error, reported on one line with a non-zero exit.
int finish_stdout(int status) {
  std::cout.flush();
  const bool ok = std::cout.good() && std::fflush(stdout) == 0 && std::ferror(stdout) == 0;
  const int err = errno;
  if (!ok) {
    std::cerr << "hullinspect: cannot write to standard output: " << std::strerror(err) << "\n";
    return status == 0 || status == 3 ? kExitFailure : status;
  }
  return status;
}

// SIGINT, SIGTERM, SIGHUP: remove the temporaries of outputs not yet committed, then die of the
// signal as before (the shell sees the same status; an experiment's journal stays resumable).
void remove_temporaries_and_die(int signal) {
  io::remove_pending_temporaries();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// A signal the caller ignores (nohup, a background job) stays ignored.
void remove_temporaries_on_signals() {
  for (int s : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (::sigaction(s, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_die;
    sigemptyset(&action.sa_mask);
    ::sigaction(s, &action, nullptr);
  }
}

}  // namespace

}  // namespace hullinspect::cli

int main(int argc, char** argv) {
  using namespace hullinspect;
  cli::remove_temporaries_on_signals();
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
  cli::add_trace_command(app, action);
  cli::require_exact_numbers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli::finish_stdout(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return cli::finish_stdout(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return cli::finish_stdout(app.exit(e));
  } catch (const CLI::ParseError& e) {
    std::cerr << "hullinspect: " << cli::one_line(cli::parse_error_message(e)) << "\n";
    return cli::kExitBadInput;
  }
  try {
    return cli::finish_stdout(action ? action() : 0);
  } catch (const ParameterError& e) {
    std::cerr << "hullinspect: " << cli::one_line(user_message(e)) << "\n";
    return cli::kExitBadInput;
  } catch (const InputError& e) {
    std::cerr << "hullinspect: " << cli::one_line(e.what()) << "\n";
    return cli::kExitBadInput;
  } catch (const std::exception& e) {  // a bug, or the environment (OutputError: a full disk)
    std::cerr << "hullinspect: " << cli::one_line(e.what()) << "\n";
    return cli::kExitFailure;
  }
}
