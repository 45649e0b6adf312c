#include "python/helicoid/helicoid.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include <cmath>
#include <limits>
#include <optional>

#include "app/helicoid_command.hpp"
#include "python/common/cli_args.hpp"

namespace ncurve::python {
namespace {

// What helicoid() returns.
struct Helicoid {
  py::object contacts;  // the contact table, a record a step
  py::str title;
  py::str program;      // the 4-axis program of --program
};

// The options of `ncurve helicoid` that Python does not take: it writes no file and prints nothing.
bool left_out(const std::string& name) {
  return name == "csv" || name == "json" || name == "output" || name == "program" || name == "plot" || name == "help";
}

// The CSV's columns, in its order, as the record's fields: floats but two.
constexpr const char* kColumns[] = {
    "psi_deg",          "A_mm",          "u_deg",        "r_mm",           "x_mm",        "y_mm",     "z_mm",
    "cutter_x_mm",      "cutter_y_mm",   "cutter_z_mm",  "cutter_alpha_deg", "cutter_s_mm", "cutter_region",
    "normal_angle_deg", "evaluations",   "plane_A_mm",   "plane_error_mm", "cusp_mm",     "Z_mm"};

const char* const kSignature = "helicoid(example=None, **options) -> ncurve.Helicoid";
const char* const kHead =
    "Disc-cutter locations for a helical surface by minimum directed distance (the helicoid paper's method): "
    "`ncurve helicoid [options] --csv` (docs/helicoid.md) from Python. example='seed004': the paper's screw-drill "
    "rotor with its cutter. Every other keyword is an option of `ncurve helicoid` with _ for - (cutter_diameter=252 "
    "for --cutter-diameter 252, no_check=True for --no-check, u=(0, 360) for --u 0:360, centre_distance=(170, 180, "
    "1) for --centre-distance 170:180:1): the CLI reads them, so a bad one is refused with its message "
    "(ValueError).";
const char* const kTail =
    "Returns an ncurve.Helicoid: `contacts`, a NumPy structured array with a record a step and the columns of "
    "`ncurve helicoid --csv` (psi_deg, A_mm, u_deg, r_mm, x_mm, y_mm, z_mm, cutter_x_mm .. cutter_s_mm, "
    "cutter_region (str), normal_angle_deg, evaluations (int), plane_A_mm, plane_error_mm, cusp_mm (NaN on the "
    "last row, which the CSV leaves empty), Z_mm) at full precision; `title`; `program` (the 4-axis program "
    "--program writes, by length, feed and program_tol). A search that fails (an interference, a contact at an "
    "edge of the cutter) raises RuntimeError with the CLI's message. The GIL is released while it searches.";

std::string helicoid_doc() {
  app::HelicoidArgs args;
  CLI::App app;
  app::add_helicoid_command(app, args);
  std::string doc = std::string(kSignature) + "\n\n" + wrapped(kHead, 0) + "\nOptions (the CLI's option in brackets):\n";
  doc += options_doc(*args.command, left_out);
  return doc + "\n" + wrapped(kTail, 0);
}

// A keyword as the option's word: a flag alone when True, a tuple as its values joined by ':'.
void add_keyword(std::vector<std::string>& words, CLI::App& command, const std::string& key, py::handle value) {
  const std::string name = option_name(key);
  const CLI::Option* option = command.get_option_no_throw("--" + name);
  if (!option) throw py::type_error(fmt::format("helicoid() got an unexpected keyword argument '{}'", key));
  if (left_out(name)) throw py::type_error(fmt::format("helicoid() takes no {}: it writes no file and prints nothing", key));
  if (option->get_expected_min() == 0) {  // a flag
    if (!PyBool_Check(value.ptr())) throw py::type_error(fmt::format("{}: expected True or False", key));
    if (value.cast<bool>()) words.push_back("--" + name);
    return;
  }
  std::string text;
  if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
    for (py::handle v : value) text += (text.empty() ? "" : ":") + option_text(v, key);
  } else {
    text = option_text(value, key);
  }
  words.push_back(fmt::format("--{}={}", name, text));
}

py::object contact_array(const helicoid::Job& job) {
  py::module_ np = py::module_::import("numpy");
  py::list fields;
  for (const char* c : kColumns) {
    const std::string name = c;
    fields.append(py::make_tuple(c, name == "cutter_region" ? "U16" : name == "evaluations" ? "<i8" : "<f8"));
  }
  const std::size_t n = job.contacts.size();
  py::object out = np.attr("zeros")(n, py::arg("dtype") = np.attr("dtype")(fields));
  std::vector<std::vector<double>> columns(std::size(kColumns), std::vector<double>(n));
  py::list regions, evaluations;
  for (std::size_t i = 0; i < n; ++i) {
    const helicoid::Contact& c = job.contacts[i];
    const double cusp = i < job.cusps.size() ? job.cusps[i] : std::numeric_limits<double>::quiet_NaN();
    const double row[] = {c.psi, c.A, c.u, c.r, c.work_point[0], c.work_point[1], c.work_point[2], c.cutter_point[0],
                          c.cutter_point[1], c.cutter_point[2], c.alpha, c.s, 0, c.normal_angle, 0, c.plane_A,
                          c.plane_A - c.A, cusp, c.z};
    for (std::size_t k = 0; k < std::size(kColumns); ++k) columns[k][i] = row[k];
    regions.append(c.region);
    evaluations.append(c.evaluations);
  }
  for (std::size_t k = 0; k < std::size(kColumns); ++k) {
    const std::string name = kColumns[k];
    if (name == "cutter_region") out[py::str(name)] = regions;
    else if (name == "evaluations") out[py::str(name)] = evaluations;
    else out[py::str(name)] = py::array_t<double>(static_cast<py::ssize_t>(n), columns[k].data());
  }
  return out;
}

Helicoid helicoid(const py::object& example, const py::kwargs& options) {
  app::HelicoidArgs args;
  CLI::App app;
  app::add_helicoid_command(app, args);
  std::vector<std::string> words{"helicoid"};
  if (!example.is_none()) words.push_back("--example=" + option_text(example, "example"));
  for (auto [key, value] : options) add_keyword(words, *args.command, key.cast<std::string>(), value);
  parse_options(app, words);

  std::optional<helicoid::ContactSearch> search;
  helicoid::Job job;
  std::string refused, failed, program;  // why the CLI would exit 2, 1
  {
    py::gil_scoped_release free_python;
    try {
      app::helicoid_job(args, search, job, false);
      helicoid::PassOptions o;
      o.z_end = -args.length;
      o.feed = args.feed;
      program = helicoid::pass_program(job, *search, o);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const app::HelicoidRefused& e) {
      refused = e.what();
    } catch (const std::exception& e) {
      failed = e.what();
    }
  }
  if (!refused.empty()) throw py::value_error(refused);
  if (!failed.empty()) throw std::runtime_error(failed);
  Helicoid out;
  out.contacts = contact_array(job);
  out.title = decoded(job.title);
  out.program = decoded(program);
  return out;
}

}  // namespace

void add_helicoid(py::module_& m) {
  py::class_<Helicoid>(m, "Helicoid", "The result of ncurve.helicoid(): the cutter locations, a record a step.")
      .def_readonly("contacts", &Helicoid::contacts,
                    "numpy structured array, a record a step with the columns of `ncurve helicoid --csv`")
      .def_readonly("title", &Helicoid::title, "the profile, lead, hand, cutter and crossing angle searched")
      .def_readonly("program", &Helicoid::program, "the 4-axis FANUC program (X, Z, A) that --program writes")
      .def("__repr__", [](const Helicoid& h) {
        return py::str("<ncurve.Helicoid: {} contacts, {}>").format(py::len(h.contacts), h.title);
      });
  static const std::string doc = helicoid_doc();
  py::options options;
  options.disable_function_signatures();
  m.def("helicoid", &helicoid, doc.c_str(), py::arg("example") = py::none());
}

}  // namespace ncurve::python
