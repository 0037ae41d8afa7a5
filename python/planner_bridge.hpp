#pragma once
// Python planners as registry entries: a planners::Planner that forwards start/decide to an
// instance of a hullinspect.Planner subclass, holding the GIL only while Python runs.

#include <pybind11/pybind11.h>

#include <string>

namespace hullinspect::python {

/// Registers `cls` (a hullinspect.Planner subclass) as planner `name`; each mission gets a new
/// instance. ParameterError if the name is taken.
void register_python_planner(const std::string& name, pybind11::object cls,
                             const std::string& description);

}  // namespace hullinspect::python
