#include "io/toml_text.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace ncurve::io {

void check_toml_nesting(std::string_view text, const std::string& origin) {
  int line = 1;
  std::size_t line_start = 0;
  int parts = 1;     // of the dotted key (or number, or string) being read
  int brackets = 0;  // [ and { open
  auto fail = [&](std::size_t at, const std::string& what) {
    throw std::runtime_error(fmt::format("{}:{}:{}: error: {}", origin, line, at - line_start + 1, what));
  };
  auto next_line = [&](std::size_t at) {
    ++line;
    line_start = at + 1;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"' || c == '\'') {  // a string (a quoted key part is one): skipped, the dotted run goes on
      const bool multi = text.substr(i, 3) == std::string_view(c == '"' ? "\"\"\"" : "'''");
      const std::string_view close = multi ? text.substr(i, 3) : text.substr(i, 1);
      std::size_t j = i + close.size();
      for (; j < text.size(); ++j) {
        if (text[j] == '\n') {
          if (!multi) break;
          next_line(j);
        } else if (c == '"' && text[j] == '\\') {
          if (++j < text.size() && text[j] == '\n') next_line(j);
        } else if (text.substr(j, close.size()) == close) {
          break;
        }
      }
      i = j + close.size() - 1;
      if (j < text.size() && text[j] == '\n') i = j - 1;  // an unclosed string: the line's end is read next
      continue;
    }
    switch (c) {
      case '#':
        while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
        break;
      case '.':
        if (++parts > kMaxTomlKeyParts)
          fail(i, fmt::format("a dotted key of more than {} parts: a machine profile's or a setup's tables nest a few levels",
                              kMaxTomlKeyParts));
        break;
      case '[':
      case '{':
        if (++brackets > kMaxTomlBrackets)
          fail(i, fmt::format("arrays or inline tables nested more than {} deep", kMaxTomlBrackets));
        parts = 1;
        break;
      case ']':
      case '}':
        if (brackets > 0) --brackets;
        parts = 1;
        break;
      case '\n':
        next_line(i);
        parts = 1;
        break;
      case '=':
      case ',':
        parts = 1;
        break;
      default:
        break;
    }
  }
}

toml::table parse_toml(std::string_view text, const std::string& origin) {
  check_toml_nesting(text, origin);
  try {
    return toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(fmt::format("{}:{}:{}: error: {}", origin, e.source().begin.line,
                                         e.source().begin.column, e.description()));
  }
}

}  // namespace ncurve::io
