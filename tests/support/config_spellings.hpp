#pragma once
// An experiment config must name the same experiment however its own path is spelled: these run
// one config under several spellings and from several directories and compare what they write.

#include <filesystem>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"

namespace hullinspect::testing {

/// Runs the CLI with `cwd` as the working directory.
CliResult run_cli_in(const std::filesystem::path& cwd, const std::vector<std::string>& args);

/// The "fingerprint" line of the manifest in `results` ("" without one).
std::string fingerprint_of(const std::filesystem::path& results);

/// Runs `experiment --config` of dir/sub/NAME as NAME and ./NAME from dir/sub, as sub/NAME from
/// dir and by its absolute path from / (into dir/r0 … dir/r3), expects one fingerprint and one
/// runs.csv, then resumes dir/r0 as ./NAME from dir/sub and by the absolute path from /, and
/// expects its runs.csv unchanged.
void expect_one_experiment_however_spelled(const std::filesystem::path& dir, const std::string& sub,
                                           const std::string& name);

}  // namespace hullinspect::testing
