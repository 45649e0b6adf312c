// ncurve.verify(): a program's moves cut into the stock of its setup, `ncurve run --verify
// --setup FILE` (docs/verify.md): the findings as diagnostics, the cut part as arrays (a mill's
// Z-map, a lathe's half-section).
#pragma once
#include <pybind11/pybind11.h>

namespace ncurve::python {
namespace py = pybind11;

// Registers ncurve.verify and the class ncurve.Verification.
void add_verify(py::module_& m);

}  // namespace ncurve::python
