#include "nc/diagnostic.hpp"

#include <fmt/format.h>

#include <cstring>

namespace ncurve::nc {

static const char* severity_name(Severity s) {
  switch (s) {
    case Severity::error: return "error";
    case Severity::warning: return "warning";
    case Severity::note: return "note";
  }
  return "error";
}

std::string block_text(const Span& s) {
  if (!s.file) return {};
  const std::string line = s.file->line(s.line);
  std::string_view text = line;
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == ';')) text.remove_suffix(1);
  return std::string(text);
}

static std::string call_stack(const Diagnostic& d) {
  std::string out;
  for (const Span& s : d.called_from) {
    std::string text(block_text(s).substr(0, 80));
    for (char& c : text)
      if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    out += fmt::format("\n       = called from {}:{} ({})", s.file ? escape_controls(s.file->name()) : "?", s.line, text);
  }
  return out;
}

std::string escape_controls(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const bool c1 = c == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(text[i + 1]) <= 0x9F;
    if (c1) {
      out += fmt::format("\\xc2\\x{:02x}", static_cast<unsigned char>(text[++i]));
    } else if ((c < 0x20 && c != '\t') || c == 0x7F) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += text[i];
    }
  }
  return out;
}

std::string format(const Diagnostic& d) {
  std::string where =
      d.span.file ? fmt::format("{}:{}:{}: ", escape_controls(d.span.file->name()), d.span.line, d.span.column) : "";
  std::string head = fmt::format("{}{}: {}{}{}", where, severity_name(d.severity), escape_controls(d.code),
                                 d.code.empty() ? "" : " ", escape_controls(d.message));
  if (!d.span.file || d.span.line == 0) return head + call_stack(d);
  const std::string line = d.span.file->line(d.span.line);
  const std::string_view text = line;
  constexpr std::size_t kMaxQuote = 160;  // long lines are quoted around the column
  std::size_t col = d.span.column ? d.span.column - 1 : 0;
  std::size_t from = col > kMaxQuote / 2 ? col - kMaxQuote / 2 : 0;
  if (from > text.size()) from = text.size();
  // control characters escaped (\x1b, a tab as a space), other bytes outside ASCII as '?': one column each
  std::string quoted;
  std::size_t caret = std::string::npos;
  const std::string_view part = text.substr(from, kMaxQuote);
  for (std::size_t i = 0; i < part.size(); ++i) {
    if (from + i == col) caret = quoted.size();
    const auto c = static_cast<unsigned char>(part[i]);
    if (c == '\t') quoted += ' ';
    else if (c < 32 || c == 127) quoted += fmt::format("\\x{:02x}", c);
    else quoted += c > 126 ? '?' : part[i];
  }
  if (caret == std::string::npos) caret = quoted.size();
  std::size_t len = d.span.length ? d.span.length : 1;
  if (caret + len > quoted.size() + 1) len = quoted.size() + 1 - caret;
  if (len == 0) len = 1;
  return fmt::format("{}\n {:>5} | {}{}\n       | {}{}{}", head, d.span.line, from ? "..." : "", quoted,
                     std::string(caret + (from ? 3 : 0), ' '), std::string(len, '^'), call_stack(d));
}

}  // namespace ncurve::nc
