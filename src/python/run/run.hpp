// ncurve.run(): a part program executed as `ncurve run` executes it, its moves as a NumPy array.
#pragma once
#include <pybind11/pybind11.h>

#include "app/run_setup.hpp"

namespace ncurve::python {
namespace py = pybind11;

// Registers ncurve.run, the class ncurve.Run and ncurve.MOVE_KINDS.
void add_run(py::module_& m);
// The program, profile and options an ncurve.Run was made with (parsed); null for another object.
const app::RunInputs* run_inputs(py::handle value);

}  // namespace ncurve::python
