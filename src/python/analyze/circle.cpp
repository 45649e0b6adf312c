// ncurve.circle_test(): the circular test on the machine model, `ncurve analyze circle`.
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>

#include <optional>

#include "app/analyze_command.hpp"
#include "python/analyze/analyze.hpp"
#include "python/common/cli_args.hpp"

namespace ncurve::python {
namespace {

// What circle_test() returns: the figures of --json and the measured turn's deviation.
struct CircleTest {
  py::dict summary;
  py::array polar;  // n x 2: angle (degrees from +p towards +q), radial deviation (mm)
};

const char* const kSignature =
    "circle_test(radius, feed, *, machine=None, kv=None, feed_forward=None, clockwise=False) -> ncurve.CircleTest";
const char* const kHead =
    "The circular test (ISO 230-4) on the machine model: three turns of a circle through the servo model, the "
    "middle one measured, beside the closed forms and the circular-interpolation paper's formula "
    "(seed002_error): `ncurve analyze circle --radius R --feed F --json` (docs/analyze.md) from Python.";
const char* const kTail =
    "Returns an ncurve.CircleTest: `summary` (the dict of `ncurve analyze circle --json`: radius_reduction, "
    "roundness, max_deviation_angle, max_contour_error in mm and degrees, closed_form with seed002_error and "
    "seed002_angle, ...) and `polar` (the measured turn, an n x 2 array of angle in degrees and radial deviation "
    "in mm, as --plot draws it). A bad argument raises ValueError with the CLI's message. The GIL is released "
    "while it works.";
const char* const kOptions[][3] = {
    {"radius", "--radius", ""},
    {"feed", "--feed", ""},
    {"machine", "--machine", " Also the TOML text itself (a str with a line break)."},
    {"kv", "--kv", " One gain, or a list of two."},
    {"feed_forward", "--feed-forward", ""},
    {"clockwise", "--cw", ""},
};

std::string circle_doc() {
  app::AnalyzeArgs args;
  CLI::App app;
  app::add_analyze_command(app, args);
  std::string doc = std::string(kSignature) + "\n\n" + wrapped(kHead, 0) + "\nArguments (the CLI's option in brackets):\n";
  for (const auto& [name, option, more] : kOptions)
    doc += fmt::format("  {}\n", name) +
           wrapped(fmt::format("{}.{} [{}]", args.circle->get_option(option)->get_description(), more, option), 6);
  return doc + "\n" + wrapped(kTail, 0);
}

CircleTest circle_test(const py::object& radius, const py::object& feed, const py::object& machine,
                       const py::object& kv, const py::object& feed_forward, bool clockwise) {
  app::AnalyzeArgs args;
  CLI::App app;
  app::add_analyze_command(app, args);
  std::vector<std::string> words{"analyze", "circle", "--radius=" + option_text(radius, "radius"),
                                 "--feed=" + option_text(feed, "feed")};
  std::optional<TextOrPath> profile;
  if (!machine.is_none()) {
    profile = text_or_path(machine, "machine");
    if (!profile->text) words.push_back("--machine=" + profile->value);
  }
  for (const std::string& k : gains(kv)) words.push_back("--kv=" + k);
  if (!feed_forward.is_none()) words.push_back("--feed-forward=" + option_text(feed_forward, "feed_forward"));
  if (clockwise) words.push_back("--cw");
  parse_options(app, words);

  nlohmann::json summary;
  motion::CircleResult result;
  std::string refused;  // why the CLI would exit 2
  {
    py::gil_scoped_release free_python;
    try {
      machine::MachineProfile p = machine::default_mill();
      if (profile && profile->text) p = machine::parse_profile(profile->value, "<text>");
      else if (!args.in.machine.empty()) p = machine::load_profile(args.in.machine);
      app::apply_servo_options(p, args);
      motion::CircleTest test;
      test.radius = args.radius;
      test.feed = args.feed;
      test.clockwise = args.clockwise;
      result = motion::circle_test(p, test);
      summary = app::circle_json(p, test, result);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      refused = e.what();
    }
  }
  if (!refused.empty()) throw py::value_error(refused);
  CircleTest out;
  out.summary = py::dict(py::module_::import("json").attr("loads")(
      summary.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
  py::array_t<double> polar({static_cast<py::ssize_t>(result.polar.size()), py::ssize_t{2}});
  auto cell = polar.mutable_unchecked<2>();
  for (std::size_t i = 0; i < result.polar.size(); ++i) {
    cell(static_cast<py::ssize_t>(i), 0) = result.polar[i].first;
    cell(static_cast<py::ssize_t>(i), 1) = result.polar[i].second;
  }
  out.polar = polar;
  return out;
}

}  // namespace

void add_circle_test(py::module_& m) {
  py::class_<CircleTest>(m, "CircleTest", "The result of ncurve.circle_test(): the circular test's figures.")
      .def_readonly("summary", &CircleTest::summary, "the figures as a dict: the keys of `ncurve analyze circle --json`")
      .def_readonly("polar", &CircleTest::polar,
                    "the measured turn: n x 2 array of angle (degrees from +X towards +Y on a mill) and radial "
                    "deviation (mm, negative inside the circle)")
      .def("__repr__", [](const CircleTest& c) {
        return py::str("<ncurve.CircleTest: R {} mm, F {} mm/min, radius reduction {:.6f} mm, roundness {:.6f} mm>")
            .format(c.summary["radius"], c.summary["feed"], c.summary["radius_reduction"], c.summary["roundness"]);
      });
  static const std::string doc = circle_doc();
  py::options options;
  options.disable_function_signatures();
  m.def("circle_test", &circle_test, doc.c_str(), py::arg("radius"), py::arg("feed"), py::kw_only(),
        py::arg("machine") = py::none(), py::arg("kv") = py::none(), py::arg("feed_forward") = py::none(),
        py::arg("clockwise") = false);
}

}  // namespace ncurve::python
