#include "serve/trace_json.hpp"

namespace ncurve::serve {

using machine::CallFrame;
using machine::ExecutionTrace;

namespace {

const char* kind_name(CallFrame::Kind k) {
  return k == CallFrame::main ? "main" : k == CallFrame::subprogram ? "subprogram" : "macro";
}

template <class T, class F>
std::vector<T> column(const auto& rows, F field) {
  std::vector<T> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(field(r));
  return out;
}

}  // namespace

void write_trace_json(Columns& out, const ExecutionTrace& t, FileTable& files) {
  fmt::memory_buffer& b = out.json;
  auto it = fmt::appender(b);
  auto num = [&](double v) {  // variables exactly as the program computed them (shortest form)
    if (std::isnan(v)) b.append(std::string_view("null"));
    else fmt::format_to(it, "{}", v == 0 ? 0.0 : v);
  };
  auto whole = [&](auto v) { fmt::format_to(it, "{}", static_cast<long long>(v)); };
  std::vector<std::uint32_t> file_index;
  for (const nc::SourceFile* f : t.files()) file_index.push_back(files.index(f));

  fmt::format_to(it, "{{\"complete\":{},\"limit\":{},\"blocks_recorded\":{},\"moves\":{},",
                 t.complete() ? "true" : "false", t.limit(), t.blocks().size(), t.total_moves());
  if (!t.complete()) fmt::format_to(it, "\"message\":{},", json_string(t.limit_message()));

  const auto& blocks = t.blocks();
  b.append(std::string_view("\"blocks\":{"));
  put_array(out, "file", column<std::uint32_t>(blocks, [&](const ExecutionTrace::Block& r) { return file_index[r.file]; }),
            whole);
  b.push_back(',');
  put_array(out, "line", column<std::uint32_t>(blocks, [](const ExecutionTrace::Block& r) { return r.line; }), whole);
  b.push_back(',');
  put_array(out, "stack", column<std::uint32_t>(blocks, [](const ExecutionTrace::Block& r) { return r.stack; }), whole);
  b.push_back(',');
  put_array(out, "move", column<std::uint64_t>(blocks, [](const ExecutionTrace::Block& r) { return r.first_move; }),
            whole);
  b.append(std::string_view("},\"stacks\":["));
  bool first_stack = true;
  for (const auto& stack : t.stacks()) {
    if (!first_stack) b.push_back(',');
    first_stack = false;
    b.push_back('[');
    for (std::size_t i = 0; i < stack.size(); ++i) {
      const CallFrame& f = stack[i];
      fmt::format_to(it, "{}{{\"kind\":\"{}\",\"program\":{},\"level\":{}", i ? "," : "", kind_name(f.kind), f.program,
                     f.level);
      if (f.call_file)
        fmt::format_to(it, ",\"call_file\":{},\"call_line\":{}", files.index(f.call_file), f.call_line);
      if (f.custom) b.append(std::string_view(",\"custom\":true"));
      if (f.modal) b.append(std::string_view(",\"modal\":true"));
      b.push_back('}');
    }
    b.push_back(']');
  }
  const auto& w = t.writes();
  b.append(std::string_view("],\"writes\":{"));
  put_array(out, "block", column<std::int64_t>(w, [](const ExecutionTrace::Write& r) { return r.block; }), whole);
  b.push_back(',');
  put_array(out, "var", column<std::int32_t>(w, [](const ExecutionTrace::Write& r) { return r.number; }), whole);
  b.push_back(',');
  put_array(out, "level", column<std::int32_t>(w, [](const ExecutionTrace::Write& r) { return r.level; }), whole);
  b.push_back(',');
  put_array(out, "old", column<double>(w, [](const ExecutionTrace::Write& r) { return r.old_value; }), num);
  b.push_back(',');
  put_array(out, "new", column<double>(w, [](const ExecutionTrace::Write& r) { return r.new_value; }), num);
  const auto& e = t.entries();
  b.append(std::string_view("},\"levels\":{"));
  put_array(out, "block", column<std::int64_t>(e, [](const ExecutionTrace::Entry& r) { return r.block; }), whole);
  b.push_back(',');
  put_array(out, "level", column<std::int32_t>(e, [](const ExecutionTrace::Entry& r) { return r.level; }), whole);
  const auto& m = t.modal_changes();
  b.append(std::string_view("},\"modal\":{"));
  std::vector<int> vars(machine::kModalVariables.begin(), machine::kModalVariables.end());
  put_array(out, "variables", vars, whole);
  b.push_back(',');
  std::vector<double> initial;
  for (const auto& v : t.initial_modal()) initial.push_back(ExecutionTrace::encode(v));
  put_array(out, "initial", initial, num);
  b.push_back(',');
  put_array(out, "block", column<std::int64_t>(m, [](const ExecutionTrace::ModalChange& r) { return r.block; }), whole);
  b.push_back(',');
  put_array(out, "var", column<std::int32_t>(m, [](const ExecutionTrace::ModalChange& r) { return r.variable; }), whole);
  b.push_back(',');
  put_array(out, "value", column<double>(m, [](const ExecutionTrace::ModalChange& r) { return r.value; }), num);
  const auto& r = t.reads();
  b.append(std::string_view("},\"reads\":{"));
  put_array(out, "block", column<std::int64_t>(r, [](const ExecutionTrace::Read& x) { return x.block; }), whole);
  b.push_back(',');
  put_array(out, "var", column<std::int32_t>(r, [](const ExecutionTrace::Read& x) { return x.number; }), whole);
  b.push_back(',');
  put_array(out, "value", column<double>(r, [](const ExecutionTrace::Read& x) { return x.value; }), num);
  const auto& tc = t.tool_changes();
  b.append(std::string_view("},\"tool\":{"));
  put_array(out, "block", column<std::int64_t>(tc, [](const ExecutionTrace::ToolChange& x) { return x.block; }), whole);
  b.push_back(',');
  put_array(out, "offset", column<std::int32_t>(tc, [](const ExecutionTrace::ToolChange& x) { return x.tool.offset; }),
            whole);
  b.push_back(',');
  put_array(out, "radius", column<double>(tc, [](const ExecutionTrace::ToolChange& x) { return x.tool.radius; }), num);
  b.push_back(',');
  put_array(out, "length", column<double>(tc, [](const ExecutionTrace::ToolChange& x) { return x.tool.length; }), num);
  b.push_back(',');
  put_array(out, "tip", column<std::int32_t>(tc, [](const ExecutionTrace::ToolChange& x) { return x.tool.tip; }), whole);
  b.append(std::string_view("}}"));
}

}  // namespace ncurve::serve
