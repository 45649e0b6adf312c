#include "python/common/diagnostic.hpp"

#include <fmt/format.h>

#include "python/common/cli_args.hpp"

namespace ncurve::python {
namespace {

// The fields as Python objects, made while the caller holds the GIL.
struct Diagnostic {
  py::str severity, code, message;
  py::object file;  // str, or None when the diagnostic has no place (a run-wide one)
  std::uint32_t line = 0, column = 0;
  py::str block;
  py::list called_from;  // (file, line, block) of the calling blocks, innermost first
  py::str text;          // as the CLI prints it: "file:line:col: error: CODE message", the block, a caret
};

const char* severity_name(nc::Severity s) {
  return s == nc::Severity::error ? "error" : s == nc::Severity::warning ? "warning" : "note";
}

}  // namespace

void add_diagnostic_class(py::module_& m) {
  py::class_<Diagnostic>(m, "Diagnostic",
                         "An alarm, warning or syntax problem of a run: where it is and what it says, as the CLI "
                         "reports it (str() gives the CLI's text).")
      .def_readonly("severity", &Diagnostic::severity, "'error' (an alarm or a syntax error), 'warning' or 'note'")
      .def_readonly("code", &Diagnostic::code, "the FANUC alarm (PS0011, ...) or ncurve code (NC1001, ...); may be ''")
      .def_readonly("message", &Diagnostic::message, "what went wrong")
      .def_readonly("file", &Diagnostic::file, "the program file's name, or None")
      .def_readonly("line", &Diagnostic::line, "1-based line in the file (0: none)")
      .def_readonly("column", &Diagnostic::column, "1-based column, in bytes (0: none)")
      .def_readonly("block", &Diagnostic::block, "the block's text, without leading and trailing blanks")
      .def_readonly("called_from", &Diagnostic::called_from,
                    "an alarm in a called program: (file, line, block) of each calling block, innermost first")
      .def("__str__", [](const Diagnostic& d) { return d.text; })
      .def("__repr__", [](const Diagnostic& d) {
        const std::string where = d.file.is_none() ? std::string()
                                                   : fmt::format(" at {}:{}:{}", py::str(d.file).cast<std::string>(),
                                                                 d.line, d.column);
        return py::str("<ncurve.Diagnostic {} {}{}: {}>")
            .format(d.severity, d.code, py::str(where), d.message);
      });
}

py::object diagnostic_object(const nc::Diagnostic& d) {
  Diagnostic out;
  out.severity = py::str(severity_name(d.severity));
  out.code = decoded(d.code);
  out.message = decoded(d.message);
  out.file = d.span.file ? py::object(decoded(d.span.file->name())) : py::object(py::none());
  out.line = d.span.file ? d.span.line : 0;
  out.column = d.span.file ? d.span.column : 0;
  out.block = decoded(d.span.file ? nc::block_text(d.span) : std::string());
  for (const nc::Span& s : d.called_from)
    out.called_from.append(py::make_tuple(s.file ? py::object(decoded(s.file->name())) : py::object(py::none()),
                                          s.line, decoded(s.file ? nc::block_text(s) : std::string())));
  out.text = decoded(nc::format(d));
  return py::cast(std::move(out));
}

py::list run_diagnostics(const std::vector<nc::Diagnostic>& problems, const machine::RunResult& result, py::object& alarm) {
  py::list all;
  for (const nc::Diagnostic& d : problems) all.append(diagnostic_object(d));
  for (const nc::Diagnostic& d : result.warnings) all.append(diagnostic_object(d));
  alarm = result.alarm ? diagnostic_object(*result.alarm) : py::none();
  if (result.alarm) all.append(alarm);
  return all;
}

}  // namespace ncurve::python
