#pragma once
// Python keyword arguments → a MissionInput, through the library's mission option declarations
// (planners/mission_input.hpp), the ones `hullinspect run` registers: defaults, checks and error
// messages are the CLI's, with the Python keyword where the CLI names its option.

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/mission_input.hpp"

namespace hullinspect::python {

/// The mission of run_mission's and Session's arguments: algorithm, uavs, s2, seed, scenario and
/// `hull_path` (may be empty: the hull is given as an object or is the default), then every
/// keyword of `params` that names a mission option (p_c is p-c, starts is start; a list gives a
/// repeated option once per item, a tuple in it is joined as X,Y for start and launch and as UAV@T
/// for fail; True sets a flag, False leaves it unset), every other keyword and every entry of
/// `options` as a planner option KEY=VALUE. Throws ParameterError naming the option.
planners::MissionInput mission_input(const pybind11::handle& algorithm,
                                     const pybind11::handle& uavs, const pybind11::handle& s2,
                                     const pybind11::handle& seed, const pybind11::handle& scenario,
                                     const std::string& hull_path, const pybind11::dict& options,
                                     const pybind11::dict& params);

/// The Python keyword of a parameter or CLI option: "part-tsp.r1" → "r1", "--p-tp" → "p_tp".
std::string python_keyword(const std::string& name);
/// A ParameterError as Python shows it: "keyword: problem".
std::string keyword_message(const ParameterError& error);

/// `value` if it is a Python int (not a bool) in [min, max]; ParameterError(keyword, …) otherwise.
pybind11::int_ integer_in(const pybind11::handle& value, const std::string& keyword,
                          const pybind11::int_& min, const pybind11::int_& max);
/// A seed given from Python: an int in [0, 2^64 - 1]; ParameterError("seed", …) otherwise.
std::uint64_t seed_value(const pybind11::handle& seed);

/// The defaults of the mission keywords (algorithm, uavs, s2, seed, scenario) from MissionInput{},
/// the defaults `hullinspect run` shows, and of run_experiment's jobs from RunnerOptions.
pybind11::dict mission_defaults();

}  // namespace hullinspect::python
