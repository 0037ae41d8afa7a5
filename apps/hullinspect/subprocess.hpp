#pragma once

#include <string>
#include <vector>

namespace hullinspect::cli {

/// Runs a program (argv[0] is its path; no shell) with the inherited environment and standard
/// streams, waits for it and returns its exit status (128 + signal if killed, 127 if it could not
/// be started).
int run_process(const std::vector<std::string>& argv);

}  // namespace hullinspect::cli
