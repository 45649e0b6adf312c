// The executed blocks of a traced run (ncurve.run(..., trace=True)) as Python reads them: a record
// per step, and the variables at any step rebuilt from what each block wrote (docs/serve.md's
// execution trace, the workbench debugger's rebuilding).
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

#include "machine/trace.hpp"

namespace ncurve::python {
namespace py = pybind11;

// Run.steps: a record per executed block, step k the k-th (file, line, move, level, depth,
// program); `file` indexes `files` (Run.files), to which a file only the trace has is added.
py::array step_records(const machine::ExecutionTrace& trace, std::vector<std::string>& files);

// The variables at step k, the state after k blocks (before block k runs; k = the number of
// blocks: after the last): {number: value or None} with #1..#33 of the level the block runs at,
// and every other variable written so far. IndexError outside 0..blocks.
py::dict variables_at(const machine::ExecutionTrace& trace, std::int64_t step);

}  // namespace ncurve::python
