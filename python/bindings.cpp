// The `hullinspect._core` extension: bindings of the library for the Python package
// (python/hullinspect/__init__.py, docs/python.md). No logic of its own: every value goes through
// the same library calls as the CLI, and library errors become ValueError with the CLI's message.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/catalog.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/presets.hpp"
#include "hullinspect/experiment/runner.hpp"
#include "hullinspect/io/result_json.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/scenario.hpp"
#include "planner_bridge.hpp"

namespace py = pybind11;
using namespace hullinspect;

namespace {

using HullPtr = std::shared_ptr<world::HullMask>;

template <class T>
py::array_t<T> grid_array(const grid::Grid<T>& g) {
  py::array_t<T> a({g.height(), g.width()});
  std::copy(g.values().begin(), g.values().end(), a.mutable_data());
  return a;
}

py::array_t<bool> mask_array(const world::HullMask& hull) {
  py::array_t<bool> a({hull.height(), hull.width()});
  const auto values = hull.mask().values();
  for (std::size_t i = 0; i < values.size(); ++i) a.mutable_data()[i] = values[i] != 0;
  return a;
}

HullPtr hull_or_default(const HullPtr& hull) {
  return hull ? hull : std::make_shared<world::HullMask>(world::default_hull());
}

/// A mission exactly as `hullinspect run` builds it from its flags: mission parameters
/// (MissionParams), the scenario's declared options (p-c, …) and planner options.
planners::MissionSpec mission_spec(const std::string& algorithm, int uavs, int s2,
                                   std::uint64_t seed, const std::string& scenario,
                                   const world::HullMask& hull, const OptionMap& planner_options,
                                   const OptionMap& mission, const OptionMap& scenario_options) {
  planners::MissionSpec spec;
  spec.algorithm = algorithm;
  spec.seed = seed;
  spec.params.uavs = uavs;
  spec.params.s2 = s2;
  for (const auto& [key, value] : mission) {
    if (key == "s1") spec.params.s1 = static_cast<int>(parse_int_param("s1", value, 1, 1 << 20));
    if (key == "theta") spec.params.theta_deg = parse_double_param("theta", value, -1e9, 1e9);
    if (key == "start-z")
      spec.params.start_z = static_cast<int>(parse_int_param("start_z", value, -1000, 1000));
    if (key == "time-limit") {
      spec.params.time_limit =
          static_cast<int>(parse_int_param("time_limit", value, -1, 2'000'000'000));
    }
  }
  try {
    spec.corrosion = world::scenario(scenario, scenario_options).corrosion(hull.width());
  } catch (const ParameterError& e) {
    const auto dot = e.name().find('.');
    if (dot == std::string::npos) throw;
    throw ParameterError(e.name().substr(dot + 1), e.problem());
  }
  spec.planner_options = planner_options;
  return spec;
}

py::dict run_mission(const std::string& algorithm, int uavs, int s2, std::uint64_t seed,
                     const std::string& scenario, const HullPtr& hull_arg,
                     const OptionMap& planner_options, const OptionMap& mission,
                     const OptionMap& scenario_options) {
  const HullPtr hull = hull_or_default(hull_arg);
  sim::MissionResult result;
  planners::MissionSpec spec;
  {
    py::gil_scoped_release release;  // Python planners take it back in start/decide
    spec = mission_spec(algorithm, uavs, s2, seed, scenario, *hull, planner_options, mission,
                        scenario_options);
    result = planners::run_mission(spec, *hull);
  }
  py::dict out;
  out["json"] = io::result_json(spec, result).dump();
  py::array_t<double> c(static_cast<py::ssize_t>(result.inspected_series.size()));
  py::array_t<double> m(static_cast<py::ssize_t>(result.known_series.size()));
  for (int t = 0; t < static_cast<int>(result.inspected_series.size()); ++t) {
    c.mutable_data()[t] = result.c_percent(t);
    m.mutable_data()[t] = result.m_percent(t);
  }
  out["c"] = c;
  out["m"] = m;
  return out;
}

experiment::ExperimentConfig load_experiment(const std::string& kind, const std::string& value) {
  if (kind == "preset") return experiment::load_preset(value);
  if (kind == "path") return experiment::load_config(value);
  // YAML text (a dict arrives as JSON, which is YAML); relative hull paths from the cwd.
  return experiment::parse_config(value, "<config>", std::filesystem::current_path());
}

void run_experiment(const std::string& kind, const std::string& value, int jobs,
                    const std::string& out) {
  py::gil_scoped_release release;
  const experiment::ExperimentPlan plan(load_experiment(kind, value));
  experiment::RunnerOptions options;
  options.jobs = jobs;
  experiment::run_experiment(plan, out, options);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "hullinspect's C++ library (use the hullinspect package, not this module)";

  // Library errors are bad input for Python too: ValueError with the CLI's one-line message.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      PyErr_SetString(PyExc_ValueError, user_message(e).c_str());
    }
  });

