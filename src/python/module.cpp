// The Python module `ncurve`: the library's commands as functions (docs/python.md). Each stage's
// binding is in a folder of its own; this file registers them and finds the shipped files.
#include <dlfcn.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <string>

#include "app/shipped.hpp"
#include "python/analyze/analyze.hpp"
#include "python/common/diagnostic.hpp"
#include "python/gen/gen.hpp"
#include "python/geom/curve.hpp"
#include "python/helicoid/helicoid.hpp"
#include "python/run/run.hpp"
#include "python/verify/verify.hpp"

namespace py = pybind11;

namespace {

// The shipped profiles and macros (--machine fanuc-lathe, --lib macros): beside an installed
// module, NCURVE_PYTHON_SHARE from its folder; in the build folder, the source tree.
void find_shipped_files() {
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void*>(&find_shipped_files), &info) || !info.dli_fname) return;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path here = fs::weakly_canonical(fs::path(info.dli_fname), ec).parent_path();
  for (const fs::path& dir : {here / NCURVE_PYTHON_SHARE, fs::path(NCURVE_SOURCE_DIR)})
    if (fs::is_directory(dir / "profiles", ec) && fs::is_directory(dir / "macros", ec)) {
      ncurve::app::set_shipped_dir(dir.string());
      return;
    }
}

}  // namespace

PYBIND11_MODULE(ncurve, m) {
  m.doc() =
      "ncurve: run, generate and analyse FANUC Custom Macro B programs for non-circular curves (docs/python.md).\n"
      "run() executes a part program as `ncurve run` does and gives its moves as a NumPy array; gen() writes the "
      "program for a curve as `ncurve gen` does; curve() samples a curve as arrays; analyze() plans a program's cycle "
      "time as `ncurve analyze`; circle_test() is `ncurve analyze circle`; helicoid() finds disc-cutter locations "
      "as `ncurve helicoid`; verify() cuts the stock as `ncurve run --verify`.";
  m.attr("__version__") = NCURVE_VERSION;
  find_shipped_files();
  m.def("shipped_dir", &ncurve::app::shipped_dir,
        "The folder of the shipped profiles, macros and examples the names machine='fanuc-lathe' and "
        "lib='macros' are found in (as `ncurve --version` says), or None.");
  ncurve::python::add_diagnostic_class(m);
  ncurve::python::add_run(m);
  ncurve::python::add_gen(m);
  ncurve::python::add_curve(m);
  ncurve::python::add_analyze(m);
  ncurve::python::add_circle_test(m);
  ncurve::python::add_helicoid(m);
  ncurve::python::add_verify(m);
}
