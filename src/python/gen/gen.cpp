#include "python/gen/gen.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <optional>

#include "app/cli_checks.hpp"
#include "app/gen_command.hpp"
#include "base/bounds.hpp"
#include "python/common/cli_args.hpp"

namespace ncurve::python {
namespace {

// What gen() returns: the program and the statistics of `ncurve gen --json`.
struct Gen {
  py::str text;   // the program (with macro_only, the cycle's macro program)
  py::str macro;  // form "cycle": the macro program the calling program needs ("" otherwise)
  py::dict stats;
  py::list warnings;
  bool ok = true;  // within the tolerance
};

// The options of `ncurve gen` that Python does not take: it writes no file and prints nothing.
bool left_out(const std::string& name) {
  return name == "list" || name == "plot" || name == "output" || name == "json" || name == "help";
}

const char* const kSignature = "gen(curve, tol=None, *, form=None, machine=None, t=None, **options) -> ncurve.Gen";
const char* const kHead =
    "Write a program for a curve within a guaranteed shape tolerance, proven by running it back through the "
    "interpreter: `ncurve gen CURVE [options] [--PARAM VALUE ...]` (docs/gen.md) from Python.";
const char* const kArgs =
    "curve: a curve's name (`ncurve gen --list` shows them and their parameters) or 'expr' (with x, y, z and "
    "t). tol: the shape tolerance, mm (None: the CLI's default, 0.005). form: expanded, arcs, macro, "
    "adaptive-macro or cycle (None: expanded). machine: a profile file, a shipped "
    "profile's name or the TOML text itself (a str with a line break). t: (FROM, TO), the range of the curve "
    "parameter t (--from and --to; --t FROM:TO for expr). Every other keyword is an option of `ncurve gen` with "
    "_ for - (step_down=2 for --step-down 2; True for a flag) or else a parameter of the curve (r0=5, a=40): "
    "the CLI reads them all, so a bad one is refused with its message (ValueError).";
const char* const kTail =
    "Returns an ncurve.Gen: `text` (the program), `macro` (form 'cycle': the macro program it calls), `stats` "
    "(the dict of `ncurve gen --json`, without the program), `warnings` (what the CLI warns of), `ok` (the "
    "program is within the tolerance; a program that is not is returned all the same, as the CLI writes it). A "
    "curve that cannot be cut raises RuntimeError with the CLI's message. The GIL is released while it works.";

// help(ncurve.gen): the command's description, Python's arguments, and each option's CLI help.
std::string gen_doc() {
  app::GenArgs args;
  CLI::App app;
  app::add_gen_command(app, args);
  std::string doc = std::string(kSignature) + "\n\n" + wrapped(kHead, 0) + "\n" + wrapped(kArgs, 0) +
                    "\nOptions (the CLI's option in brackets):\n";
  doc += options_doc(*args.command, [](const std::string& name) {
    return left_out(name) || name == "curve" || name == "tol" || name == "form" || name == "machine" || name == "from" ||
           name == "to" || name == "t";
  });
  return doc + "\n" + wrapped(kTail, 0);
}

// A keyword as the command line's words: an option of gen as --name=value (a flag alone when True,
// nothing when False), anything else as the pair --name value the curve's parameters are read from.
void add_keyword(std::vector<std::string>& words, CLI::App& command, const std::string& key, py::handle value) {
  const std::string name = option_name(key);
  const CLI::Option* option = command.get_option_no_throw("--" + name);
  if (option && left_out(name))
    throw py::type_error(fmt::format("gen() takes no {}: it writes no file and prints nothing", key));
  if (option && option->get_expected_min() == 0) {  // a flag
    if (!PyBool_Check(value.ptr())) throw py::type_error(fmt::format("{}: expected True or False", key));
    if (value.cast<bool>()) words.push_back("--" + name);
    return;
  }
  const std::string text = option_text(value, key);
  if (option) {
    words.push_back(fmt::format("--{}={}", name, text));
  } else {
    words.push_back("--" + name);
    words.push_back(text);
  }
}

Gen gen(const py::object& curve, const py::object& tol, const py::object& form, const py::object& machine,
        const py::object& t, const py::kwargs& options) {
  app::GenArgs args;
  CLI::App app;
  app::add_gen_command(app, args);
  CLI::App& command = *args.command;
  std::vector<std::string> words{"gen", option_text(curve, "curve")};
  if (!tol.is_none()) words.push_back("--tol=" + option_text(tol, "tol"));
  if (!form.is_none()) words.push_back("--form=" + option_text(form, "form"));
  std::optional<TextOrPath> profile;
  if (!machine.is_none()) {
    profile = text_or_path(machine, "machine");
    if (!profile->text) words.push_back("--machine=" + profile->value);
  }
  if (!t.is_none()) {
    const py::sequence range = py::reinterpret_borrow<py::sequence>(t);
    if (!py::isinstance<py::sequence>(t) || py::isinstance<py::str>(t) || range.size() != 2)
      throw py::type_error("t: expected (FROM, TO)");
    const std::string from = option_text(range[0], "t"), to = option_text(range[1], "t");
    if (words[1] == "expr") words.push_back(fmt::format("--t={}:{}", from, to));
    else words.insert(words.end(), {"--from=" + from, "--to=" + to});
  }
  for (auto [key, value] : options) add_keyword(words, command, key.cast<std::string>(), value);
  parse_options(app, words);
  if (profile && profile->text) {
    args.machine = "<text>";
    args.machine_text = profile->value;
  }

  std::optional<app::GenJob> job;
  gen::Result result;
  nlohmann::json stats;
  std::string refused, failed;  // why the CLI would exit 2, 1
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release free_python;
    try {
      job.emplace(app::gen_job(args, command.remaining(), "ncurve gen", app::long_options(command)));
      warnings = app::gen_warnings(*job);
      result = gen::generate(job->curve, job->options);
      stats = app::gen_json(*job, result, nullptr);
      const app::GenTimes times = app::gen_times(*job, result);
      app::add_gen_times(stats, times, result.text);
      if (std::string w = app::slower_warning(*job, times); !w.empty()) warnings.push_back(std::move(w));
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const base::BoundExceeded& e) {
      refused = e.what();
    } catch (const std::exception& e) {
      (job ? failed : refused) = e.what();
    }
  }
  if (!refused.empty()) throw py::value_error(refused);
  if (!failed.empty()) throw std::runtime_error(failed);

