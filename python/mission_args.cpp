#include "mission_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/runner.hpp"

namespace hullinspect::python {

namespace py = pybind11;

namespace {

/// A Python value as the command line would give it: True/False as true/false, numbers as Python
/// prints them (repr of a float round-trips), anything else as str().
std::string text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  return py::str(value).cast<std::string>();
}

/// A tuple as one option value: (x, y) → "x,y" for --start, (uav, t) → "uav@t" for --fail.
std::string item_text(const std::string& option, const py::handle& item) {
  if (!py::isinstance<py::tuple>(item)) return text(item);
  std::string out;
  for (const auto& part : item.cast<py::tuple>()) {
    if (!out.empty()) out += option == "fail" ? "@" : ",";
    out += text(part);
  }
  return out;
}

}  // namespace

planners::MissionInput mission_input(const py::handle& algorithm, const py::handle& uavs,
                                     const py::handle& s2, const py::handle& seed,
                                     const py::handle& scenario, const std::string& hull_path,
                                     const py::dict& options, const py::dict& params) {
  planners::MissionInput input;
  planners::set_mission_option(input, "algorithm", text(algorithm));
  planners::set_mission_option(input, "uavs", text(uavs));
  planners::set_mission_option(input, "s2", text(s2));
  planners::set_mission_option(input, "seed", text(seed));
  planners::set_mission_option(input, "scenario", text(scenario));
  if (!hull_path.empty()) planners::set_mission_option(input, "hull", hull_path);
  for (const auto& [key, value] : params) {
    std::string name = key.cast<std::string>();
    std::replace(name.begin(), name.end(), '_', '-');
    if (name == "starts") name = "start";
    const planners::MissionOptionDecl* decl = planners::find_mission_option(name);
    // "option" and "hull" are run_mission's own arguments: as keywords they are planner options.
    if (decl == nullptr || name == "option" || name == "hull") {
      input.planner_options.push_back(name + "=" + text(value));
    } else if (decl->kind == planners::InputKind::kFlag) {
      if (value.cast<bool>()) planners::set_mission_option(input, name, "true");
    } else if (decl->kind == planners::InputKind::kRepeated && py::isinstance<py::list>(value)) {
      for (const auto& item : value.cast<py::list>()) {
        planners::set_mission_option(input, name, item_text(name, item));
      }
    } else {
      planners::set_mission_option(input, name, item_text(name, value));
    }
  }
  for (const auto& [key, value] : options) {
    input.planner_options.push_back(key.cast<std::string>() + "=" + text(value));
  }
  return input;
}

std::string python_keyword(const std::string& name) {
  std::string out = name;
  if (const auto dot = out.rfind('.'); dot != std::string::npos) out = out.substr(dot + 1);
  if (out.rfind("--", 0) == 0) out = out.substr(2);
  std::replace(out.begin(), out.end(), '-', '_');
  if (out == "start") return "starts";
  return out;
}

std::string keyword_message(const ParameterError& error) {
  return python_keyword(error.name()) + ": " + error.problem();
}

py::int_ integer_in(const py::handle& value, const std::string& keyword, const py::int_& min,
                    const py::int_& max) {
  if (py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value)) {
    const auto number = py::reinterpret_borrow<py::int_>(value);
    if (number >= min && number <= max) return number;
  }
  throw ParameterError(
      keyword,
      fmt::format("must be an integer in [{}, {}] (got {})", py::repr(min).cast<std::string>(),
                  py::repr(max).cast<std::string>(), py::repr(value).cast<std::string>()));
}

std::uint64_t seed_value(const py::handle& seed) {
  return integer_in(seed, "seed", py::int_(0), py::int_(std::numeric_limits<std::uint64_t>::max()))
      .cast<std::uint64_t>();
}

py::dict mission_defaults() {
  const planners::MissionInput args;
  py::dict out;
  out["algorithm"] = args.algorithm;
  out["uavs"] = args.uavs;
  out["s2"] = args.s2;
  out["seed"] = args.seed;
  out["scenario"] = args.scenario;
  out["jobs"] = experiment::RunnerOptions{}.jobs;
  return out;
}

}  // namespace hullinspect::python
