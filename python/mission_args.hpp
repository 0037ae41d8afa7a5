#pragma once
// Python keyword arguments → the CLI's own mission options. run_mission and Session turn their
// arguments into the command line `hullinspect run` would get and parse it with the CLI's parser
// (apps/hullinspect/mission_options.cpp), so defaults, checks and error messages are the CLI's.

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "../apps/hullinspect/mission_options.hpp"

namespace hullinspect::python {

/// The command-line words for one mission: --algorithm, --uavs, --s2, --seed, --scenario, then
/// every keyword of `params` that names a mission option (p_c → --p-c; a list repeats the option,
/// a tuple in it is joined as X,Y for --start and as UAV@T for --fail; True is a flag), every other
/// keyword and every entry of `options` as -O KEY=VALUE. `hull_path` (may be empty) adds --hull.
std::vector<std::string> mission_words(const std::string& algorithm, const pybind11::handle& uavs,
                                       const pybind11::handle& s2, const pybind11::handle& seed,
                                       const std::string& scenario, const std::string& hull_path,
                                       const pybind11::dict& options, const pybind11::dict& params);

/// Parses `words` as `hullinspect run` does. Throws ParameterError with the CLI's message for
/// anything its parser refuses ("--uavs: 'x' is not a valid value (see --help)").
cli::MissionArgs parse_mission_words(const std::vector<std::string>& words);

}  // namespace hullinspect::python
