#include "python/verify/verify.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include <optional>

#include "app/cli_checks.hpp"
#include "app/run_setup.hpp"
#include "app/run_verify.hpp"
#include "python/common/cli_args.hpp"
#include "python/common/diagnostic.hpp"
#include "python/common/run_args.hpp"
#include "report/path_plot.hpp"
#include "report/summary.hpp"
#include "sim/verifier.hpp"

namespace ncurve::python {
namespace {

// What verify() returns.
struct Verification {
  py::list findings;  // the verifier's warnings (NC2080 ..)
  py::list diagnostics;
  py::object alarm = py::none();
  bool ok = true;
  py::dict summary;  // `ncurve run --verify --json`; its "verify" the verifier's
  py::object heights = py::none();  // a mill's Z-map: (ny, nx), row j at y0 + (j + 0.5) cell
  py::object origin = py::none();   // (x, y) of the map's corner, mm
  py::object cell = py::none();     // mm
  py::object section = py::none();  // a lathe's: the half-section's polygons, each (n, 2) of Z, X radius
};

const char* const kSignature =
    "verify(program, *, setup=None, machine=None, lib=(), set={}, params={}, max_steps=None, max_seconds=None, "
    "nose_centre=False, resolution=None, design=None, tol=None, curve=None, t=None, wall=None, max_moves=None, "
    "**curve_params) -> ncurve.Verification";
const char* const kHead =
    "Cut the stock with a program's moves and report what goes wrong (a rapid through material, a cut deeper than "
    "the flutes, a holder or fixture hit, ...): `ncurve run PROGRAM --verify --setup FILE --json` (docs/verify.md) "
    "from Python.";
const char* const kTail =
    "Returns an ncurve.Verification: `findings` (ncurve.Diagnostic, the verifier's warnings NC2080 .. NC2089, as "
    "the CLI lists them), `diagnostics` (everything the run reported, the findings among them), `alarm`, `ok`, "
    "`summary` (the dict of `ncurve run --verify --json`; `summary['verify']` the verifier's: stock, tools, zmap, "
    "volume_removed_mm3, findings, ...), and the cut part: on a mill `heights` (the Z-map, a 2-D array (ny, nx), "
    "cell [j, i] centred at origin + ((i + 0.5) cell, (j + 0.5) cell)), `origin` (x, y) and `cell` (mm); on a "
    "lathe `section` (the half-section's polygons, each an (n, 2) array of Z and X as a radius). A bad argument "
    "raises ValueError with the CLI's message. With curve, summary['verify']['curve'] has the walls against it. "
    "The GIL is released while it works.";
const char* const kRunArgs[][2] = {{"machine", "--machine"},   {"lib", "--lib"},
                                   {"set", "--set"},           {"params", "--param"},
                                   {"max_steps", "--max-steps"}, {"max_seconds", "--max-seconds"},
                                   {"nose_centre", "--nose-centre"}};
const char* const kOwnArgs[][3] = {
    {"setup", "--setup", " Also the TOML text itself (a str with a line break; it may name no STL file). None: "
                         "the defaults (--verify alone)."},
    {"resolution", "--resolution", ""},
    {"design", "--design", ""},
    {"tol", "--tol", ""},
    {"curve", "--curve", " Its parameters as keywords (a=40; expr's x, y, z as strings), as gen() takes them."},
    {"t", "--from", " (FROM, TO): --from and --to (--t FROM:TO for expr)."},
    {"wall", "--wall", ""},
    {"max_moves", "--max-moves", ""}};

std::string verify_doc() {
  app::RunInputs in;
  app::VerifyArgs va;
  CLI::App command("run");
  app::add_run_inputs(&command, in, true);
  app::add_verify_options(&command, va);
  std::string doc = std::string(kSignature) + "\n\n" + wrapped(kHead, 0) +
                    "\nArguments (the CLI's option in brackets):\n  program\n" +
                    wrapped("part program: as run() takes it (its text, or its file).", 6);
  for (const auto& [name, option, more] : kOwnArgs)
    doc += fmt::format("  {}\n", name) +
           wrapped(fmt::format("{}.{} [{}]", command.get_option(option)->get_description(), more, option), 6);
  for (const auto& [name, option] : kRunArgs)
    doc += fmt::format("  {}\n", name) +
           wrapped(fmt::format("{}. As run() takes it. [{}]", command.get_option(option)->get_description(), option), 6);
  return doc + "\n" + wrapped(kTail, 0);
}

Verification verify(const py::object& program, const py::object& setup_file, const py::object& machine,
                    const py::object& lib, const py::object& set, const py::object& params, const py::object& max_steps,
                    const py::object& max_seconds, bool nose_centre, const py::object& resolution,
                    const py::object& design, const py::object& tol, const py::object& curve, const py::object& t,
                    const py::object& wall, const py::object& max_moves, const py::kwargs& curve_params) {
  app::RunInputs in;
  app::VerifyArgs va;
  CLI::App command("run");
  app::add_run_inputs(&command, in, true);
  app::add_verify_options(&command, va);
  const RunWords given = run_words(program, machine, lib, set, params, max_steps, max_seconds, nose_centre);
  std::vector<std::string> words = given.words;
  words.push_back("--verify");
  std::optional<TextOrPath> setup_text;
  if (!setup_file.is_none()) {
    setup_text = text_or_path(setup_file, "setup");
    if (!setup_text->text) words.push_back("--setup=" + setup_text->value);
  }
  if (!resolution.is_none()) words.push_back("--resolution=" + option_text(resolution, "resolution"));
  if (!design.is_none()) words.push_back("--design=" + option_text(design, "design"));
  if (!tol.is_none()) words.push_back("--tol=" + option_text(tol, "tol"));
  if (!wall.is_none()) words.push_back("--wall=" + option_text(wall, "wall"));
  if (!max_moves.is_none()) words.push_back("--max-moves=" + option_text(max_moves, "max_moves"));
  add_curve_words(words, curve, t, curve_params, "verify");
  parse_options(command, words);
  va.curve_extras = command.remaining();
  va.curve.command = "ncurve run";
  va.curve.options = app::long_options(command);
  given.apply(in);
  if (setup_text && setup_text->text) va.setup_text = setup_text->value;

  std::optional<app::RunSetup> setup;
  std::optional<app::RunVerification> verification;
  machine::RunResult result;
  std::size_t warnings_before = 0;
  std::string refused;  // why the CLI would not run it
  {
    py::gil_scoped_release free_python;
    try {
      setup.emplace(app::prepare_run(in));
      verification.emplace(va, setup->profile, *setup->lib, setup->options);
      machine::NullSink no_moves;
      std::optional<report::TeeSink> tee;
      if (verification->sink()) tee.emplace(no_moves, *verification->sink());
      machine::Interpreter interp(setup->profile, *setup->lib, setup->options);
      machine::MoveSink& target = tee ? static_cast<machine::MoveSink&>(*tee) : no_moves;
      result = interp.run(target);
      if (result.alarm) target.stopped(*result.alarm);
      warnings_before = result.warnings.size();
      verification->finish(result);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      refused = e.what();
    }
  }
  if (!refused.empty()) throw py::value_error(refused);

  const report::RunReport rep = app::run_report(*setup, in.program, result, &verification->report());

  Verification out;
  out.summary = py::dict(py::module_::import("json").attr("loads")(report::summary_json(rep)));
  out.diagnostics = run_diagnostics(setup->problems, result, out.alarm);
  for (std::size_t i = warnings_before; i < result.warnings.size(); ++i)  // the verification's, the same objects
    out.findings.append(out.diagnostics[setup->problems.size() + i]);
  out.ok = result.ok();
  if (const sim::ZMap* map = verification->map()) {
    py::array_t<double> heights({static_cast<py::ssize_t>(map->ny()), static_cast<py::ssize_t>(map->nx())});
    std::copy(map->heights().begin(), map->heights().end(), heights.mutable_data());
    out.heights = heights;
    out.cell = py::float_(map->cell());
    out.origin = py::make_tuple(map->cell_x(0) - map->cell() / 2, map->cell_y(0) - map->cell() / 2);
  }
  if (const sim::LatheSection* section = verification->section()) {
    py::list polygons;
    for (const auto& polygon : section->polygons()) {
      py::array_t<double> points({static_cast<py::ssize_t>(polygon.size()), py::ssize_t{2}});
      auto p = points.mutable_unchecked<2>();
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        p(static_cast<py::ssize_t>(i), 0) = polygon[i].x;
        p(static_cast<py::ssize_t>(i), 1) = polygon[i].y;
      }
      polygons.append(points);
    }
    out.section = polygons;
  }
  return out;
}

}  // namespace