  py::class_<world::HullMask, HullPtr>(m, "Hull")
      .def_static(
          "default", [] { return std::make_shared<world::HullMask>(world::default_hull()); },
          "The built-in 230 x 30 ship side profile")
      .def_static(
          "load",
          [](const std::string& path) {
            return std::make_shared<world::HullMask>(world::load_hull(path));
          },
          py::arg("path"), "A text mask or PGM image (docs/formats.md), or 'default'")
      .def_property_readonly("mask", &mask_array, "numpy bool array [y][x], True on hull cells")
      .def_property_readonly("width", &world::HullMask::width)
      .def_property_readonly("height", &world::HullMask::height)
      .def_property_readonly("cells", &world::HullMask::cell_count)
      .def_property_readonly("source", &world::HullMask::source)
      .def("__repr__", [](const world::HullMask& h) {
        return fmt::format("Hull({}x{}, {} cells, {})", h.width(), h.height(), h.cell_count(),
                           h.source());
      });

  py::class_<world::Instance>(m, "Instance")
      .def_property_readonly(
          "truth", [](const world::Instance& i) { return grid_array(i.truth); },
          "C: numpy int8 [y][x], -1 not hull, 0 clean, 1 corroded")
      .def_property_readonly(
          "prior", [](const world::Instance& i) { return grid_array(i.prior); },
          "C': numpy int8 [y][x], -1 not hull, 0, 1")
      .def_readonly("seed", &world::Instance::seed)
      .def_property_readonly("corroded_cells", &world::Instance::corroded_cells);

  m.def(
      "make_instance",
      [](const HullPtr& hull_arg, std::uint64_t seed, const std::string& scenario,
         const OptionMap& scenario_options) {
        const HullPtr hull = hull_or_default(hull_arg);
        const auto corrosion = world::scenario(scenario, scenario_options).corrosion(hull->width());
        world::validate(corrosion, *hull);
        return world::generate_instance(*hull, corrosion, seed);
      },
      py::arg("hull"), py::arg("seed"), py::arg("scenario"), py::arg("options"));

  m.def("run_mission", &run_mission, py::arg("algorithm"), py::arg("uavs"), py::arg("s2"),
        py::arg("seed"), py::arg("scenario"), py::arg("hull"), py::arg("planner_options"),
        py::arg("mission"), py::arg("scenario_options"));
  m.def("run_experiment", &run_experiment, py::arg("kind"), py::arg("value"), py::arg("jobs"),
        py::arg("out"));
  m.def(
      "catalog", [](const std::string& kind) { return experiment::catalog_json(kind).dump(); },
      py::arg("kind") = "");
  m.def("preset_text",
        [](const std::string& name) { return std::string(experiment::preset_text(name)); });
  m.def("register_planner", &python::register_python_planner, py::arg("name"), py::arg("cls"),
        py::arg("description"));
}
