// Source text, positions in it, and diagnostics that quote the block they refer to.
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "nc/source_file.hpp"

namespace ncurve::nc {

struct Span {
  const SourceFile* file = nullptr;
  std::uint32_t line = 0;    // 1-based
  std::uint32_t column = 0;  // 1-based, in bytes
  std::uint32_t length = 1;
};

enum class Severity { error, warning, note };

struct Diagnostic {
  Severity severity = Severity::error;
  std::string code;  // FANUC alarm ("PS0011", "MC3001") or an ncurve code ("NC1001"); may be empty
  std::string message;
  Span span;
  std::vector<Span> called_from = {};  // an alarm in a called program: the calling blocks, innermost first
};

// The text of the block at a span, without leading and trailing blanks.
std::string block_text(const Span& s);

// "file:line:col: error: PS0011 feed rate is zero" followed by the block and a caret, and a
// "called from file:line (block)" line for each call around it.
// Text from a program or a file name made safe for a terminal: control characters (C0 but the tab,
// DEL and the C1 range as UTF-8 encodes it) as \xNN escapes, so a message cannot move the cursor or retitle
// the window. Other bytes pass unchanged.
std::string escape_controls(std::string_view text);

// "file:line:col: error: PS0011 feed rate is zero" followed by the block and a caret; program text
// (message, file name, quoted block) with its control characters escaped.
std::string format(const Diagnostic& d);

// Raised by the interpreter at the block that causes an alarm; caught by run().
struct Alarm : std::runtime_error {
  explicit Alarm(Diagnostic d) : std::runtime_error(d.message), diagnostic(std::move(d)) {}
  Diagnostic diagnostic;
};

}  // namespace ncurve::nc
