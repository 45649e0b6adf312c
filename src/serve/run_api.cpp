// POST /api/run: the run's summary, its moves as columns, its diagnostics and, asked for, its
// execution trace.
#include <nlohmann/json.hpp>

#include <cstring>
#include <new>
#include <optional>

#include "report/summary.hpp"
#include "serve/api.hpp"
#include "serve/move_columns.hpp"
#include "serve/request.hpp"
#include "serve/trace_json.hpp"

namespace ncurve::serve {

using nlohmann::json;

std::string json_string(const std::string& s) {
  return json(s).dump(-1, ' ', false, json::error_handler_t::replace);
}

Answer error_answer(int status, const std::string& message) {
  json j{{"error", message}, {"status", status}};
  return Answer{status, j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n"};
}

namespace {
// Everything the editor marks: the syntax found on reading (but the one the run alarmed on), the
// warnings, the alarm.
json diagnostics(const report::RunReport& rep) {
  const machine::RunResult& res = *rep.result;
  json out = json::array();
  for (const auto& d : rep.text_problems)
    if (!res.alarm || res.alarm->span.line != d.span.line || res.alarm->span.file != d.span.file ||
        res.alarm->code != d.code)
      out.push_back(report::diagnostic_json(d));
  for (const auto& w : res.warnings) out.push_back(report::diagnostic_json(w));
  if (res.alarm) out.push_back(report::diagnostic_json(*res.alarm));
  return out;
}
}  // namespace

Answer api_run(const ServeConfig& config, const std::string& body, const std::atomic<bool>* cancel) {
  const json j = parse_body(body);
  check_keys(j, {"program", "name", "machine", "set", "param", "max_steps", "max_seconds", "nose_centre", "moves",
                 "trace", "trace_limit", "format"},
             "POST /api/run");
  const app::RunInputs in = run_inputs(config, j);
  const bool want_moves = get_bool(j, "moves", true);
  const bool want_trace = get_bool(j, "trace", false);
  const std::string format = get_string(j, "format").value_or("json");
  if (format != "json" && format != "binary") throw ApiError(400, "\"format\" is \"json\" or \"binary\"");
  std::size_t trace_limit = machine::ExecutionTrace::kDefaultLimit;
  if (auto n = get_number(j, "trace_limit")) {
    if (!(*n >= 1 && *n <= static_cast<double>(machine::ExecutionTrace::kMaxLimit)))
      throw ApiError(400, fmt::format("\"trace_limit\" is 1 to {}", machine::ExecutionTrace::kMaxLimit));
    trace_limit = static_cast<std::size_t>(*n);
  }
  app::RunSetup setup = prepare(in);
  setup.options.cancel = cancel;

  FileTable files;
  std::optional<MoveColumns> moves;
  machine::NullSink no_moves;
  if (want_moves) moves.emplace(setup.profile, files, config.max_moves);
  std::optional<machine::ExecutionTrace> trace;
  if (want_trace) trace.emplace(trace_limit);
  machine::Interpreter interp(setup.profile, *setup.lib, setup.options);
  if (trace) interp.observe(&*trace);
  const machine::RunResult result = interp.run(moves ? static_cast<machine::MoveSink&>(*moves) : no_moves);

  report::RunReport rep;
  rep.source = in.program;
  rep.profile = &setup.profile;
  rep.result = &result;
  rep.stats = report::source_stats(*setup.lib, setup.lib->main()->file.get());
  rep.text_problems = std::move(setup.problems);
  rep.text_problems_left_out = setup.problems_left_out;
  rep.unchecked_lines = setup.unchecked_lines;

  fmt::memory_buffer b;
  auto it = fmt::appender(b);
  // a binary answer: "NCB1", the arrays' length L (u32, little-endian), the arrays, the JSON
  std::string bytes;
  if (format == "binary") bytes.assign("NCB1\0\0\0\0", 8);
  Columns columns{b, format == "binary" ? &bytes : nullptr, 8};
  const bool runaway = result.alarm && result.alarm->code == "NC9000";
  b.push_back('{');
  // the alarm names the command's options; a request sets the same bounds by its keys
  if (runaway)
    fmt::format_to(it, "\"error\":{},\"status\":422,",
                   json_string(result.alarm->message + " (in a request: \"max_steps\" and \"max_seconds\", up to the "
                                                       "server's --max-steps and --max-seconds)"));
  fmt::format_to(it, "\"summary\":{},\"diagnostics\":{}",
                 report::summary_object(rep).dump(-1, ' ', false, json::error_handler_t::replace),
                 diagnostics(rep).dump(-1, ' ', false, json::error_handler_t::replace));
  fmt::format_to(it, ",\"profile\":{}", profile_json(setup.profile).dump(-1, ' ', false, json::error_handler_t::replace));
  if (moves) {
    b.append(std::string_view(",\"moves\":"));
    moves->write_json(columns);
  }
  if (trace) {
    b.append(std::string_view(",\"trace\":"));
    write_trace_json(columns, *trace, files);
  }
  b.append(std::string_view(",\"files\":["));
  for (std::size_t i = 0; i < files.names().size(); ++i) {
    if (i) b.push_back(',');
    b.append(json_string(files.names()[i]));
  }
  b.append(std::string_view("]}\n"));
  const int status = runaway ? 422 : 200;
  if (!columns.blob) return Answer{status, std::string(b.data(), b.size())};
  bytes.resize((bytes.size() + 7) / 8 * 8, '\0');
  const auto length = static_cast<std::uint32_t>(bytes.size() - 8);
  std::memcpy(bytes.data() + 4, &length, sizeof length);
  bytes.append(b.data(), b.size());
  return Answer{status, std::move(bytes), "application/octet-stream"};
}

Answer api_run(const ServeConfig& config, const std::string& body) { return api_run(config, body, nullptr); }

}  // namespace ncurve::serve
