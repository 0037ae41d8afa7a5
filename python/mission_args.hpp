#pragma once
// Python keyword arguments → the CLI's own mission options. run_mission and Session turn their
// arguments into the command line `hullinspect run` would get and parse it with the CLI's parser
// (apps/hullinspect/mission_options.cpp), so defaults, checks and error messages are the CLI's.

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

#include "../apps/hullinspect/mission_options.hpp"
#include "hullinspect/core/errors.hpp"

namespace hullinspect::python {

/// The command-line words for one mission: --algorithm, --uavs, --s2, --seed, --scenario, then
/// every keyword of `params` that names a mission option (p_c → --p-c; a list repeats the option,
/// a tuple in it is joined as X,Y for --start and as UAV@T for --fail; True is a flag), every other
/// keyword and every entry of `options` as -O KEY=VALUE. `hull_path` (may be empty) adds --hull.
std::vector<std::string> mission_words(const std::string& algorithm, const pybind11::handle& uavs,
                                       const pybind11::handle& s2, const pybind11::handle& seed,
                                       const std::string& scenario, const std::string& hull_path,
                                       const pybind11::dict& options, const pybind11::dict& params);

/// Parses `words` as `hullinspect run` does. Throws ParameterError naming the option for anything
/// its parser refuses (the CLI's "--uavs: 'x' is not a valid value (see --help)" becomes
/// ParameterError("uavs", "'x' is not a valid value")).
cli::MissionArgs parse_mission_words(const std::vector<std::string>& words);

/// The Python keyword of a parameter or CLI option: "part-tsp.r1" → "r1", "--p-tp" → "p_tp".
std::string python_keyword(const std::string& name);
/// A ParameterError as Python shows it: "keyword: problem".
std::string keyword_message(const ParameterError& error);

/// `value` if it is a Python int (not a bool) in [min, max]; ParameterError(keyword, …) otherwise.
pybind11::int_ integer_in(const pybind11::handle& value, const std::string& keyword,
                          const pybind11::int_& min, const pybind11::int_& max);
/// A seed given from Python: an int in [0, 2^64 - 1]; ParameterError("seed", …) otherwise.
std::uint64_t seed_value(const pybind11::handle& seed);

/// The defaults of the mission keywords (algorithm, uavs, s2, seed, scenario) from MissionArgs, the
/// declarations `hullinspect run` reads, and of run_experiment's jobs from RunnerOptions.
pybind11::dict mission_defaults();

}  // namespace hullinspect::python
