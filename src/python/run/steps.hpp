// The executed blocks of a traced run (ncurve.run(..., trace=True)) as Python reads them: a record
// per step, and the variables at any step rebuilt from what each block wrote (docs/serve.md's
// execution trace, the workbench debugger's rebuilding).
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <map>
#include <memory>
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
// and every other variable written so far. IndexError outside 0..blocks. States are kept every
// `every` blocks (made at the first call, under the GIL), so that a step costs at most that many
// blocks' writes, as the workbench debugger does it.
class StepVariables {
public:
  explicit StepVariables(std::shared_ptr<const machine::ExecutionTrace> trace);
  py::dict at(std::int64_t step) const;
  const machine::ExecutionTrace& trace() const { return *trace_; }

private:
  using State = std::map<std::pair<std::int32_t, std::int32_t>, double>;  // (level, number); level -1: not a local
  struct Cursor {  // the next level entry and write to apply
    std::size_t entry = 0, write = 0;
  };
  // Blocks from .. to-1 (-1: the presets): each block's new levels cleared, then its writes applied.
  void apply(State& vars, std::int64_t from, std::int64_t to, Cursor& at) const;

  std::shared_ptr<const machine::ExecutionTrace> trace_;
  std::int64_t every_ = 64;
  mutable std::vector<std::pair<State, Cursor>> snapshots_;
};

}  // namespace ncurve::python