void add_verify(py::module_& m) {
  py::class_<Verification>(m, "Verification", "The result of ncurve.verify(): the findings and the cut part.")
      .def_readonly("findings", &Verification::findings,
                    "list of ncurve.Diagnostic: what the verifier found (NC2080 .. NC2089), each at its block")
      .def_readonly("diagnostics", &Verification::diagnostics,
                    "list of ncurve.Diagnostic: syntax problems, warnings (the findings among them), then the alarm")
      .def_readonly("alarm", &Verification::alarm, "the ncurve.Diagnostic the run stopped on, or None")
      .def_readonly("ok", &Verification::ok, "True when the program ran to its end without an alarm")
      .def_readonly("summary", &Verification::summary,
                    "the dict of `ncurve run --verify --json`; summary['verify'] is the verifier's")
      .def_readonly("heights", &Verification::heights,
                    "a mill: the Z-map, 2-D array (ny, nx) of the material's height over each cell, mm; None on a "
                    "lathe or where nothing was verified")
      .def_readonly("origin", &Verification::origin, "a mill: (x, y) of the Z-map's corner, mm")
      .def_readonly("cell", &Verification::cell, "a mill: the Z-map's cell size, mm")
      .def_readonly("section", &Verification::section,
                    "a lathe: the cut half-section, a list of polygons, each an (n, 2) array of Z and X (a radius), mm")
      .def("__repr__", [](const Verification& v) {
        return py::str("<ncurve.Verification: {} findings{}>").format(py::len(v.findings), v.ok ? "" : ", alarm");
      });
  static const std::string doc = verify_doc();
  py::options options;
  options.disable_function_signatures();
  m.def("verify", &verify, doc.c_str(), py::arg("program"), py::kw_only(), py::arg("setup") = py::none(),
        py::arg("machine") = py::none(), py::arg("lib") = py::tuple(), py::arg("set") = py::dict(),
        py::arg("params") = py::dict(), py::arg("max_steps") = py::none(), py::arg("max_seconds") = py::none(),
        py::arg("nose_centre") = false, py::arg("resolution") = py::none(), py::arg("design") = py::none(),
        py::arg("tol") = py::none(), py::arg("curve") = py::none(), py::arg("t") = py::none(),
        py::arg("wall") = py::none(), py::arg("max_moves") = py::none());
}

}  // namespace ncurve::python
