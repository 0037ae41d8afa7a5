// The `hullinspect._core` extension: bindings of the library for the Python package
// (python/hullinspect/__init__.py, docs/python.md). No logic of its own: missions are read through
// the library's mission option declarations, as the CLI's are (mission_args.hpp), and run by the
// same library calls as `hullinspect run`, and library errors become ValueError with the CLI's
// one-line message.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/catalog.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/presets.hpp"
#include "hullinspect/experiment/runner.hpp"
#include "hullinspect/files/output_set.hpp"
#include "hullinspect/io/result_json.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/io/traced_mission.hpp"
#include "hullinspect/planners/mission_input.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/scenario.hpp"
#include "hullinspect/world/user_maps.hpp"
#include "mission_args.hpp"
#include "planner_bridge.hpp"
#include "python_calls.hpp"
#include "session.hpp"

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

HullPtr load_hull(const std::string& path) {
  return std::make_shared<world::HullMask>(
      planners::load_hull_argument(path, planners::MeshInput{}));
}

HullPtr hull_or_default(const HullPtr& hull) {
  return hull ? hull : std::make_shared<world::HullMask>(world::default_hull());
}

/// The hull of a mission: the Hull object given, else --hull as the CLI loads it.
HullPtr mission_hull(const HullPtr& given, const planners::MissionInput& args) {
  return given ? given : std::make_shared<world::HullMask>(planners::load_mission_hull(args));
}

