// The arguments run() and analyze() share (program, machine, lib, set, params, max_steps,
// max_seconds, nose_centre) made into the words of the command's run options (--machine=...,
// --set=#100=5, ...), and the program or profile given as text put back after they are parsed.
#pragma once
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "app/run_setup.hpp"
#include "python/common/cli_args.hpp"

namespace ncurve::python {
namespace py = pybind11;

struct RunWords {
  std::vector<std::string> words;  // the program ("-" for text), then the options
  std::optional<TextOrPath> source, profile;
  // After the words are parsed into `in`: the program's and the profile's text, named <text>.
  void apply(app::RunInputs& in) const;
};

RunWords run_words(const py::object& program, const py::object& machine, const py::object& lib, const py::object& set,
                   const py::object& params, const py::object& max_steps, const py::object& max_seconds,
                   bool nose_centre);

}  // namespace ncurve::python
