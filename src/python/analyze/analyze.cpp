#include "python/analyze/analyze.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>

#include <algorithm>
#include <optional>

#include "app/analyze_command.hpp"
#include "app/analyze_contour.hpp"
#include "app/analyze_shape.hpp"
#include "app/run_verify.hpp"
#include "base/bounds.hpp"
#include "python/common/cli_args.hpp"
#include "python/common/diagnostic.hpp"
#include "python/common/run_args.hpp"
#include "python/run/run.hpp"

namespace ncurve::python {
namespace {

// What analyze() returns.
struct Analysis {
  py::dict summary;   // `ncurve analyze --json`
  py::array blocks;   // a record a motion, the columns of --blocks
  py::list files;     // the names blocks["file"] indexes
  py::list diagnostics;
  py::object alarm = py::none();
  bool ok = true;
};

// A motion's timing as --blocks writes it (a row of its CSV), in a record of fixed size.
struct BlockRecord {
  std::int32_t file;
  std::uint32_t line;
  std::uint8_t kind;   // ncurve.MOVE_KINDS
  std::uint8_t limit;  // ncurve.FEED_LIMITS
  bool starved;
  std::uint8_t pad = 0;
  double length_mm, programmed_mm_min, cap_mm_min, v_in_mm_min, v_peak_mm_min, v_out_mm_min, start_s, seconds, wait_s,
      settle_s;
};

py::dtype block_dtype() {
  py::list names, formats, offsets;
  auto field = [&](const char* name, const char* format, std::size_t offset) {
    names.append(name);
    formats.append(format);
    offsets.append(offset);
  };
  field("file", "<i4", offsetof(BlockRecord, file));
  field("line", "<u4", offsetof(BlockRecord, line));
  field("kind", "u1", offsetof(BlockRecord, kind));
  field("length_mm", "<f8", offsetof(BlockRecord, length_mm));
  field("programmed_mm_min", "<f8", offsetof(BlockRecord, programmed_mm_min));
  field("cap_mm_min", "<f8", offsetof(BlockRecord, cap_mm_min));
  field("limit", "u1", offsetof(BlockRecord, limit));
  field("v_in_mm_min", "<f8", offsetof(BlockRecord, v_in_mm_min));
  field("v_peak_mm_min", "<f8", offsetof(BlockRecord, v_peak_mm_min));
  field("v_out_mm_min", "<f8", offsetof(BlockRecord, v_out_mm_min));
  field("start_s", "<f8", offsetof(BlockRecord, start_s));
  field("seconds", "<f8", offsetof(BlockRecord, seconds));
  field("wait_s", "<f8", offsetof(BlockRecord, wait_s));
  field("settle_s", "<f8", offsetof(BlockRecord, settle_s));
  field("starved", "?", offsetof(BlockRecord, starved));
  py::dict spec;
  spec["names"] = names;
  spec["formats"] = formats;
  spec["offsets"] = offsets;
  spec["itemsize"] = sizeof(BlockRecord);
  return py::dtype::from_args(spec);
}

const char* const kSignature =
    "analyze(program, *, machine=None, lib=(), set={}, params={}, max_steps=None, max_seconds=None, servo=False, "
    "kv=None, feed_forward=None, max_ticks=None, curve=None, t=None, tol=None, programmed=False, setup=None, "
    "wall=None, max_moves=None, **curve_params) -> ncurve.Analysis";
const char* const kHead =
    "How long a program runs on a machine and how far the machine strays from it: `ncurve analyze PROGRAM "
    "[options] --json --blocks FILE` (docs/analyze.md) from Python.";
const char* const kProgram =
    "as run() takes it (its text, or its file), or an ncurve.Run, whose program, machine and options "
    "are analysed again (then give none of machine .. max_seconds).";
const char* const kTail =
    "Returns an ncurve.Analysis: `summary` (the dict of `ncurve analyze --json`: cycle_time_s, motion_s, wait_s, "
    "..., and with servo=True contour_error), `blocks` (a NumPy structured array, a record a motion with the "
    "columns of --blocks: file (index into `files`), line, kind (ncurve.MOVE_KINDS), length_mm, "
    "programmed_mm_min, cap_mm_min, limit (ncurve.FEED_LIMITS), v_in_mm_min, v_peak_mm_min, v_out_mm_min, "
    "start_s, seconds, wait_s, settle_s, starved), `files`, `diagnostics`, `alarm`, `ok`. With curve, the summary "
    "has the shape error against it and the part cut (`shape`, `part`, as --json has them); a contour that does "
    "not follow the curve raises RuntimeError with the CLI's message. A program that stops on "
    "an alarm returns what was planned up to it and the alarm (the CLI prints the alarm and no totals). A bad "
    "argument raises ValueError with the CLI's message. The GIL is released while it works.";
// the run's options (as run() takes them), then analyze's own
const char* const kRunOptions[] = {"--machine", "--lib", "--set", "--param", "--max-steps", "--max-seconds"};
const char* const kOwnOptions[][3] = {
    {"servo", "--servo", ""},
    {"kv", "--kv", " One gain, or a list of two."},
    {"feed_forward", "--feed-forward", ""},
    {"max_ticks", "--max-ticks", ""},
    {"curve", "--curve", " Its parameters as keywords (a=40; expr's x, y, z as strings), as gen() takes them."},
    {"t", "--from", " (FROM, TO): --from and --to (--t FROM:TO for expr)."},
    {"tol", "--tol", ""},
    {"programmed", "--programmed", ""},
    {"setup", "--setup", ""},
    {"wall", "--wall", ""},
    {"max_moves", "--max-moves", ""}};

std::string analyze_doc() {
  app::AnalyzeArgs args;
  CLI::App app;
  app::add_analyze_command(app, args);
  std::string doc = std::string(kSignature) + "\n\n" + wrapped(kHead, 0) + "\nArguments (the CLI's option in brackets):\n" +
                    "  program\n" + wrapped(kProgram, 6);
  const char* const python[] = {"machine", "lib", "set", "params", "max_steps", "max_seconds"};
  for (std::size_t i = 0; i < std::size(kRunOptions); ++i)
    doc += fmt::format("  {}\n", python[i]) +
           wrapped(fmt::format("{}. As run() takes it. [{}]", args.command->get_option(kRunOptions[i])->get_description(),
                               kRunOptions[i]),
                   6);
  for (const auto& [name, option, more] : kOwnOptions)
    doc += fmt::format("  {}\n", name) +
           wrapped(fmt::format("{}.{} [{}]", args.command->get_option(option)->get_description(), more, option), 6);
  return doc + "\n" + wrapped(kTail, 0);
}

Analysis analyze(const py::object& program, const py::object& machine, const py::object& lib, const py::object& set,
                 const py::object& params, const py::object& max_steps, const py::object& max_seconds, bool servo,
                 const py::object& kv, const py::object& feed_forward, const py::object& max_ticks,
                 const py::object& curve_name, const py::object& t, const py::object& tol, bool programmed,
                 const py::object& setup_file, const py::object& wall, const py::object& max_moves,
                 const py::kwargs& curve_params) {
  app::AnalyzeArgs args;
  CLI::App app;
  app::add_analyze_command(app, args);
  const app::RunInputs* of_run = run_inputs(program);
  std::optional<RunWords> given;
  std::vector<std::string> words{"analyze"};
  if (of_run) {
    const bool more = !machine.is_none() || !max_steps.is_none() || !max_seconds.is_none() ||
                      !(py::isinstance<py::tuple>(lib) && py::len(lib) == 0) ||
                      !(py::isinstance<py::dict>(set) && py::len(set) == 0) ||
                      !(py::isinstance<py::dict>(params) && py::len(params) == 0);
    if (more) throw py::type_error("analyze(run): the Run brings its program, machine and options; give none of them");
    words.push_back("-");
  } else {
    given = run_words(program, machine, lib, set, params, max_steps, max_seconds, false);
    words.insert(words.end(), given->words.begin(), given->words.end());
  }
  if (servo) words.push_back("--servo");
  for (const std::string& k : gains(kv)) words.push_back("--kv=" + k);
  if (!feed_forward.is_none()) words.push_back("--feed-forward=" + option_text(feed_forward, "feed_forward"));
  if (!max_ticks.is_none()) words.push_back("--max-ticks=" + option_text(max_ticks, "max_ticks"));
  if (!tol.is_none()) words.push_back("--tol=" + option_text(tol, "tol"));
  if (programmed) words.push_back("--programmed");
  if (!setup_file.is_none()) words.push_back("--setup=" + option_text(setup_file, "setup"));
  if (!wall.is_none()) words.push_back("--wall=" + option_text(wall, "wall"));
  if (!max_moves.is_none()) words.push_back("--max-moves=" + option_text(max_moves, "max_moves"));
  add_curve_words(words, curve_name, t, curve_params, "analyze");
  parse_options(app, words);
  const std::vector<std::string> extras = args.command->remaining();
  if (args.curve.name.empty() && args.tol > 0)  // the CLI's words
    throw py::value_error("--shape-csv, --shape-plot and --tol need a nominal curve (--curve NAME ...)");
  if (of_run) {
    args.in = *of_run;
  } else {
    given->apply(args.in);
  }

  std::optional<app::RunSetup> setup;
  std::vector<BlockRecord> rows;
  std::vector<std::string> files;
  machine::RunResult result;
  nlohmann::json summary;
  std::string refused, failed;  // why the CLI would exit 2, 1
  {
    py::gil_scoped_release free_python;
    try {
      setup.emplace(app::prepare_run(args.in));
      app::apply_servo_options(setup->profile, args);
      const machine::MachineProfile& profile = setup->profile;
      std::optional<geom::Curve> curve;
      if (!args.curve.name.empty()) {
        try {
          curve.emplace(app::build_curve(args.curve, extras, profile));
        } catch (const std::bad_alloc&) {
          throw;
        } catch (const std::exception& e) {
          throw std::runtime_error(std::string("--curve: ") + e.what());
        }
      }
      std::optional<motion::ServoSim> sim;
      if (args.servo) sim.emplace(profile);
      auto file_index = [&](const nc::SourceFile* f) {
        const std::string name = f ? f->name() : std::string();
        const auto at = static_cast<std::int32_t>(std::find(files.begin(), files.end(), name) - files.begin());
        if (at == static_cast<std::int32_t>(files.size())) files.push_back(name);
        return at;
      };
      motion::Planner planner(profile, [&](const motion::BlockTime& b) {
        rows.push_back({file_index(b.move.file), b.move.line, static_cast<std::uint8_t>(b.move.kind),
                        static_cast<std::uint8_t>(b.limit), b.starved, 0, b.length, b.programmed, b.cap, b.v_in,
                        b.v_peak, b.v_out, b.start, b.seconds, b.wait, b.settle});
        if (sim) {
          app::check_servo_ticks(b, profile, args.max_ticks);
          sim->on_block(b);
        }
      });
      app::ContourTee tee;  // the moves to the planner, and with a curve to the part and the contour
      tee.planner = &planner;
      tee.profile = &profile;
      tee.max_moves = args.max_moves;
      tee.programmed = args.programmed;
      std::vector<machine::Move> contour;
      std::optional<app::RunVerification> part;
      if (curve) {
        tee.contour = &contour;
        tee.plane_only = !profile.lathe() && curve->planar_z();
        part.emplace(app::analyze_part(args), profile, *setup->lib, setup->options);
        tee.part = part->sink();
      }
      machine::Interpreter interp(profile, *setup->lib, setup->options);
      result = interp.run(tee);
      planner.finish();
      if (sim) app::settle(*sim, profile);
      if (part) part->finish(result);
      summary = app::analyze_json(args.in.program, profile, planner.totals(), sim ? &*sim : nullptr);
      if (curve && result.ok()) {
        app::shape::Report shape;
        shape.path = !tee.compensated ? app::shape::Path::plain
                     : args.programmed ? app::shape::Path::programmed
                                       : app::shape::Path::tool;
        if (auto why = app::shape::measure(std::move(contour), *curve, profile, args.tol, shape)) {
          failed = *why;
          if (shape.path == app::shape::Path::tool)
            failed += "; the path measured is the tool's, radius compensation applied (G41/G42): --programmed "
                      "measures the contour as programmed";
        } else {
          app::shape::add_json(summary, *curve, shape, args.tol);
          summary["part"] = report::verify_json(part->report());
        }
      }
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      refused = e.what();
    }
  }
  if (!failed.empty()) throw std::runtime_error(failed);
  if (!refused.empty()) throw py::value_error(refused);

  Analysis out;
  out.summary = py::dict(py::module_::import("json").attr("loads")(
      summary.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
  out.diagnostics = run_diagnostics(setup->problems, result, out.alarm);
  out.ok = result.ok();
  for (const std::string& f : files) out.files.append(decoded(f));
  out.blocks = py::array(block_dtype(), std::vector<py::ssize_t>{static_cast<py::ssize_t>(rows.size())}, std::vector<py::ssize_t>{});
  std::copy(rows.begin(), rows.end(), static_cast<BlockRecord*>(out.blocks.mutable_data()));
  return out;
}

}  // namespace

void add_analyze(py::module_& m) {
  py::tuple limits(5);
  for (int k = 0; k < 5; ++k) limits[k] = py::str(motion::to_string(static_cast<motion::Limit>(k)));
  m.attr("FEED_LIMITS") = limits;

  py::class_<Analysis>(m, "Analysis", "The result of ncurve.analyze(): the cycle time and each motion's timing.")
      .def_readonly("summary", &Analysis::summary, "the totals as a dict: the keys of `ncurve analyze --json`")
      .def_readonly("blocks", &Analysis::blocks,
                    "numpy structured array, a record a motion with the columns of `ncurve analyze --blocks`: file "
                    "(index into files), line, kind (ncurve.MOVE_KINDS), length_mm, programmed_mm_min, cap_mm_min, "
                    "limit (ncurve.FEED_LIMITS), v_in_mm_min, v_peak_mm_min, v_out_mm_min, start_s, seconds, wait_s, "
                    "settle_s, starved")
      .def_readonly("files", &Analysis::files, "the program files' names, as blocks['file'] indexes them")
      .def_readonly("diagnostics", &Analysis::diagnostics,
                    "list of ncurve.Diagnostic: syntax problems found in the files, warnings, then the alarm")
      .def_readonly("alarm", &Analysis::alarm, "the ncurve.Diagnostic the program stopped on, or None")
      .def_readonly("ok", &Analysis::ok, "True when the program ran to its end without an alarm")
      .def("__repr__", [](const Analysis& a) {
        return py::str("<ncurve.Analysis: cycle time {:.3f} s, {} motions{}>")
            .format(a.summary["cycle_time_s"], a.blocks.size(), a.ok ? py::str("") : py::str(", alarm"));
      });
  static const std::string doc = analyze_doc();
  py::options options;
  options.disable_function_signatures();
  m.def("analyze", &analyze, doc.c_str(), py::arg("program"), py::kw_only(), py::arg("machine") = py::none(),
        py::arg("lib") = py::tuple(), py::arg("set") = py::dict(), py::arg("params") = py::dict(),
        py::arg("max_steps") = py::none(), py::arg("max_seconds") = py::none(), py::arg("servo") = false,
        py::arg("kv") = py::none(), py::arg("feed_forward") = py::none(), py::arg("max_ticks") = py::none(),
        py::arg("curve") = py::none(), py::arg("t") = py::none(), py::arg("tol") = py::none(),
        py::arg("programmed") = false, py::arg("setup") = py::none(), py::arg("wall") = py::none(),
        py::arg("max_moves") = py::none());
}

}  // namespace ncurve::python