  Gen out;
  out.text = decoded(args.macro_only ? result.macro : result.text);
  out.macro = decoded(result.macro);
  out.stats = py::dict(py::module_::import("json").attr("loads")(
      stats.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
  for (const std::string& w : warnings) out.warnings.append(decoded(w));
  out.ok = result.within_tolerance;
  return out;
}

}  // namespace

void add_gen(py::module_& m) {
  py::class_<Gen>(m, "Gen", "The result of ncurve.gen(): the program and its statistics.")
      .def_readonly("text", &Gen::text, "the program (with macro_only=True, the cycle's macro program)")
      .def_readonly("macro", &Gen::macro, "form 'cycle': the macro program the calling program calls; '' otherwise")
      .def_readonly("stats", &Gen::stats, "the statistics as a dict: the keys of `ncurve gen --json` but program")
      .def_readonly("warnings", &Gen::warnings, "what `ncurve gen` warns of, each without 'warning: '")
      .def_readonly("ok", &Gen::ok, "True when the program is within the tolerance")
      .def("__repr__", [](const Gen& g) {
        return py::str("<ncurve.Gen: {} {}, {} blocks, max deviation {:.6f} mm{}>")
            .format(g.stats["curve"], g.stats["form"], g.stats["blocks"], g.stats["max_deviation"],
                    g.ok ? "" : " (beyond the tolerance)");
      });
  static const std::string doc = gen_doc();
  py::options options;
  options.disable_function_signatures();
  m.def("gen", &gen, doc.c_str(), py::arg("curve"), py::arg("tol") = py::none(), py::kw_only(),
        py::arg("form") = py::none(), py::arg("machine") = py::none(), py::arg("t") = py::none());
}

}  // namespace ncurve::python
