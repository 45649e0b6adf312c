#include "python/run/steps.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace ncurve::python {
namespace {

struct StepRecord {
  std::int32_t file;   // index into Run.files
  std::uint32_t line;
  std::uint64_t move;  // moves made before the block
  std::int32_t level;  // local variable level of the block (0: the main program's)
  std::int32_t depth;  // calls open around it (0: the main program)
  std::int32_t program;  // O number of the program it is in (-1: none)
};

constexpr std::int32_t kLocals = 33;

py::object value_object(double v) { return std::isnan(v) ? py::object(py::none()) : py::object(py::float_(v)); }

}  // namespace

py::array step_records(const machine::ExecutionTrace& trace, std::vector<std::string>& files) {
  std::vector<std::int32_t> file_index;  // the trace's files in `files`, added where missing
  for (const nc::SourceFile* f : trace.files()) {
    const auto at = std::find(files.begin(), files.end(), f->name());
    file_index.push_back(static_cast<std::int32_t>(at - files.begin()));
    if (at == files.end()) files.push_back(f->name());
  }
  const auto& blocks = trace.blocks();
  py::list names, formats, offsets;
  auto field = [&](const char* name, const char* format, std::size_t offset) {
    names.append(name);
    formats.append(format);
    offsets.append(offset);
  };
  field("file", "<i4", offsetof(StepRecord, file));
  field("line", "<u4", offsetof(StepRecord, line));
  field("move", "<u8", offsetof(StepRecord, move));
  field("level", "<i4", offsetof(StepRecord, level));
  field("depth", "<i4", offsetof(StepRecord, depth));
  field("program", "<i4", offsetof(StepRecord, program));
  py::dict spec;
  spec["names"] = names;
  spec["formats"] = formats;
  spec["offsets"] = offsets;
  spec["itemsize"] = sizeof(StepRecord);
  py::array out(py::dtype::from_args(spec), std::vector<py::ssize_t>{static_cast<py::ssize_t>(blocks.size())}, std::vector<py::ssize_t>{});
  auto* rows = static_cast<StepRecord*>(out.mutable_data());
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const auto& stack = trace.stacks()[blocks[k].stack];
    rows[k] = {file_index[blocks[k].file], blocks[k].line, blocks[k].first_move,
               stack.empty() ? 0 : stack.back().level, static_cast<std::int32_t>(stack.empty() ? 0 : stack.size() - 1),
               stack.empty() ? -1 : stack.back().program};
  }
  return out;
}

StepVariables::StepVariables(std::shared_ptr<const machine::ExecutionTrace> trace) : trace_(std::move(trace)) {
  const auto n = static_cast<std::int64_t>(trace_->blocks().size());
  every_ = std::max<std::int64_t>(64, n / 200);
}

void StepVariables::apply(State& vars, std::int64_t from, std::int64_t to, Cursor& at) const {
  const auto& writes = trace_->writes();
  const auto& entries = trace_->entries();
  for (std::int64_t b = from; b < to; ++b) {
    for (; at.entry < entries.size() && entries[at.entry].block <= b; ++at.entry)
      if (entries[at.entry].block == b)
        for (std::int32_t v = 1; v <= kLocals; ++v) vars.erase({entries[at.entry].level, v});
    for (; at.write < writes.size() && writes[at.write].block <= b; ++at.write)
      vars[{writes[at.write].level, writes[at.write].number}] = writes[at.write].new_value;
  }
}

py::dict StepVariables::at(std::int64_t step) const {
  const auto& blocks = trace_->blocks();
  const auto n = static_cast<std::int64_t>(blocks.size());
  if (step < 0 || step > n)
    throw py::index_error(fmt::format("step {} is outside the run's steps 0..{} (step {}: after the last block){}{}",
                                      step, n, n, trace_->complete() ? "" : "; ", trace_->limit_message()));
  if (snapshots_.empty()) {  // the states at steps 0, every, 2 every, ...: any step is at most `every` blocks away
    State vars;
    Cursor at;
    apply(vars, -1, 0, at);  // the presets
    for (std::int64_t k = 0; k <= n; k += every_) {
      if (k > 0) apply(vars, k - every_, k, at);
      snapshots_.push_back({vars, at});
    }
  }
  auto [vars, at] = snapshots_[static_cast<std::size_t>(step / every_)];
  apply(vars, step / every_ * every_, step, at);
  std::int32_t level = 0;  // of the innermost call the block runs in
  if (n > 0)
    if (const auto& stack = trace_->stacks()[blocks[static_cast<std::size_t>(std::min(step, n - 1))].stack];
        !stack.empty())
      level = stack.back().level;
  py::dict out;
  for (std::int32_t v = 1; v <= kLocals; ++v) {
    const auto it = vars.find({level, v});
    out[py::int_(v)] = it == vars.end() ? py::object(py::none()) : value_object(it->second);
  }
  for (const auto& [key, value] : vars)
    if (key.first < 0) out[py::int_(key.second)] = value_object(value);
  return out;
}

}  // namespace ncurve::python
