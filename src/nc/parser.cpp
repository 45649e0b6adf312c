// Splits program text into programs and blocks, line by line; each block is compiled by the fast
// path (plain_line) or the general scanner and compile_block (block_parser); loops are paired.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <span>

#include "base/bounds.hpp"
#include "base/memory.hpp"
#include "nc/block_parser.hpp"
#include "nc/plain_line.hpp"
#include "nc/program.hpp"
#include "nc/text.hpp"

namespace ncurve::nc {
namespace {

using namespace text;

// The first kMaxDiagnostics problems of a kind (syntax, loops) and a count of the rest.
struct Problems {
  std::vector<Diagnostic> list;
  std::size_t more = 0;
};

void add_error(Program& p, Block& b, std::string code, std::string message, std::uint16_t column,
               std::uint32_t length, Problems& all) {
  Diagnostic d{Severity::error, std::move(code), std::move(message), Span{p.file.get(), b.line, column, length}};
  if (all.list.size() < kMaxDiagnostics) all.list.push_back(d);
  else ++all.more;
  if (b.error < 0) {
    b.error = static_cast<std::int32_t>(p.errors.size());
    p.errors.push_back(std::move(d));
  }
}

// Pairs DO/WHILE with END in each program; FANUC allows three levels of nesting.
void match_loops(Program& p, Problems& all) {
  std::vector<std::int32_t> open;
  for (std::size_t i = 0; i < p.blocks.size(); ++i) {
    Block& b = p.blocks[i];
    if (b.kind == Statement::while_do || b.kind == Statement::do_loop) {
      if (open.size() >= 3) {
        add_error(p, b, "PS0126", "DO loops nested more than 3 deep", b.column, 1, all);
        continue;
      }
      open.push_back(static_cast<std::int32_t>(i));
    } else if (b.kind == Statement::end_loop) {
      if (!open.empty() && p.blocks[open.back()].loop_id == b.loop_id) {
        b.match = open.back();
        p.blocks[open.back()].match = static_cast<std::int32_t>(i);
        open.pop_back();
      } else if (open.empty()) {
        add_error(p, b, "PS0124", fmt::format("END {} without a DO {} before it", b.loop_id, b.loop_id), b.column, 3,
                  all);
      } else {
        add_error(p, b, "PS0124",
                  fmt::format("END {} closes DO {} (line {}) out of order: loops may nest but not overlap", b.loop_id,
                              p.blocks[open.back()].loop_id, p.blocks[open.back()].line),
                  b.column, 3, all);
      }
    }
  }
  for (std::int32_t i : open) {
    Block& b = p.blocks[i];
    add_error(p, b, "PS0124", fmt::format("DO {} has no END {}", b.loop_id, b.loop_id), b.column, 2, all);
  }
}

struct LineScanner {
  std::array<Ch, kMaxBlockChars> buf;
  std::size_t n = 0;
  std::string comment;
  bool has_comment = false;
  std::string error;
  std::uint16_t error_col = 0;
  // A comment holding a '(' ends at its first ')' all the same: where it opened and closed.
  std::uint16_t nested_open = 0, early_open = 0, early_close = 0;

