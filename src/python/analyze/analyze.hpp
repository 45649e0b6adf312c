// ncurve.analyze(): a program's cycle time as `ncurve analyze` plans it (feed planning, block and
// macro processing, the servo's contour error), the totals as --json and each motion as --blocks.
#pragma once
#include <pybind11/pybind11.h>

namespace ncurve::python {
namespace py = pybind11;

// Registers ncurve.analyze, the class ncurve.Analysis and ncurve.FEED_LIMITS.
void add_analyze(py::module_& m);
// Registers ncurve.circle_test (the circular test, `ncurve analyze circle`).
void add_circle_test(py::module_& m);

}  // namespace ncurve::python
