// POST /api/run: the run's summary, its moves as columns, its diagnostics and, asked for, its
// execution trace.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <new>
#include <optional>

#include "app/run_verify.hpp"
#include "report/backplot_data.hpp"
#include "report/path_plot.hpp"
#include "report/summary.hpp"
#include "report/verify_report.hpp"
#include "serve/api.hpp"
#include "serve/move_columns.hpp"
#include "serve/request.hpp"
#include "serve/run_settings.hpp"
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
// "curve": {"name", "params": {..}, "x", "y", "z", "t", "from", "to"}: the design's curve, as ncurve run --curve
void read_curve(const json& c, app::VerifyArgs& va) {
  if (!c.is_object()) throw ApiError(400, "\"curve\" must be an object, e.g. {\"name\": \"ellipse\", \"params\": {\"a\": 20}}");
  check_keys(c, {"name", "params", "x", "y", "z", "t", "from", "to"}, "\"curve\"");
  va.curve.name = get_string(c, "name", true).value();
  va.curve.x = get_string(c, "x").value_or("");
  va.curve.y = get_string(c, "y").value_or("");
  va.curve.z = get_string(c, "z").value_or("");
  va.curve.t_range = get_string(c, "t").value_or("");
  va.curve.from = get_number(c, "from");
  va.curve.to = get_number(c, "to");
  va.curve.command = "POST /api/run \"curve\"";
  if (auto it = c.find("params"); it != c.end() && !it->is_null()) {
    if (!it->is_object()) throw ApiError(400, "\"curve\": \"params\" must be an object, e.g. {\"a\": 5}");
    for (const auto& [k, v] : it->items()) {
      if (!v.is_number()) throw ApiError(400, fmt::format("\"curve\": the value of \"{}\" must be a number", k));
      va.curve_extras.push_back("--" + k);
      va.curve_extras.push_back(fmt::format("{}", v.get<double>()));
    }
  }
}

}  // namespace

Answer api_run(const ServeConfig& config, const std::string& body, const std::atomic<bool>* cancel) {
  const json j = parse_body(body);
  check_keys(j, {"program", "name", "machine", "set", "param", "max_steps", "max_seconds", "nose_centre", "moves",
                 "trace", "trace_limit", "format", "verify", "setup", "setup_name", "resolution", "cells", "cut_moves",
                 "curve", "tol", "wall", "lib", "tool_offsets"},
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
  // the profile as its file gives it; the run on it with the request's tool offsets
  const json profile = profile_json(setup.profile);
  apply_tool_offsets(j, setup.profile);
  // the part: the setup's stock (or the default box) cut by the moves, its findings among the warnings
  app::VerifyArgs va;
  va.verify = get_bool(j, "verify", false);
  va.setup_text = get_string(j, "setup");
  va.setup = get_string(j, "setup_name").value_or(va.setup_text ? "setup.toml" : "");
  if (auto r = get_number(j, "resolution")) {
    if (!(*r >= 1e-3 && *r <= 1e3)) throw ApiError(400, "\"resolution\" is a Z-map cell of 0.001 to 1000 mm");
    va.resolution = *r;
  }
  if (auto n = get_number(j, "cells")) {
    if (!(*n >= 10 && *n <= 2000 && *n == std::floor(*n))) throw ApiError(400, "\"cells\" is a whole 10 to 2000");
    va.cells = static_cast<int>(*n);
  }
  if (auto n = get_number(j, "cut_moves")) {
    if (!(*n >= 0 && *n <= 1e15)) throw ApiError(400, "\"cut_moves\" is a count of motions, 0 or more");
    va.cut_moves = static_cast<std::uint64_t>(*n);
  }
  if (auto c = j.find("curve"); c != j.end() && !c->is_null()) read_curve(*c, va);
  if (auto t = get_number(j, "tol")) {
    if (!(*t >= 1e-6 && *t <= 1e3)) throw ApiError(400, "\"tol\" is 0.000001 to 1000 mm");
    va.tol = *t;
  }
  va.wall = get_string(j, "wall").value_or(va.wall);
  if (va.wall != "auto" && va.wall != "groove" && va.wall != "edge")
    throw ApiError(400, "\"wall\" is \"auto\", \"groove\" or \"edge\"");
  va.max_moves = std::min<std::size_t>(va.max_moves, config.max_moves);
  va.most_cells = kMostPartCells;
  std::optional<app::RunVerification> verify;
  if (va.on()) {
    try {
      verify.emplace(va, setup.profile, *setup.lib, setup.options);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      throw ApiError(400, e.what());
    }
  }

  FileTable files;
  std::optional<MoveColumns> moves;
  machine::NullSink no_moves;
  if (want_moves) moves.emplace(setup.profile, files, config.max_moves);
  std::optional<machine::ExecutionTrace> trace;
  if (want_trace) trace.emplace(trace_limit);
  machine::Interpreter interp(setup.profile, *setup.lib, setup.options);
  if (trace) interp.observe(&*trace);
  if (moves && !in.nose_centre) moves->follow_nose_tip([&interp] { return interp.nose_tip_now(); });
  machine::MoveSink& shown = moves ? static_cast<machine::MoveSink&>(*moves) : no_moves;
  std::optional<report::TeeSink> tee;
  if (verify && verify->sink()) tee.emplace(shown, *verify->sink());
  machine::RunResult result = interp.run(tee ? static_cast<machine::MoveSink&>(*tee) : shown);
  if (verify) verify->finish(result);

  report::RunReport rep = app::run_report(setup, in.program, result, verify ? &verify->report() : nullptr);

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
  fmt::format_to(it, ",\"profile\":{}", profile.dump(-1, ' ', false, json::error_handler_t::replace));
  if (moves) {
    b.append(std::string_view(",\"moves\":"));
    moves->write_json(columns);
  }
  if (trace) {
    b.append(std::string_view(",\"trace\":"));
    write_trace_json(columns, *trace, files);
  }
  if (verify && verify->map()) {
    json part = report::part_json(sim::part_grid(*verify->map()));
    if (verify->report().curve) part["deviation"] = report::deviation_json(*verify->report().curve);
    fmt::format_to(it, ",\"part\":{}", part.dump());
  }
  if (verify && verify->section())
    fmt::format_to(it, ",\"part\":{}", report::lathe_part_json(report::lathe_part(*verify->section())).dump());
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
