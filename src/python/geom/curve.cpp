#include "python/geom/curve.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include <optional>

#include "app/curve_args.hpp"
#include "app/shipped.hpp"
#include "machine/profile.hpp"
#include "python/common/cli_args.hpp"

namespace ncurve::python {
namespace {

// What curve() returns: the samples as arrays, and what the curve is.
struct CurveSamples {
  py::str name;
  py::tuple range;  // (t0, t1) of the curve
  py::dict params;  // name: value, the defaults with those given
  py::array_t<double> t, point, d1, d2, curvature;
};

const char* const kDoc =
    "curve(curve, *, t=None, n=1001, at=None, machine=None, **params) -> ncurve.CurveSamples\n\n"
    "A curve as `ncurve gen` and `ncurve analyze --curve` take it, sampled: its points, first and second "
    "derivatives with respect to t (per degree where t is an angle, as in the catalogue) and curvature, as "
    "NumPy arrays.\n\n"
    "curve: a curve's name (`ncurve gen --list`) or 'expr' (with x, y, z: its expressions in t). t: (FROM, TO), "
    "the range of t (--from/--to; expr's --t FROM:TO); None: the curve's own. n: that many samples at equal "
    "steps of t over the range, both ends included. at: the values of t to sample at instead (a 1-D sequence or "
    "array). machine: a profile (name, file or TOML text) whose macro arithmetic evaluates the expressions. "
    "Every other keyword is a parameter of the curve (r0=5, a=40; expr's names). A bad one is refused with the "
    "CLI's message (ValueError).\n\n"
    "Returns an ncurve.CurveSamples: `t` (n), `point`, `d1`, `d2` (n x 3: X Y Z), `curvature` (n; 0 where "
    "straight), `name`, `range` (the curve's t0, t1), `params` (every parameter's value). Where the curve is "
    "undefined the values are NaN or infinite, not an error.";

CurveSamples curve(const py::object& name, const py::object& t, const py::object& n, const py::object& at,
                   const py::object& machine, const py::kwargs& params) {
  app::CurveArgs args;
  std::string machine_path;
  CLI::App command("curve");
  app::add_curve_options(&command, args, "the curve");
  command.add_option("--machine", machine_path)->transform(app::profile_path());
  std::vector<std::string> words{"--curve=" + option_text(name, "curve")};
  std::optional<TextOrPath> profile;
  if (!machine.is_none()) {
    profile = text_or_path(machine, "machine");
    if (!profile->text) words.push_back("--machine=" + profile->value);
  }
  if (!t.is_none()) {
    if (!py::isinstance<py::sequence>(t) || py::isinstance<py::str>(t) || py::len(t) != 2)
      throw py::type_error("t: expected (FROM, TO)");
    const py::sequence range = py::reinterpret_borrow<py::sequence>(t);
    const std::string from = option_text(range[0], "t"), to = option_text(range[1], "t");
    if (words[0] == "--curve=expr") words.push_back(fmt::format("--t={}:{}", from, to));
    else words.insert(words.end(), {"--from=" + from, "--to=" + to});
  }
  for (auto [key, value] : params) {
    const std::string k = key.cast<std::string>();
    // x, y, z are expr's expressions (options); anything else a parameter, as --NAME VALUE
    if (k == "x" || k == "y" || k == "z") words.push_back(fmt::format("--{}={}", k, option_text(value, k)));
    else words.insert(words.end(), {"--" + k, option_text(value, k)});
  }
  parse_options(command, words);

  // the parameters to sample at: n equal steps over the range, or those given
  std::optional<py::array_t<double>> given;
  long count = 0;
  if (!at.is_none()) {
    given = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(at);
    if (!given || given->ndim() != 1) throw py::type_error("at: expected a 1-D sequence or array of numbers");
  } else {
    if (!PyLong_Check(n.ptr()) || PyBool_Check(n.ptr())) throw py::type_error("n: expected an int");
    count = n.cast<long>();
    if (count < 2 || count > 100'000'000) throw py::value_error(fmt::format("n: must be from 2 to 1e8, got {}", count));
  }

  CurveSamples out;
  std::optional<geom::Curve> c;
  std::string refused;
  {
    py::gil_scoped_release free_python;
    try {
      machine::MachineProfile p = machine::default_mill();
      if (profile && profile->text) p = machine::parse_profile(profile->value, "<text>");
      else if (!machine_path.empty()) p = machine::load_profile(machine_path);
      c.emplace(app::build_curve(args, command.remaining(), p));
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      refused = e.what();
    }
  }
  if (!c) throw py::value_error(refused);
  const std::size_t size = given ? static_cast<std::size_t>(given->size()) : static_cast<std::size_t>(count);
  out.t = given ? *given : py::array_t<double>(static_cast<py::ssize_t>(size));
  out.point = py::array_t<double>({static_cast<py::ssize_t>(size), py::ssize_t{3}});
  out.d1 = py::array_t<double>({static_cast<py::ssize_t>(size), py::ssize_t{3}});
  out.d2 = py::array_t<double>({static_cast<py::ssize_t>(size), py::ssize_t{3}});
  out.curvature = py::array_t<double>(static_cast<py::ssize_t>(size));
  double* ts = out.t.mutable_data();
  double *p = out.point.mutable_data(), *d1 = out.d1.mutable_data(), *d2 = out.d2.mutable_data();
  double* k = out.curvature.mutable_data();
  {
    py::gil_scoped_release free_python;
    if (!given)
      for (std::size_t i = 0; i < size; ++i)  // the last exactly t1
        ts[i] = i + 1 == size ? c->t1() : c->t0() + (c->t1() - c->t0()) * static_cast<double>(i) / (size - 1);
    std::vector<geom::Curve::Jet> jets(size);
    c->jets({ts, size}, jets);
    for (std::size_t i = 0; i < size; ++i) {
      for (int a = 0; a < 3; ++a) {
        p[3 * i + a] = jets[i].p[a];
        d1[3 * i + a] = jets[i].d1[a];
        d2[3 * i + a] = jets[i].d2[a];
      }
      k[i] = c->curvature(ts[i]);
    }
  }
  out.name = decoded(c->name());
  out.range = py::make_tuple(c->t0(), c->t1());
  for (const geom::Curve::Param& q : c->params()) out.params[decoded(q.name)] = q.value;
  return out;
}

}  // namespace

void add_curve(py::module_& m) {
  py::class_<CurveSamples>(m, "CurveSamples", "The samples of ncurve.curve(): a curve's points, derivatives and "
                                              "curvature as NumPy arrays.")
      .def_readonly("name", &CurveSamples::name, "the curve's name ('expr' for an expression)")
      .def_readonly("range", &CurveSamples::range, "(t0, t1): the curve's range of t")
      .def_readonly("params", &CurveSamples::params, "every parameter's value, by name")
      .def_readonly("t", &CurveSamples::t, "the values of t sampled (n)")
      .def_readonly("point", &CurveSamples::point, "X Y Z at each t (n x 3), mm")
      .def_readonly("d1", &CurveSamples::d1, "the first derivative with respect to t (n x 3)")
      .def_readonly("d2", &CurveSamples::d2, "the second derivative with respect to t (n x 3)")
      .def_readonly("curvature", &CurveSamples::curvature, "the curvature at each t (n), 1/mm; 0 where straight")
      .def("__repr__", [](const CurveSamples& s) {
        return py::str("<ncurve.CurveSamples: {} at {} values of t>").format(s.name, s.t.size());
      });
  py::options options;
  options.disable_function_signatures();
  m.def("curve", &curve, kDoc, py::arg("curve"), py::kw_only(), py::arg("t") = py::none(), py::arg("n") = 1001,
        py::arg("at") = py::none(), py::arg("machine") = py::none());
}

}  // namespace ncurve::python
