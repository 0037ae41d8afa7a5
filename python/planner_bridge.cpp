#include "planner_bridge.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include <memory>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/planner.hpp"
#include "python_calls.hpp"

namespace hullinspect::python {

namespace py = pybind11;

namespace {

py::array_t<std::int8_t> grid_array(const grid::Grid<std::int8_t>& g) {
  py::array_t<std::int8_t> a({g.height(), g.width()});
  std::copy(g.values().begin(), g.values().end(), a.mutable_data());
  return a;
}

sim::Action parse_action(const py::handle& item, int uav, int t, const std::string& planner) {
  const std::string text = py::str(item);
  if (text == "N") return sim::Action::kNorth;
  if (text == "S") return sim::Action::kSouth;
  if (text == "E") return sim::Action::kEast;
  if (text == "W") return sim::Action::kWest;
  if (text == "hover") return sim::Action::kHover;
  if (text == "change") return sim::Action::kChangePlane;
  throw Error(
      fmt::format("planner '{}': UAV {} at t = {}: unknown action '{}' (expected N, S, E, "
                  "W, hover or change)",
                  planner, uav, t, text));
}

class PythonPlanner final : public planners::Planner {
 public:
  PythonPlanner(std::string name, py::object instance)
      : name_(std::move(name)), instance_(std::move(instance)) {}
  ~PythonPlanner() override {
    py::gil_scoped_acquire gil;
    prior_ = py::object();
    instance_ = py::object();
  }

  void start(const planners::PlannerContext& context) override {
    run_python_call([&] { start_in_python(context); });
  }

  void decide(const sim::PlannerView& view, std::span<sim::Action> actions) override {
    run_python_call([&] { decide_in_python(view, actions); });
  }

 private:
  void start_in_python(const planners::PlannerContext& context) {
    py::gil_scoped_acquire gil;
    const auto& hull = context.hull.mask();
    py::array_t<bool> mask({hull.height(), hull.width()});
    for (int i = 0; i < static_cast<int>(hull.values().size()); ++i) {
      mask.mutable_data()[i] = hull.values()[static_cast<std::size_t>(i)] != 0;
    }
    prior_ = grid_array(context.prior);
    py::list starts;
    for (const auto& c : context.starts) starts.append(py::make_tuple(c.x, c.y));
    const auto& p = context.params;
    py::object ns = py::module_::import("types").attr("SimpleNamespace");
    py::object ctx =
        ns(py::arg("hull") = mask, py::arg("prior") = prior_, py::arg("starts") = starts,
           py::arg("uavs") = p.uavs, py::arg("s1") = p.s1, py::arg("s2") = p.s2,
           py::arg("plane_change_steps") = p.plane_change_steps(),
           py::arg("time_limit") = p.time_limit);
    instance_.attr("start")(ctx);
  }

  void decide_in_python(const sim::PlannerView& view, std::span<sim::Action> actions) {
    py::gil_scoped_acquire gil;
    py::list uavs;
    for (const auto& u : view.uavs) {
      uavs.append(py::make_tuple(u.pos.x, u.pos.y, u.z, u.in_transit(), u.failed));
    }
    py::object ns = py::module_::import("types").attr("SimpleNamespace");
    py::object v = ns(py::arg("t") = view.time, py::arg("map") = grid_array(view.map),
                      py::arg("prior") = prior_, py::arg("uavs") = uavs);
    py::object result = instance_.attr("decide")(v);
    const py::sequence seq = py::reinterpret_borrow<py::sequence>(result);
    if (!py::isinstance<py::sequence>(result) || py::isinstance<py::str>(result) ||
        seq.size() != actions.size()) {
      throw Error(
          fmt::format("planner '{}': decide() at t = {} must return one action per UAV ({} "
                      "strings)",
                      name_, view.time, actions.size()));
    }
    for (std::size_t k = 0; k < actions.size(); ++k) {
      actions[k] = parse_action(seq[k], static_cast<int>(k), view.time, name_);
    }
  }

  std::string name_;
  py::object instance_;
  py::object prior_;
};

struct NoOptions {};

}  // namespace

void register_python_planner(const std::string& name, py::object cls,
                             const std::string& description) {
  if (planners::planners().contains(name)) {
    throw ParameterError("algorithm", fmt::format("planner '{}' is already registered", name));
  }
  // The class object lives as long as the registry (the process); it is only touched with the GIL.
  auto holder = std::shared_ptr<py::object>(new py::object(std::move(cls)), [](py::object* o) {
    if (Py_IsInitialized()) {
      py::gil_scoped_acquire gil;
      delete o;
    }
  });
  planners::planners().add(make_entry<planners::Planner, NoOptions>(
      name, description, Params<NoOptions>(name), [name, holder](const NoOptions&) {
        std::unique_ptr<planners::Planner> planner;
        run_python_call([&] {
          py::gil_scoped_acquire gil;
          planner = std::make_unique<PythonPlanner>(name, (*holder)());
        });
        return planner;
      }));
}

}  // namespace hullinspect::python
