#include "python/common/cli_args.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ncurve::python {

std::string option_text(py::handle value, std::string_view what) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) {
    py::object path = py::module_::import("os").attr("fspath")(value);
    if (py::isinstance<py::str>(path)) return path.cast<std::string>();
    return py::reinterpret_borrow<py::bytes>(path).cast<std::string>();
  }
  if (PyBool_Check(value.ptr()))  // True is an int to Python, a mistake here
    throw py::type_error(fmt::format("{}: expected a number or a str, got a bool", what));
  if (PyLong_Check(value.ptr()) || PyIndex_Check(value.ptr())) return py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  if (PyFloat_Check(value.ptr()) || PyNumber_Check(value.ptr()))
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  throw py::type_error(fmt::format("{}: expected a str, path or number, got {}", what,
                                   py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>()));
}

TextOrPath text_or_path(py::handle value, std::string_view what) {
  if (!py::isinstance<py::str>(value) && !py::hasattr(value, "__fspath__"))
    throw py::type_error(fmt::format("{}: expected program text (a str with a line break) or a path, got {}", what,
                                     py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>()));
  TextOrPath out{option_text(value, what)};
  out.text = py::isinstance<py::str>(value) && out.value.find_first_of("\r\n") != std::string::npos;
  return out;
}

std::vector<std::string> option_list(py::handle values, std::string_view what) {
  std::vector<std::string> out;
  if (values.is_none()) return out;
  if (py::isinstance<py::str>(values) || py::hasattr(values, "__fspath__")) {
    out.push_back(option_text(values, what));
    return out;
  }
  if (!py::isinstance<py::iterable>(values))
    throw py::type_error(fmt::format("{}: expected a str, a path or a list of them", what));
  for (py::handle v : values) out.push_back(option_text(v, what));
  return out;
}

std::vector<std::string> gains(py::handle values) {
  if (values.is_none()) return {};
  if (py::isinstance<py::str>(values) || !py::isinstance<py::iterable>(values)) return {option_text(values, "kv")};
  std::vector<std::string> out;
  for (py::handle v : values) out.push_back(option_text(v, "kv"));
  return out;
}

void add_curve_words(std::vector<std::string>& words, const py::object& curve, const py::object& t,
                     const py::kwargs& params, std::string_view function) {
  if (curve.is_none() && (py::len(params) > 0 || !t.is_none()))
    throw py::type_error(fmt::format("{}() got an unexpected keyword argument '{}' (a curve's parameter needs curve=)",
                                     function, t.is_none() ? py::str(params.begin()->first).cast<std::string>() : "t"));
  if (curve.is_none()) return;
  const std::string name = option_text(curve, "curve");
  words.push_back("--curve=" + name);
  if (!t.is_none()) {
    if (!py::isinstance<py::sequence>(t) || py::isinstance<py::str>(t) || py::len(t) != 2)
      throw py::type_error("t: expected (FROM, TO)");
    const py::sequence range = py::reinterpret_borrow<py::sequence>(t);
    const std::string from = option_text(range[0], "t"), to = option_text(range[1], "t");
    if (name == "expr") words.push_back(fmt::format("--t={}:{}", from, to));
    else words.insert(words.end(), {"--from=" + from, "--to=" + to});
  }
  for (auto [key, value] : params) {
    const std::string k = key.cast<std::string>();
    if (k == "x" || k == "y" || k == "z") words.push_back(fmt::format("--{}={}", k, option_text(value, k)));
    else words.insert(words.end(), {"--" + k, option_text(value, k)});
  }
}

void parse_options(CLI::App& command, const std::vector<std::string>& words) {
  std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 takes them last first
  try {
    command.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw py::value_error(e.what());
  }
}

py::str decoded(std::string_view text) {
  PyObject* s = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "replace");
  if (!s) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(s);
}

std::string wrapped(std::string_view text, std::size_t indent, std::size_t width) {
  std::string out, line(indent, ' ');
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find(' ', at), text.size());
    const std::string_view word = text.substr(at, end - at);
    if (line.size() > indent && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line.assign(indent, ' ');
    }
    if (line.size() > indent) line += ' ';
    line += word;
    at = end + 1;
  }
  return out + line + "\n";
}

std::string option_name(std::string keyword) {
  std::ranges::replace(keyword, '_', '-');
  return keyword;
}

std::string options_doc(const CLI::App& command, const std::function<bool(const std::string&)>& skip) {
  std::string doc;
  for (const CLI::Option* o : command.get_options()) {
    if (o->get_lnames().empty() || skip(o->get_lnames().front())) continue;
    const std::string& name = o->get_lnames().front();
    std::string keyword = name;
    std::ranges::replace(keyword, '-', '_');
    doc += fmt::format("  {}\n", keyword) + wrapped(fmt::format("{} [--{}]", o->get_description(), name), 6);
  }
  return doc;
}

}  // namespace ncurve::python
