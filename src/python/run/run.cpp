#include "python/run/run.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>

#include "app/run_setup.hpp"
#include "machine/interpreter.hpp"
#include "python/common/cli_args.hpp"
#include "python/common/diagnostic.hpp"
#include "python/common/run_args.hpp"
#include "python/run/move_records.hpp"
#include "python/run/steps.hpp"
#include "report/summary.hpp"

namespace ncurve::python {
namespace {
using namespace pybind11::literals;

// What run() returns: the moves as records, and what the CLI's summary says.
struct Run {
  py::array moves;
  py::list files;  // the names `moves["file"]` indexes
  py::dict summary;
  py::list diagnostics;
  py::object alarm = py::none();
  bool ok = true;
  py::bytes printed;
  std::shared_ptr<const StepVariables> trace;  // trace=True: what each block changed
  py::object steps = py::none();
  app::RunInputs inputs;  // as parsed: what analyze() of this Run runs again
};

const char* const kNotTraced =
    "the run recorded no variables: run it with ncurve.run(..., trace=True) (as the workbench's /api/run "
    "\"trace\": true)";

// The Python arguments with the CLI option each stands for, in the order of help().
struct Argument {
  const char* name;
  const char* option;  // the CLI's ("program" for the positional one)
  const char* python;  // what Python takes beyond the CLI's value (null: the help is Python's own)
};
constexpr Argument kArguments[] = {
    {"program", "program", nullptr},  // kProgram
    {"machine", "--machine", "Also the TOML text itself (a str with a line break), or an os.PathLike."},
    {"lib", "--lib", "A folder, or a list of them."},
    {"set", "--set", "A dict: {100: 5} or {'#100': 5}."},
    {"params", "--param", "A dict: {6050: 102, '3401#0': 1}."},
    {"max_steps", "--max-steps", "None: the CLI's default."},
    {"max_seconds", "--max-seconds", "None: the CLI's default."},
    {"nose_centre", "--nose-centre", ""},
    {"trace", nullptr, "record what each block changes, as the workbench debugger's trace (/api/run \"trace\": true): "
                       "Run.steps and Run.variables_at(step). About 32 bytes a block, variable write and system "
                       "variable read. [/api/run \"trace\"]"},
    {"trace_limit", nullptr, "the most trace records (None: 2,000,000; at most 20,000,000); past it the trace "
                             "stops at a whole block and says so. [/api/run \"trace_limit\"]"},
};

const char* const kSignature =
    "run(program, *, machine=None, lib=(), set={}, params={}, max_steps=None, max_seconds=None, nose_centre=False, "
    "trace=False, trace_limit=None) -> ncurve.Run";
// the positional argument's help: the CLI's speaks of standard input
const char* const kProgram =
    "part program: its text (a str with a line break; named <text> in messages), or its file (a str without a "
    "line break, or an os.PathLike; a file of 8 MB or more is read block by block as the run reaches it)";
const char* const kRunHead =
    "Execute a part program as a FANUC control would and report the tool path: `ncurve run PROGRAM "
    "[options]` (docs/run.md) from Python.";
const char* const kRunTail =
    "Returns an ncurve.Run: `moves`, a NumPy structured array with a record a move (ncurve.MOVE_KINDS names "
    "`kind`), `files` (the names `moves['file']` indexes), `summary` (the dict of `ncurve run --json`), "
    "`diagnostics` (ncurve.Diagnostic: syntax problems, warnings, then the alarm), `alarm`, `ok`, `printed` "
    "(what DPRNT sent, as --dprnt writes it). A program that stops on an alarm returns its moves up to it and "
    "the alarm: it does not raise. A bad argument raises ValueError with the CLI's message (TypeError for a "
    "value of the wrong type). The GIL is released while the program runs.";

// help(ncurve.run): the command's description and each argument's CLI help, with what Python adds.
std::string run_doc() {
  app::RunInputs in;
  CLI::App command("run");
  app::add_run_inputs(&command, in, true);
  std::string doc = std::string(kSignature) + "\n\n" + wrapped(kRunHead, 0) +
                    "\nArguments (the CLI's option in brackets):\n";
  for (const Argument& a : kArguments) {
    if (!a.option) {  // the server's, not the CLI's
      doc += fmt::format("  {}\n", a.name) + wrapped(a.python, 6);
      continue;
    }
    std::string text = a.python ? command.get_option(a.option)->get_description() : std::string(kProgram);
    const std::string more = a.python && *a.python ? std::string(" ") + a.python : "";
    text = fmt::format("{}.{} [{}]", text, more, a.option);
    doc += fmt::format("  {}\n", a.name) + wrapped(text, 6);
  }
  return doc + "\n" + wrapped(kRunTail, 0);
}

// The record's NumPy dtype: the fields at their offsets, the record's size.
py::dtype record_dtype(const MoveRecords& records) {
  py::list names, formats, offsets;
  for (const RecordField& f : records.fields()) {
    names.append(f.name);
    formats.append(f.format);
    offsets.append(f.offset);
  }
  py::dict spec("names"_a = names, "formats"_a = formats, "offsets"_a = offsets,
                "itemsize"_a = records.record_size());
  return py::dtype::from_args(spec);
}

Run run(const py::object& program, const py::object& machine, const py::object& lib, const py::object& set,
        const py::object& params, const py::object& max_steps, const py::object& max_seconds, bool nose_centre, bool trace,
        const py::object& trace_limit) {
  // the arguments as the command line's words, parsed by the command's options
  app::RunInputs in;
  CLI::App command("run");
  app::add_run_inputs(&command, in, true);
  const RunWords given = run_words(program, machine, lib, set, params, max_steps, max_seconds, nose_centre);
  parse_options(command, given.words);
  std::size_t most_records = machine::ExecutionTrace::kDefaultLimit;
  if (!trace_limit.is_none()) {
    const double limit = py::float_(trace_limit);
    if (!(limit >= 1 && limit <= static_cast<double>(machine::ExecutionTrace::kMaxLimit)) || limit != std::floor(limit))
      throw py::value_error(fmt::format("trace_limit is a whole number from 1 to {}", machine::ExecutionTrace::kMaxLimit));
    most_records = static_cast<std::size_t>(limit);
  }
  given.apply(in);

  std::optional<app::RunSetup> setup;
  std::optional<MoveRecords> records;
  machine::RunResult result;
  std::string refused;  // why the CLI would not run it
  std::shared_ptr<machine::ExecutionTrace> recorded;
  if (trace) recorded = std::make_shared<machine::ExecutionTrace>(most_records);
  {
    py::gil_scoped_release free_python;
    try {
      setup.emplace(app::prepare_run_of_any_size(in));
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      refused = e.what();
    }
    if (setup) {
      records.emplace(setup->profile);
      machine::Interpreter interp(setup->profile, *setup->lib, setup->options);
      if (recorded) interp.observe(recorded.get());
      result = interp.run(*records);
      if (setup->lib->streamed()) app::complete_problems(*setup);  // the file is read to its end
    }
  }
  if (!setup) throw py::value_error(refused);

  const report::RunReport rep = app::run_report(*setup, in.program, result);

  Run out;
  out.summary = py::dict(py::module_::import("json").attr("loads")(report::summary_json(rep)));
  out.diagnostics = run_diagnostics(setup->problems, result, out.alarm);
  out.ok = result.ok();
  out.inputs = in;
  out.printed = py::bytes(result.output.bytes);
  std::vector<std::string> files = records->files();
  if (recorded) {
    out.steps = step_records(*recorded, files);
    out.trace = std::make_shared<const StepVariables>(std::move(recorded));
  }
  for (const std::string& f : files) out.files.append(decoded(f));
  // the records handed to NumPy as they are: the capsule frees them with the array
  const py::dtype dtype = record_dtype(*records);
  const std::size_t count = records->count();
  std::unique_ptr<RecordBuffer> buffer = records->take();
  unsigned char* data = buffer->release();
  py::capsule owner(data, [](void* p) { std::free(p); });
  out.moves = py::array(dtype, {static_cast<py::ssize_t>(count)}, {static_cast<py::ssize_t>(dtype.itemsize())},
                        data, owner);
  return out;
}

}  // namespace

const app::RunInputs* run_inputs(py::handle value) {
  return py::isinstance<Run>(value) ? &value.cast<const Run&>().inputs : nullptr;
}

void add_run(py::module_& m) {
  py::tuple kinds(10);
  for (int k = 0; k < 10; ++k) kinds[k] = py::str(machine::to_string(static_cast<machine::MoveKind>(k)));
  m.attr("MOVE_KINDS") = kinds;

  py::class_<Run>(m, "Run", "The result of ncurve.run(): the moves and the summary of one run.")
      .def_readonly("moves", &Run::moves,
                    "numpy structured array, a record a move (motions, dwells and events in order): kind "
                    "(index into ncurve.MOVE_KINDS), line, file (index into files), program (O number), x0 y0 z0 "
                    "(start), x y z (end), a0 a .. for the profile's rotary axes, cx cy cz (arc centre), f, length, "
                    "seconds, code, plane, clockwise, feed_per_rev, compensated, corner, threading, lookahead")
      .def_readonly("files", &Run::files, "the program files' names, as moves['file'] indexes them")
      .def_readonly("summary", &Run::summary, "the summary as a dict: the keys of `ncurve run --json`")
      .def_readonly("diagnostics", &Run::diagnostics,
                    "list of ncurve.Diagnostic: syntax problems found in the files, warnings, then the alarm")
      .def_readonly("alarm", &Run::alarm, "the ncurve.Diagnostic the run stopped on, or None")
      .def_readonly("ok", &Run::ok, "True when the program ran to its end without an alarm")
      .def_readonly("printed", &Run::printed, "the bytes POPEN, DPRNT, BPRNT and PCLOS sent (as --dprnt writes them)")
      .def_readonly("steps", &Run::steps,
                    "trace=True: numpy structured array, a record per executed block (step k is the k-th): file "
                    "(index into files), line, move (moves made before it), level (local variable level), depth "
                    "(calls open), program (O number); None otherwise")
      .def(
          "variables_at",
          [](const Run& r, std::int64_t step) {
            if (!r.trace) throw py::value_error(kNotTraced);
            return r.trace->at(step);
          },
          py::arg("step"),
          "The variables at step `step` (0 .. len(steps)): the state after that many blocks, before block `step` "
          "runs (len(steps): after the last), as the workbench debugger shows it. A dict {number: value}: #1..#33 "
          "of the local level the block runs at, then every common and system variable written so far; None for "
          "a vacant one. IndexError outside the steps; ValueError when the run was not traced (trace=True).")
      .def_property_readonly(
          "trace_complete", [](const Run& r) { return r.trace ? py::object(py::bool_(r.trace->trace().complete())) : py::object(py::none()); },
          "trace=True: whether every executed block is in the trace (False past trace_limit); None otherwise")
      .def("__repr__", [](const Run& r) {
        return py::str("<ncurve.Run: {} moves, {}>")
            .format(r.moves.size(), r.ok ? py::str("ok") : py::str("alarm {}").format(r.alarm.attr("code")));
      });

  static const std::string doc = run_doc();
  py::options options;
  options.disable_function_signatures();  // the doc's first line is the signature, in Python's words
  m.def("run", &run, doc.c_str(), py::arg("program"), py::kw_only(), py::arg("machine") = py::none(),
        py::arg("lib") = py::tuple(), py::arg("set") = py::dict(), py::arg("params") = py::dict(),
        py::arg("max_steps") = py::none(), py::arg("max_seconds") = py::none(), py::arg("nose_centre") = false,
        py::arg("trace") = false, py::arg("trace_limit") = py::none());
}

}  // namespace ncurve::python
