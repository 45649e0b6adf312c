#include "python/common/run_args.hpp"

#include <fmt/format.h>

namespace ncurve::python {
namespace {

// A dict's items as "KEY=VALUE" words of an option: "#" before a --set key without one.
void add_assignments(std::vector<std::string>& words, py::handle values, const char* option, const char* what,
                     bool hash) {
  if (values.is_none()) return;
  if (!py::isinstance<py::dict>(values))
    throw py::type_error(fmt::format("{}: expected a dict, got {}", what,
                                     py::str(py::type::handle_of(values).attr("__name__")).cast<std::string>()));
  for (auto [key, value] : py::reinterpret_borrow<py::dict>(values)) {
    std::string k = option_text(key, what);
    if (hash && !k.starts_with('#')) k = "#" + k;
    words.push_back(fmt::format("{}={}={}", option, k, option_text(value, what)));
  }
}

}  // namespace

RunWords run_words(const py::object& program, const py::object& machine, const py::object& lib, const py::object& set,
                   const py::object& params, const py::object& max_steps, const py::object& max_seconds,
                   bool nose_centre) {
  RunWords out;
  std::vector<std::string>& words = out.words;
  out.source = text_or_path(program, "program");
  words.push_back(out.source->text ? "-" : out.source->value);  // the text is given by apply ("-" passes the file check)
  if (!machine.is_none()) {
    out.profile = text_or_path(machine, "machine");
    if (!out.profile->text) words.push_back("--machine=" + out.profile->value);
  }
  for (const std::string& folder : option_list(lib, "lib")) words.push_back("--lib=" + folder);
  add_assignments(words, set, "--set", "set", true);
  add_assignments(words, params, "--param", "params", false);
  if (!max_steps.is_none()) words.push_back("--max-steps=" + option_text(max_steps, "max_steps"));
  if (!max_seconds.is_none()) words.push_back("--max-seconds=" + option_text(max_seconds, "max_seconds"));
  if (nose_centre) words.push_back("--nose-centre");
  return out;
}

void RunWords::apply(app::RunInputs& in) const {
  if (source && source->text) {
    in.program = "<text>";
    in.text = source->value;
  }
  if (profile && profile->text) {
    in.machine = "<text>";
    in.machine_text = profile->value;
  }
}

}  // namespace ncurve::python
