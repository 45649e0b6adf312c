// POST /api/gen and POST /api/analyze: `ncurve gen --json` and `ncurve analyze --json` over HTTP.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <new>
#include <optional>

#include "app/analyze_command.hpp"
#include "app/gen_command.hpp"
#include "base/bounds.hpp"
#include "geom/curve.hpp"
#include "motion/planner.hpp"
#include "motion/servo.hpp"
#include "report/summary.hpp"
#include "serve/api.hpp"
#include "serve/request.hpp"
#include "serve/run_settings.hpp"
#include "serve/tool_columns.hpp"

namespace ncurve::serve {

using nlohmann::json;

namespace {
constexpr double kMaxServoTicks = 50e6;  // as analyze --max-ticks' default
constexpr long kMaxGenMoves = 5'000'000;
constexpr std::size_t kMostCurvePoints = 200'000;  // /api/gen's "reference" polyline

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n"; }
}  // namespace

Answer api_curves() {
  json list = json::array();
  for (const geom::CurveSpec& c : geom::catalogue()) {
    json params = json::array();
    for (const geom::ParamSpec& p : c.params) params.push_back({{"name", p.name}, {"value", p.value}, {"doc", p.doc}});
    list.push_back({{"name", c.name}, {"doc", c.doc}, {"x", c.x}, {"y", c.y}, {"z", c.z}, {"from", c.from},
                    {"to", c.to}, {"t_doc", c.t_doc}, {"lathe", c.lathe}, {"params", params}});
  }
  // what `ncurve gen` takes without --form and --tol
  const app::GenArgs defaults;
  return Answer{200, dump(json{{"curves", list}, {"default_form", defaults.form}, {"default_tol", defaults.tol}})};
}

Answer api_gen(const ServeConfig& config, const std::string& body) {
  const json j = parse_body(body);
  check_keys(j, {"curve", "params", "x", "y", "z", "t", "from", "to", "tol", "form", "lines", "machine", "feed", "depth",
                 "step_down", "clearance", "program_number", "tool_radius", "tip", "side", "cycle_program",
                 "macro_only", "tool", "spindle", "spindle_ccw", "css", "max_rpm", "coolant", "inch", "max_moves",
                 "param", "tool_offsets"},
             "POST /api/gen");
  app::GenArgs a;
  a.curve = get_string(j, "curve", true).value();
  a.x = get_string(j, "x").value_or("");
  a.y = get_string(j, "y").value_or("");
  a.z = get_string(j, "z").value_or("");
  a.t_range = get_string(j, "t").value_or("");
  a.from = get_number(j, "from");
  a.to = get_number(j, "to");
  a.form = get_string(j, "form").value_or(a.form);
  a.lines = get_string(j, "lines").value_or(a.lines);
  a.side = get_string(j, "side").value_or(a.side);
  auto number = [&](const char* key, auto& field) {
    if (auto v = get_number(j, key)) field = static_cast<std::remove_reference_t<decltype(field)>>(*v);
  };
  number("tol", a.tol);
  number("feed", a.feed);
  number("depth", a.depth);
  number("step_down", a.step_down);
  number("clearance", a.clearance);
  number("program_number", a.program_number);
  number("tool_radius", a.tool_radius);
  number("tip", a.tip);
  number("cycle_program", a.cycle_program);
  number("tool", a.tool);
  number("spindle", a.spindle);
  number("css", a.css);
  number("max_rpm", a.max_rpm);
  number("max_moves", a.max_moves);
  if (a.max_moves < 1 || a.max_moves > kMaxGenMoves)
    throw ApiError(400, fmt::format("\"max_moves\" is 1 to {}", kMaxGenMoves));
  a.macro_only = get_bool(j, "macro_only", false);
  a.spindle_ccw = get_bool(j, "spindle_ccw", false);
  a.coolant = get_bool(j, "coolant", false);
  a.inch = get_bool(j, "inch", false);
  if (j.contains("machine")) {
    app::RunInputs in;
    choose_profile(config, j, in);
    a.machine = in.machine;
    a.machine_text = in.machine_text;
  } else {
    a.machine = config.machine;
  }
  std::vector<std::string> extras;  // the curve's parameters, as the command line's --NAME VALUE
  if (auto it = j.find("params"); it != j.end() && !it->is_null()) {
    if (!it->is_object()) throw ApiError(400, "\"params\" must be an object, e.g. {\"a\": 5}");
    for (const auto& [k, v] : it->items()) {
      if (!v.is_number()) throw ApiError(400, fmt::format("\"params\": the value of \"{}\" must be a number", k));
      extras.push_back("--" + k);
      extras.push_back(fmt::format("{}", v.get<double>()));
    }
  }
  std::optional<app::GenJob> job;
  try {
    job.emplace(app::gen_job(a, extras, "POST /api/gen", {}));
  } catch (const std::bad_alloc&) {
    throw;  // 507
  } catch (const std::exception& e) {
    throw ApiError(400, e.what());
  }
  // the control the program is generated for and measured on: the run's parameters and tool offsets
  try {
    app::apply_parameters(job->options.profile, option_values(j, "param"));
  } catch (const std::runtime_error& e) {
    throw ApiError(400, e.what());
  }
  apply_tool_offsets(j, job->options.profile);
  // what the command line prints as "warning: ..." before it generates, in the answer or the error
  const std::vector<std::string> warnings = app::gen_warnings(*job);
  gen::Result r;
  try {
    r = gen::generate(job->curve, job->options);
  } catch (const std::bad_alloc&) {
    throw;  // 507
  } catch (const std::exception& e) {
    return Answer{422, dump(json{{"error", e.what()}, {"status", 422}, {"warnings", warnings}})};
  }
  const std::string& program = a.macro_only ? r.macro : r.text;
  json out = app::gen_json(*job, r, &program);
  out["warnings"] = warnings;
  // the curve and each move's deviation, for the page to draw (a tenth of the tolerance, with room)
  const CurvePolyline curve = curve_polyline(r.cutter_centre ? *r.cutter_centre : job->curve, r.placement,
                                             job->options.tol / 20, kMostCurvePoints);
  std::string head = dump(out);  // {...}\n
  fmt::memory_buffer b;
  b.append(std::string_view(head).substr(0, head.rfind('}')));
  write_gen_geometry(b, curve, r.stats, job->options.profile);
  b.append(std::string_view("}\n"));
  return Answer{200, std::string(b.data(), b.size())};
}

Answer api_analyze(const ServeConfig& config, const std::string& body, const std::atomic<bool>* cancel) {
  const json j = parse_body(body);
  check_keys(j, {"program", "name", "machine", "set", "param", "max_steps", "max_seconds", "nose_centre", "servo",
                 "moves", "lib", "tool_offsets"},
             "POST /api/analyze");
  const app::RunInputs in = run_inputs(config, j);
  const bool servo = get_bool(j, "servo", false);
  std::optional<FeedColumns> feeds;
  if (get_bool(j, "moves", false)) feeds.emplace(config.max_moves);
  app::RunSetup setup = prepare(in);
  setup.options.cancel = cancel;
  apply_tool_offsets(j, setup.profile);
  const machine::MachineProfile& profile = setup.profile;
  std::optional<motion::ServoSim> sim;
  if (servo) sim.emplace(profile);
  motion::Planner planner(profile, [&](const motion::BlockTime& b) {
    if (feeds) feeds->planned(b);
    if (!sim) return;
    if ((b.start + b.seconds) / profile.servo.period > kMaxServoTicks)
      throw base::BoundExceeded(fmt::format("\"servo\": the program runs longer than {:.3g} servo periods ({:.4g} s of "
                                            "machine time); ncurve analyze --servo --max-ticks runs it longer",
                                            kMaxServoTicks, kMaxServoTicks * profile.servo.period));
    sim->on_block(b);
  });
  struct Tee final : machine::MoveSink {  // the feeds see each move before the planner times it
    FeedColumns* feeds;
    motion::Planner& planner;
    Tee(FeedColumns* f, motion::Planner& p) : feeds(f), planner(p) {}
    void on_move(const machine::Move& m) override {
      if (feeds) feeds->made(m);
      planner.on_move(m);
    }
    void stopped(const nc::Diagnostic& d) override { planner.stopped(d); }
  } tee(feeds ? &*feeds : nullptr, planner);
  machine::Interpreter interp(profile, *setup.lib, setup.options);
  machine::RunResult result;
  try {
    result = interp.run(tee);
    planner.finish();
  } catch (const base::BoundExceeded& e) {
    throw ApiError(422, e.what());
  }
  if (sim) app::settle(*sim, profile);
  json out = app::analyze_json(in.program, profile, planner.totals(), sim ? &*sim : nullptr);
  out["ok"] = result.ok();
  out["alarm"] = result.alarm ? report::diagnostic_json(*result.alarm) : json(nullptr);
  const bool runaway = result.alarm && result.alarm->code == "NC9000";
  if (runaway) {
    out["error"] = result.alarm->message;
    out["status"] = 422;
  }
  if (!feeds) return Answer{runaway ? 422 : 200, dump(out)};
  std::string head = dump(out);
  fmt::memory_buffer b;
  b.append(std::string_view(head).substr(0, head.rfind('}')));
  b.append(std::string_view(",\"moves\":"));
  feeds->write_json(b);
  b.append(std::string_view("}\n"));
  return Answer{runaway ? 422 : 200, std::string(b.data(), b.size())};
}

Answer api_analyze(const ServeConfig& config, const std::string& body) { return api_analyze(config, body, nullptr); }

}  // namespace ncurve::serve