  void clear() {
    n = 0;
    comment.clear();
    has_comment = false;
    error.clear();
    nested_open = early_open = early_close = 0;
  }
  bool failed() const { return !error.empty(); }
};

// The program number lines (O1234, :1234) in the text the control does not read, after the '%' on
// line end_line that ends the file.
std::vector<UnreadProgram> programs_after_end(const std::string& text, std::size_t pos, std::uint32_t end_line) {
  std::vector<UnreadProgram> found;
  std::uint32_t line = end_line;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    ++line;
    std::size_t k = pos;
    while (k < eol && (text[k] == ' ' || text[k] == '\t')) ++k;
    if (k + 1 < eol && (to_upper(text[k]) == 'O' || text[k] == ':') && is_digit(text[k + 1])) {
      int number = 0;
      for (std::size_t j = k + 1, digits = 0; j < eol && is_digit(text[j]) && digits < 8; ++j, ++digits)
        number = number * 10 + (text[j] - '0');
      found.push_back(UnreadProgram{number, line, end_line});
    }
    pos = eol + 1;
  }
  return found;
}

// The last block alarms when the control reaches it (a text problem, no block skip).
bool follows_alarm(const Program& p) {
  return !p.blocks.empty() && p.blocks.back().error >= 0 && !p.blocks.back().block_skip;
}

// A line that starts no program (O or ':' first) and has no N (but a leading N of a number already
// given, which GOTO does not reach), '/', '%', DO, WHILE (W) or END: none of its blocks is a jump
// target, so after a block that alarms it can never run. Conservative: the letters anywhere on the
// line, comments too.
bool cannot_be_a_target(std::string_view raw, const Program& p) {
  std::size_t k = raw.find_first_not_of(" \t\r");
  if (k != std::string_view::npos && (to_upper(raw[k]) == 'O' || raw[k] == ':')) return false;
  if (k != std::string_view::npos && to_upper(raw[k]) == 'N') {
    std::size_t end = ++k;
    while (end < raw.size() && is_digit(raw[end]) && end - k <= 8) ++end;
    if (end == k || end - k > 8) return false;
    if (!p.sequence_index.contains(std::stoi(std::string(raw.substr(k, end - k))))) return false;
    k = end;
  } else {
    k = 0;
  }
  for (; k < raw.size(); ++k) {
    const char c = to_upper(raw[k]);
    if (c == 'N' || c == '/' || c == '%' || c == 'W') return false;
    if (c == 'D' && k + 1 < raw.size() && to_upper(raw[k + 1]) == 'O') return false;
  }
  return true;
}

}  // namespace

std::size_t compiled_size(std::size_t text_bytes, std::size_t lines) {
  return text_bytes + lines * (sizeof(std::size_t) + sizeof(Block) + sizeof(Word));
}

std::size_t memory_bound(std::size_t text_bytes, const ParseOptions& options) {
  return options.max_memory ? options.max_memory : std::max<std::size_t>(10 * text_bytes, std::size_t{256} << 20);
}

