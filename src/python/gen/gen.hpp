// ncurve.gen(): a program for a curve, written and proven as `ncurve gen` writes it.
#pragma once
#include <pybind11/pybind11.h>

namespace ncurve::python {
namespace py = pybind11;

// Registers ncurve.gen and the class ncurve.Gen.
void add_gen(py::module_& m);

}  // namespace ncurve::python
