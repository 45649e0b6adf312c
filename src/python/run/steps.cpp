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

py::dict variables_at(const machine::ExecutionTrace& trace, std::int64_t step) {
  const auto& blocks = trace.blocks();
  const auto n = static_cast<std::int64_t>(blocks.size());
  if (step < 0 || step > n)
    throw py::index_error(fmt::format("step {} is outside the run's steps 0..{} (step {}: after the last block){}{}",
                                      step, n, n, trace.complete() ? "" : "; ", trace.limit_message()));
  // the presets and blocks 0..step-1: each block's new levels cleared, then its writes applied
  std::map<std::pair<std::int32_t, std::int32_t>, double> vars;  // (level, number); level -1 for non-locals
  const auto& writes = trace.writes();
  const auto& entries = trace.entries();
  std::size_t w = 0, e = 0;
  for (std::int64_t b = -1; b < step; ++b) {
    for (; e < entries.size() && entries[e].block <= b; ++e)
      if (entries[e].block == b)
        for (std::int32_t v = 1; v <= kLocals; ++v) vars.erase({entries[e].level, v});
    for (; w < writes.size() && writes[w].block <= b; ++w) vars[{writes[w].level, writes[w].number}] = writes[w].new_value;
  }
  std::int32_t level = 0;  // of the innermost call the block runs in
  if (n > 0)
    if (const auto& stack = trace.stacks()[blocks[static_cast<std::size_t>(std::min(step, n - 1))].stack]; !stack.empty())
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