ParseResult parse(std::shared_ptr<const SourceFile> file, ParseOptions options) {
  const int max_digits = std::clamp(options.max_digits, 1, kMostDigits);
  if (const std::size_t need = compiled_size(file->text().size(), file->line_count()),
      bound = memory_bound(file->text().size(), options);
      need > bound)
    throw base::BoundExceeded(fmt::format(
        "{}: {} lines in {:.1f} MB would take at least {:.0f} MB of memory once read ({:.0f} bytes a line), more than "
        "the bound of {:.0f} MB ({}); --max-memory MB raises it",
        file->name(), file->line_count(), file->text().size() / 1e6, need / 1e6,
        static_cast<double>(need) / static_cast<double>(std::max<std::size_t>(file->line_count(), 1)), bound / 1e6,
        options.max_memory ? "--max-memory" : "ten times the program's size, at least 256 MB"));
  ParseResult result;
  std::uint32_t line = 0;
  Program* current = nullptr;
  auto new_program = [&](int number) {
    result.programs.push_back(std::make_unique<Program>());
    current = result.programs.back().get();
    current->number = number;
    current->file = file;
    // The first program of a file usually is all of it: reserving for its lines saves regrowth copies and
    // page faults on long expanded programs. Later programs grow as needed.
    if (result.programs.size() == 1) {
      std::size_t lines_left = file->line_count() > line ? file->line_count() - line : 1;
      base::reserve_large(current->blocks, lines_left + 1);
      base::reserve_large(current->words, 2 * lines_left + 4);
    }
  };
  bool started = false;  // a block has been read (a later '%' ends the file)
  Problems syntax, loops;
  // A block with an error after another such block is never reached: the one before alarms, and only
  // an N makes a block a target (the first block with that N). It is counted, not kept (junk).
  auto drop_if_unreachable = [&](const Block& b) {
    std::vector<Block>& blocks = current->blocks;
    if (b.error < 0 || b.block_skip || blocks.size() < 2) return;
    if (b.sequence >= 0 && current->sequence_index.at(b.sequence) + 1 == static_cast<std::int32_t>(blocks.size()))
      return;  // the first block with its N: a GOTO target
    const Block& before = blocks[blocks.size() - 2];
    if (before.error < 0 || before.block_skip) return;
    if (b.error + 1 == static_cast<std::int32_t>(current->errors.size())) current->errors.pop_back();
    if (b.comment >= 0 && b.comment + 1 == static_cast<std::int32_t>(current->comments.size()))
      current->comments.pop_back();
    blocks.pop_back();
  };

  auto handle_block = [&](LineScanner& ls, std::uint32_t line) {
    std::span<const Ch> s(ls.buf.data(), ls.n);
    std::size_t i = 0;
    // An alarm in the words after a comment that held a '(' comes from its early end.
    auto why = [&ls](std::string message, std::uint16_t column) {
      if (ls.early_close && column > ls.early_close)
        message += fmt::format("; the comment opened at column {} closed early at column {}: a comment ends at its "
                               "first ')' (comments do not nest), and the text after it is read as words",
                               ls.early_open, ls.early_close);
      return message;
    };
    // Program number line: O1234 (NAME), or :1234 in ISO code
    if (!s.empty() && (s[0].c == 'O' || s[0].c == ':') && s.size() > 1 && is_digit(s[1].c)) {
      std::size_t j = 1;
      std::string digits;
      while (j < s.size() && is_digit(s[j].c)) digits += s[j++].c;
      const bool too_long = digits.size() > 8;
      const int number = too_long ? -1 : std::stoi(digits);
      new_program(number > 0 ? number : -1);
      current->line = line;
      if (ls.has_comment) current->name = ls.comment;
      started = true;
      if (too_long || number == 0) {  // the program alarms where it starts
        Block& b = current->blocks.emplace_back();
        b.line = line;
        b.column = s[0].col;
        add_error(*current, b, too_long ? "PS0003" : "PS0074",
                  too_long ? fmt::format("O{}: a program number has at most 8 digits", digits)
                           : std::string("O0 is not a program number: program numbers start at 1"),
                  s[0].col, static_cast<std::uint32_t>(j), syntax);
        return;
      }
      if (j == s.size()) return;
      s = s.subspan(j);
    }
    if (!current) new_program(-1);
    Block& b = current->blocks.emplace_back();
    b.line = line;
    b.column = s.empty() ? 1 : s[0].col;
    if (ls.has_comment) {
      b.comment = static_cast<std::int32_t>(current->comments.size());
      current->comments.push_back(ls.comment);
    }
    if (!ls.error.empty()) {
      add_error(*current, b, "PS0009", why(ls.error, ls.error_col), ls.error_col, 1, syntax);
      started = true;
      drop_if_unreachable(b);
      return;
    }
    if (i < s.size() && s[i].c == '/') {
      b.block_skip = true;
      ++i;
      if (i < s.size() && is_digit(s[i].c)) ++i;
    }
    if (i < s.size() && s[i].c == 'N') {
      std::size_t j = i + 1;
      std::string digits;
      while (j < s.size() && is_digit(s[j].c)) digits += s[j++].c;
      if (digits.empty()) {
        add_error(*current, b, "PS0005", why("no number after address N", s[i].col), s[i].col, 1, syntax);
      } else if (digits.size() > 8) {
        add_error(*current, b, "PS0003", "sequence number has more than 8 digits", s[i].col,
                  static_cast<std::uint32_t>(digits.size() + 1), syntax);
      } else {
        b.sequence = std::stoi(digits);
        current->sequence_index.emplace(b.sequence, static_cast<std::int32_t>(current->blocks.size() - 1));
      }
      i = j;
    }
    if (b.kind == Statement::empty && b.error < 0 && i < s.size()) {
      std::size_t words_mark = current->words.size(), code_mark = current->code.size();
      try {
        compile_block(s.subspan(i), *current, b, max_digits);
      } catch (const SyntaxError& e) {
        current->words.resize(words_mark);
        current->code.resize(code_mark);
        b.kind = Statement::empty;
        b.words_begin = b.words_end = static_cast<std::uint32_t>(words_mark);
        b.target = b.value = b.cond = Expr{};
        add_error(*current, b, e.code, why(e.message, e.column), e.column, e.length, syntax);
      }
    }
    started = true;
    drop_if_unreachable(b);
  };

  const std::string& text = file->text();
  std::size_t pos = 0;
  bool done = false;
  auto scanner = std::make_unique<LineScanner>();
  LineScanner& ls = *scanner;
  while (pos < text.size() && !done) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    ++line;
    std::string_view raw(text.data() + pos, eol - pos);
    pos = eol + 1;

    std::size_t first = raw.find_first_not_of(" \t\r");
    if (first != std::string_view::npos && raw[first] == '%') {
      if (started) done = true;
      continue;
    }
    if (syntax.list.size() >= kMaxDiagnostics && current && follows_alarm(*current) && cannot_be_a_target(raw, *current)) {
      ++result.unchecked_lines;
      continue;
    }
    if (current && plain_nc_line(raw, line, *current, max_digits)) {
      started = true;
      continue;
    }
    ls.clear();
    bool in_comment = false;
    std::size_t comment_start = 0;
    bool block_open = false;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      char c = raw[k];
      if (!in_comment && c > ' ' && c <= '~' && c != '(' && c != ';') {  // the common case first
        block_open = true;
        if (ls.failed()) continue;
        if (ls.n < kMaxBlockChars) {
          ls.buf[ls.n++] = Ch{to_upper(c), clamp_col(k + 1)};
          continue;
        }
        ls.error = fmt::format("block longer than {} characters", kMaxBlockChars);
        ls.error_col = clamp_col(k + 1);
        continue;
      }
      if (in_comment) {
        if (c == ')') {
          in_comment = false;
          ls.has_comment = true;
          if (ls.nested_open && !ls.early_close) {
            ls.early_open = clamp_col(comment_start + 1);
            ls.early_close = clamp_col(k + 1);
          }
        } else if (c == '(' && !ls.nested_open) {
          ls.nested_open = clamp_col(k + 1);
          if (ls.comment.size() < kMaxComment) ls.comment += c;
        } else if (ls.comment.size() < kMaxComment) {
          ls.comment += c;
        }
        continue;
      }
      if (c == '(') {
        in_comment = true;
        comment_start = k;
        if (!ls.early_close) ls.nested_open = 0;
        if (ls.has_comment && ls.comment.size() < kMaxComment) ls.comment += ' ';
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r') continue;
      if (c == ';') {
        handle_block(ls, line);
        ls.clear();
        block_open = false;
        continue;
      }
      block_open = true;  // a control character or a byte outside ASCII
      if (ls.failed()) continue;
      ls.error = fmt::format("invalid character (byte 0x{:02X})", static_cast<unsigned char>(c));
      ls.error_col = clamp_col(k + 1);
    }
    if (in_comment && !ls.failed()) {
      ls.error = "comment '(' is not closed on this line";
      ls.error_col = clamp_col(comment_start + 1);
    }
    if (block_open || !ls.error.empty() || ls.has_comment) handle_block(ls, line);
  }
  if (done) result.after_end = programs_after_end(text, pos, line);
  for (auto& p : result.programs) match_loops(*p, loops);
  std::stable_sort(loops.list.begin(), loops.list.end(),  // a DO without END comes at its program's end
                   [](const Diagnostic& a, const Diagnostic& b) { return a.span.line < b.span.line; });
  // each list is in line order: the first kMaxDiagnostics of both together are among them
  std::vector<Diagnostic>& all = result.diagnostics;
  all.reserve(syntax.list.size() + loops.list.size());
  std::merge(std::make_move_iterator(syntax.list.begin()), std::make_move_iterator(syntax.list.end()),
             std::make_move_iterator(loops.list.begin()), std::make_move_iterator(loops.list.end()),
             std::back_inserter(all), [](const Diagnostic& a, const Diagnostic& b) { return a.span.line < b.span.line; });
  result.more_diagnostics = syntax.more + loops.more;
  if (all.size() > kMaxDiagnostics) {
    result.more_diagnostics += all.size() - kMaxDiagnostics;
    all.resize(kMaxDiagnostics);
  }
  return result;
}

CompiledExpr compile_expression(const std::string& text, const std::string& origin) {
  std::vector<Ch> chars;
  for (std::size_t k = 0; k < text.size(); ++k) {
    unsigned char u = static_cast<unsigned char>(text[k]);
    if (u == ' ' || u == '\t') continue;
    if (u < 32 || u > 126 || chars.size() >= kMaxBlockChars)
      throw Alarm(Diagnostic{Severity::error, "PS0114",
                             fmt::format("{}: column {}: invalid character or expression too long", origin, k + 1),
                             Span{}});
    chars.push_back(Ch{to_upper(static_cast<char>(u)), clamp_col(k + 1)});
  }
  Program p;
  try {
    compile_standalone(chars, p);
  } catch (const SyntaxError& e) {
    throw Alarm(Diagnostic{Severity::error, e.code, fmt::format("{}: column {}: {}", origin, e.column, e.message),
                           Span{}});
  }
  return CompiledExpr{std::move(p.code)};
}

}  // namespace ncurve::nc
