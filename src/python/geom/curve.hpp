// ncurve.curve(): a curve of the catalogue (or expr) sampled as NumPy arrays: points, first and
// second derivatives, curvature, the curve `ncurve gen` and `analyze --curve` take.
#pragma once
#include <pybind11/pybind11.h>

namespace ncurve::python {
namespace py = pybind11;

// Registers ncurve.curve and the class ncurve.CurveSamples.
void add_curve(py::module_& m);

}  // namespace ncurve::python