py::dict result_dict(const planners::MissionSpec& spec, const sim::MissionResult& result) {
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

/// The files a mission reads, which its trace must not replace.
void add_mission_inputs(io::OutputSet& outputs, const planners::MissionInput& args) {
  if (args.hull != "default") outputs.add_input(args.hull, "hull");
  if (!args.prior.empty()) outputs.add_input(args.prior, "prior");
  if (!args.truth.empty()) outputs.add_input(args.truth, "truth");
  if (!args.no_fly.empty()) outputs.add_input(args.no_fly, "no_fly");
}

/// `hullinspect run --json` of the mission `args` without printing: the result JSON and c(t), m(t);
/// with `trace_path` the trace is written there too (as `run --trace`), with `keep_trace` it is
/// returned as JSON text under "trace".
py::dict run_mission(const planners::MissionInput& args, const HullPtr& hull_arg,
                     const std::string& trace_path, bool keep_trace) {
  sim::MissionResult result;
  planners::MissionSpec spec;
  std::string trace_text;
  {
    py::gil_scoped_release release;  // Python planners take it back in start/decide
    io::OutputSet outputs;
    add_mission_inputs(outputs, args);
    outputs.add_output(trace_path, "trace");
    outputs.check();
    const HullPtr hull = mission_hull(hull_arg, args);
    spec = planners::build_spec(args, *hull);
    if (trace_path.empty() && !keep_trace) {
      result = planners::run_mission(spec, *hull);
    } else {
      auto traced = io::run_traced_mission(spec, *hull);
      result = std::move(traced.result);
      trace_text = traced.trace.dump();
      if (!trace_path.empty()) {
        outputs.write(trace_path, trace_text + "\n");
        outputs.commit();
      }
    }
  }
  py::dict out = result_dict(spec, result);
  if (keep_trace) out["trace"] = trace_text;
  return out;
}

/// C′ for a Session: None (no expected corrosion), a map file, or an array [y][x] over the hull.
grid::Grid<std::int8_t> session_prior(const py::object& prior, const world::HullMask& hull) {
  grid::Grid<std::int8_t> out(hull.width(), hull.height(), -1);
  for (int i : hull.cells()) out[i] = 0;
  if (prior.is_none()) return out;
  if (py::isinstance<py::str>(prior)) {
    return world::load_corrosion_map(prior.cast<std::string>(), hull).cells;
  }
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(prior);
  if (!a || a.ndim() != 2 || a.shape(0) != hull.height() || a.shape(1) != hull.width()) {
    throw Error(
        fmt::format("prior: expected a path or an array of shape ({}, {}) [y][x] like the "
                    "hull's mask",
                    hull.height(), hull.width()));
  }
  // 1 expected corrosion, 0 none, -1 (make_instance's marker) off the hull only.
  for (int y = 0; y < hull.height(); ++y) {
    for (int x = 0; x < hull.width(); ++x) {
      const double v = a.at(y, x);
      const bool on_hull = hull.is_hull(x, y);
      if (!(v == 0 || v == 1 || (v == -1 && !on_hull))) {
        throw Error(fmt::format("prior[{}][{}]: expected {} (got {})", y, x,
                                on_hull ? "0 or 1 on a hull cell" : "-1, 0 or 1", v));
      }
      if (v == 1 && !on_hull) {
        throw Error(
            fmt::format("prior: cell ({}, {}) is marked corroded but is not a hull cell", x, y));
      }
      if (on_hull) out(x, y) = v == 1 ? 1 : 0;
    }
  }
  return out;
}

std::unique_ptr<python::Session> make_session(const planners::MissionInput& args,
                                              const HullPtr& hull_arg, const py::object& prior,
                                              bool keep_trace) {
  if (!args.truth.empty() || !args.fail.empty() || args.fail_rate != 0 ||
      args.fail_one_within != 0 || !args.prior.empty()) {
    throw Error(
        "Session: truth and fail options do not apply to a live session (the readings are "
        "the truth; report failures with step(readings, failed=[…]))");
  }
  const HullPtr hull = mission_hull(hull_arg, args);
  planners::MissionSpec spec = planners::build_spec(args, *hull);
  auto prior_grid = session_prior(prior, *hull);
  py::gil_scoped_release release;
  return std::make_unique<python::Session>(hull, std::move(spec), std::move(prior_grid),
                                           keep_trace);
}

std::vector<python::CellReading> readings_from(const py::iterable& items) {
  std::vector<python::CellReading> out;
  const py::module_ numpy = py::module_::import("numpy");
  const py::object numpy_bool = numpy.attr("bool_");
  const py::object numpy_integer = numpy.attr("integer");
  std::size_t j = 0;
  for (const auto& item : items) {
    const auto seq = py::reinterpret_borrow<py::sequence>(item);
    if (!py::isinstance<py::sequence>(item) || py::isinstance<py::str>(item) || seq.size() != 4) {
      throw Error(fmt::format("readings[{}]: expected (x, y, plane, corroded), got {}", j,
                              py::repr(item).cast<std::string>()));
    }
    // True/False (Python or numpy bools) or the integers 0/1: text such as 'no' is refused
    // rather than read as corroded.
    const py::handle corroded = seq[3];
    const bool is_bool =
        py::isinstance<py::bool_>(corroded) || py::isinstance(corroded, numpy_bool);
    const bool is_integer =
        py::isinstance<py::int_>(corroded) || py::isinstance(corroded, numpy_integer);
    const bool is_01 =
        is_integer && (py::int_(py::reinterpret_borrow<py::object>(corroded)).equal(py::int_(0)) ||
                       py::int_(py::reinterpret_borrow<py::object>(corroded)).equal(py::int_(1)));
    if (!is_bool && !is_01) {
      throw Error(fmt::format("readings[{}]: corroded must be True or False, got {}", j,
                              py::repr(corroded).cast<std::string>()));
    }
    try {
      out.push_back({seq[0].cast<int>(), seq[1].cast<int>(), seq[2].cast<int>(),
                     PyObject_IsTrue(corroded.ptr()) == 1});
    } catch (const py::cast_error&) {
      throw Error(fmt::format("readings[{}]: x, y and plane must be integers, got {}", j,
                              py::repr(item).cast<std::string>()));
    }
    ++j;
  }
  return out;
}

py::list action_names(std::span<const sim::Action> actions) {
  py::list out;
  for (const auto a : actions) {
    switch (a) {
      case sim::Action::kNorth:
        out.append("N");
        break;
      case sim::Action::kSouth:
        out.append("S");
        break;
      case sim::Action::kEast:
        out.append("E");
        break;
      case sim::Action::kWest:
        out.append("W");
        break;
      case sim::Action::kChangePlane:
        out.append("change");
        break;
      case sim::Action::kHover:
        out.append("hover");
        break;
    }
  }
  return out;
}

py::list uav_tuples(std::span<const sim::UavState> uavs) {
  py::list out;
  for (const auto& u : uavs)
    out.append(py::make_tuple(u.pos.x, u.pos.y, u.z, u.in_transit(), u.failed));
  return out;
}

experiment::ExperimentConfig load_experiment(const std::string& kind, const std::string& value) {
  if (kind == "preset") return experiment::load_preset(value);
  if (kind == "path") return experiment::load_config(value);
  // YAML text (a dict arrives as JSON, which is YAML); relative hull paths from the cwd.
  return experiment::parse_config(value, "<config>", std::filesystem::current_path());
}

void run_experiment(const std::string& kind, const std::string& value, const py::handle& jobs_arg,
                    const std::string& out, bool resume) {
  const int jobs =
      python::integer_in(jobs_arg, "jobs", py::int_(0), py::int_(experiment::kMaxJobs)).cast<int>();
  std::optional<experiment::ExperimentPlan> loaded;
  try {
    loaded.emplace(load_experiment(kind, value));
  } catch (const ParameterError& e) {  // a preset is run_experiment's `config`
    if (e.name() != "preset") throw;
    throw ParameterError("config", e.problem());
  }
  const experiment::ExperimentPlan& plan = *loaded;
  // Worker threads fly the missions; Python planners' calls and Ctrl-C are served on this thread.
  python::serve_python_calls([&](const std::atomic<bool>& stopped) {
    experiment::RunnerOptions options;
    options.jobs = jobs;
    options.resume = resume;
    options.on_progress = [&stopped](const experiment::Progress&) {
      if (stopped) throw Error("interrupted");
    };
    options.interrupted = [&stopped] { return stopped.load(); };
    experiment::run_experiment(plan, out, options);
  });
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "hullinspect's C++ library (use the hullinspect package, not this module)";

  // Bad input is ValueError with the CLI's one-line message, naming the Python keyword where the
  // CLI names its option; a broken model rule (a planner bug) is RuntimeError.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const LogicError& e) {
      PyErr_SetString(PyExc_RuntimeError, user_message(e).c_str());
    } catch (const ParameterError& e) {
      PyErr_SetString(PyExc_ValueError, python::keyword_message(e).c_str());
    } catch (const Error& e) {
      PyErr_SetString(PyExc_ValueError, user_message(e).c_str());
    }
  });

  py::class_<world::HullMask, HullPtr>(m, "Hull")
      .def_static(
          "default", [] { return std::make_shared<world::HullMask>(world::default_hull()); },
          "The built-in 230 x 30 ship side profile")
      .def_static("load", &load_hull, py::arg("path"),
                  "Anything `--hull` takes: 'default', 'dtc', a text mask, a PGM image, a hull "
                  "JSON or a mesh (docs/hulls.md)")
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
      [](const HullPtr& hull_arg, const py::object& seed_arg, const std::string& scenario,
         const OptionMap& scenario_options) {
        const std::uint64_t seed = python::seed_value(seed_arg);
        const HullPtr hull = hull_or_default(hull_arg);
        const world::CorrosionParams corrosion =
            planners::scenario_corrosion(scenario, scenario_options, hull->width());
        world::validate(corrosion, *hull);
        return world::generate_instance(*hull, corrosion, seed);
      },
      py::arg("hull"), py::arg("seed"), py::arg("scenario"), py::arg("options"));

  // A mission's inputs, read from keywords by mission_input and handed to run_mission or Session.
  py::class_<planners::MissionInput>(m, "MissionInput");
  m.def("mission_input", &python::mission_input, py::arg("algorithm"), py::arg("uavs"),
        py::arg("s2"), py::arg("seed"), py::arg("scenario"), py::arg("hull_path"),
        py::arg("options"), py::arg("params"));
  m.def("run_mission", &run_mission, py::arg("mission"), py::arg("hull"), py::arg("trace_path"),
        py::arg("keep_trace"));
  m.def(
      "read_trace", [](const std::string& path) { return io::read_trace(path).dump(); },
      py::arg("path"), "The trace file as JSON text, checked as `hullinspect view` checks it");
  m.def("mission_defaults", &python::mission_defaults,
        "The defaults of `hullinspect run`'s options, from the same declarations");
  m.def("run_experiment", &run_experiment, py::arg("kind"), py::arg("value"), py::arg("jobs"),
        py::arg("out"), py::arg("resume"));
  m.attr("__version__") = HULLINSPECT_VERSION;
  m.def(
      "catalog", [](const std::string& kind) { return experiment::catalog_json(kind).dump(); },
      py::arg("kind") = "");
  m.def("preset_names", &experiment::preset_names);
  m.def("register_planner", &python::register_python_planner, py::arg("name"), py::arg("cls"),
        py::arg("description"));

  py::class_<python::Session>(m, "Session")
      .def(py::init(&make_session), py::arg("mission"), py::arg("hull"), py::arg("prior"),
           py::arg("keep_trace"))
      .def("trace", [](const python::Session& s) { return s.trace().dump(); })
      .def(
          "step",
          [](python::Session& s, const py::iterable& readings, const std::vector<int>& failed) {
            const auto parsed = readings_from(readings);
            std::vector<sim::Action> actions;
            {
              py::gil_scoped_release release;
              actions = s.step(parsed, failed);
            }
            return action_names(actions);
          },
          py::arg("readings"), py::arg("failed") = std::vector<int>{})
      .def(
          "expected_readings",
          [](const python::Session& s, const std::vector<int>& failed) {
            py::list out;
            for (const auto& [x, y, plane] : s.expected_readings(failed)) {
              out.append(py::make_tuple(x, y, plane));
            }
            return out;
          },
          py::arg("failed") = std::vector<int>{})
      .def_property_readonly("t", &python::Session::time)
      .def_property_readonly("finished", &python::Session::finished)
      .def_property_readonly("complete", &python::Session::complete)
      .def_property_readonly("map", [](const python::Session& s) { return grid_array(s.map()); })
      .def_property_readonly("uavs", [](const python::Session& s) { return uav_tuples(s.uavs()); })
      .def_property_readonly("hull", [](const python::Session& s) { return mask_array(s.hull()); })
      .def("result", [](const python::Session& s) { return result_dict(s.spec(), s.result()); });
}
