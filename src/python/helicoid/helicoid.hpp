// ncurve.helicoid(): disc-cutter locations for a helical surface, `ncurve helicoid` (the helicoid
// paper's minimum directed distance), the contact table as a NumPy structured array.
#pragma once
#include <pybind11/pybind11.h>

namespace ncurve::python {
namespace py = pybind11;

// Registers ncurve.helicoid and the class ncurve.Helicoid.
void add_helicoid(py::module_& m);

}  // namespace ncurve::python
