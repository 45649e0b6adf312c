// ncurve.Diagnostic: one alarm, warning or syntax problem as Python reads it (file, line, column,
// code, message, severity, the block quoted), its str() the CLI's text of it.
#pragma once
#include <pybind11/pybind11.h>

#include <vector>

#include "machine/interpreter.hpp"
#include "nc/diagnostic.hpp"

namespace ncurve::python {
namespace py = pybind11;

// Registers the class ncurve.Diagnostic.
void add_diagnostic_class(py::module_& m);
// A Python ncurve.Diagnostic holding d's fields (the class must be registered).
py::object diagnostic_object(const nc::Diagnostic& d);
// A run's diagnostics in the CLI's order: the files' syntax problems, the run's warnings, then its
// alarm, which `alarm` is also set to (None without one).
py::list run_diagnostics(const std::vector<nc::Diagnostic>& problems, const machine::RunResult& result, py::object& alarm);

}  // namespace ncurve::python
