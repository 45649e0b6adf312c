#include "nc/diagnostic.hpp"

#include <fmt/format.h>

#include <cstring>

namespace ncurve::nc {

SourceFile::SourceFile(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
  line_starts_.push_back(0);
  const char* begin = text_.data();
  const char* end = begin + text_.size();
  for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', end - p))) != nullptr;)
    line_starts_.push_back(static_cast<std::size_t>(++p - begin));
  if (line_starts_.size() > 1 && line_starts_.back() == text_.size()) line_starts_.pop_back();
}

std::string_view SourceFile::line(std::uint32_t number) const {
  if (number == 0 || number > line_starts_.size()) return {};
  std::size_t begin = line_starts_[number - 1];
  std::size_t end = number < line_starts_.size() ? line_starts_[number] : text_.size();
  while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
  return std::string_view(text_).substr(begin, end - begin);
}

static const char* severity_name(Severity s) {
  switch (s) {
    case Severity::error: return "error";
    case Severity::warning: return "warning";
    case Severity::note: return "note";
  }
  return "error";
}

std::string_view block_text(const Span& s) {
  if (!s.file) return {};
  std::string_view text = s.file->line(s.line);
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == ';')) text.remove_suffix(1);
  return text;
}

static std::string call_stack(const Diagnostic& d) {
  std::string out;
  for (const Span& s : d.called_from) {
    std::string text(block_text(s).substr(0, 80));
    for (char& c : text)
      if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    out += fmt::format("\n       = called from {}:{} ({})", s.file ? s.file->name() : "?", s.line, text);
  }
  return out;
}

std::string format(const Diagnostic& d) {
  std::string where = d.span.file ? fmt::format("{}:{}:{}: ", d.span.file->name(), d.span.line, d.span.column) : "";
  std::string head = fmt::format("{}{}: {}{}{}", where, severity_name(d.severity), d.code, d.code.empty() ? "" : " ",
                                 d.message);
  if (!d.span.file || d.span.line == 0) return head + call_stack(d);
  std::string_view text = d.span.file->line(d.span.line);
  constexpr std::size_t kMaxQuote = 160;  // long lines are quoted around the column
  std::size_t col = d.span.column ? d.span.column - 1 : 0;
  std::size_t from = col > kMaxQuote / 2 ? col - kMaxQuote / 2 : 0;
  if (from > text.size()) from = text.size();
  std::string quoted(text.substr(from, kMaxQuote));
  for (char& c : quoted)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  std::size_t caret = col - from;
  if (caret > quoted.size()) caret = quoted.size();
  std::size_t len = d.span.length ? d.span.length : 1;
  if (caret + len > quoted.size() + 1) len = quoted.size() + 1 - caret;
  if (len == 0) len = 1;
  return fmt::format("{}\n {:>5} | {}{}\n       | {}{}{}", head, d.span.line, from ? "..." : "", quoted,
                     std::string(caret + (from ? 3 : 0), ' '), std::string(len, '^'), call_stack(d));
}

}  // namespace ncurve::nc
