// Python arguments made into the command line's option values, parsed by the command's own CLI11
// options, so that a bad value is refused with the message `ncurve` gives (as a ValueError).
#pragma once
#include <CLI/CLI.hpp>
#include <pybind11/pybind11.h>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncurve::python {
namespace py = pybind11;

// An option's value as the command line would carry it: a str as it is, an os.PathLike as its
// path, an int in decimal, a float (or NumPy number) as Python's repr, which reads back exactly.
// TypeError naming `what` for anything else.
std::string option_text(py::handle value, std::string_view what);
// A str (or os.PathLike) that names a file, or a str holding a line break: the text itself.
struct TextOrPath {
  std::string value;
  bool text = false;
};
TextOrPath text_or_path(py::handle value, std::string_view what);
// One value or an iterable of them (a single str or path is one), each by option_text.
std::vector<std::string> option_list(py::handle values, std::string_view what);

// --kv's values: one gain (a number) or a list of them, each by option_text.
std::vector<std::string> gains(py::handle values);

// A curve as `--curve` takes it (run --verify, analyze): --curve=NAME, t=(FROM, TO) as --from/--to
// (--t FROM:TO for expr), expr's x, y, z as their options and every other parameter as the pair
// --NAME VALUE the command leaves over for the curve. TypeError for a parameter without a curve.
void add_curve_words(std::vector<std::string>& words, const py::object& curve, const py::object& t,
                     const py::kwargs& params, std::string_view function);

// Parses "--option=value" words (and positional values) in order with the command's options;
// ValueError with CLI11's message ("--machine: no profile file 'x' ...") for a bad one.
void parse_options(CLI::App& command, const std::vector<std::string>& words);

// Text from the library as a Python str: UTF-8, bytes that are not as U+FFFD (as the CLI's JSON).
py::str decoded(std::string_view text);

// `text` wrapped to lines of at most `width` characters, each after `indent` spaces (the first too).
std::string wrapped(std::string_view text, std::size_t indent, std::size_t width = 100);

// A Python keyword's option name: its underscores as dashes (nose_centre: nose-centre).
std::string option_name(std::string keyword);
// The command's options as a docstring lists them, those `skip` names by long name left out: each
// keyword (dashes as underscores) and under it the option's description and [--option].
std::string options_doc(const CLI::App& command, const std::function<bool(const std::string&)>& skip);

}  // namespace ncurve::python
