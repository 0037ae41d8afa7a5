#pragma once
// Runs the built CLI (HULLINSPECT_CLI, set by CTest, or the one beside the test binary) and
// captures its exit status, stdout and stderr.

#include <string>
#include <vector>

namespace hullinspect::testing {

struct CliResult {
  int status = -1;
  std::string out;
  std::string err;
};

/// The CLI's path: $HULLINSPECT_CLI, else the hullinspect beside the test executable.
std::string cli_path();

/// Runs `hullinspect <args>` without a shell (arguments are passed as given).
CliResult run_cli(const std::vector<std::string>& args);

/// A fresh empty temporary directory for one test.
std::string make_temp_dir(const std::string& name);

}  // namespace hullinspect::testing
