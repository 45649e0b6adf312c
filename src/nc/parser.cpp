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
#include "nc/line_reader.hpp"
#include "nc/text.hpp"

namespace ncurve::nc {
namespace text {

void Problems::add(Diagnostic d) {
  if (kept < kMaxDiagnostics) {
    if (keep) list.push_back(std::move(d));
    ++kept;
  } else {
    ++more;
  }
}

void add_error(Program& p, Block& b, std::string code, std::string message, std::uint16_t column,
               std::uint32_t length, Problems& all) {
  Diagnostic d{Severity::error, std::move(code), std::move(message), Span{p.file.get(), b.line, column, length}};
  if (b.error < 0) {
    b.error = static_cast<std::int32_t>(p.errors.size());
    p.errors.push_back(d);
  }
  all.add(std::move(d));
}

void LoopMatcher::see(std::int32_t index, const Block& b, const Pair& pair, const Fault& fault) {
  if (b.kind == Statement::while_do || b.kind == Statement::do_loop) {
    if (open_.size() >= 3) {
      fault(index, b.line, b.column, "PS0126", "DO loops nested more than 3 deep", 1);
      return;
    }
    open_.push_back(Open{index, b.loop_id, b.line, b.column});
  } else if (b.kind == Statement::end_loop) {
    if (!open_.empty() && open_.back().id == b.loop_id) {
      pair(open_.back().index, index, b.loop_id, open_.back().line);
      open_.pop_back();
    } else if (open_.empty()) {
      fault(index, b.line, b.column, "PS0124", fmt::format("END {} without a DO {} before it", b.loop_id, b.loop_id), 3);
    } else {
      fault(index, b.line, b.column, "PS0124",
            fmt::format("END {} closes DO {} (line {}) out of order: loops may nest but not overlap", b.loop_id,
                        open_.back().id, open_.back().line),
            3);
    }
  }
}

void LoopMatcher::close(const Fault& fault) {
  for (const Open& o : open_)
    fault(o.index, o.line, o.column, "PS0124", fmt::format("DO {} has no END {}", o.id, o.id), 2);
  open_.clear();
}

void match_loops(Program& p, Problems& all) {
  LoopMatcher m;
  auto pair = [&](std::int32_t d, std::int32_t e, std::uint8_t, std::uint32_t) {
    p.blocks[d].match = e;
    p.blocks[e].match = d;
  };
  auto fault = [&](std::int32_t i, std::uint32_t, std::uint16_t, const char* code, std::string message,
                   std::uint32_t length) {
    Block& b = p.blocks[i];
    add_error(p, b, code, std::move(message), b.column, length, all);
  };
  for (std::size_t i = 0; i < p.blocks.size(); ++i) m.see(static_cast<std::int32_t>(i), p.blocks[i], pair, fault);
  m.close(fault);
}

void programs_after_end(std::string_view text, std::uint32_t& line, std::uint32_t end_line,
                        std::vector<UnreadProgram>& found) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
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
}

void merge_problems(Problems& syntax, Problems& loops, ParseResult& result) {
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
}

struct LineReader::Scanner {
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

LineReader::LineReader(const SourceFile& file, int max_digits, Hooks hooks)
    : file_(file), max_digits_(max_digits), hooks_(std::move(hooks)), scanner_(std::make_unique<Scanner>()) {}
LineReader::~LineReader() = default;

bool LineReader::last_alarms(const Program* current, const ReadState& state) const {
  if (!current || current->blocks.empty()) return current && state.last_alarms;
  return current->blocks.back().error >= 0 && !current->blocks.back().block_skip;
}

// The block is the first of the program with its N (a GOTO target).
bool LineReader::first_with_sequence(const Program& p, const Block& b) const {
  return p.sequence_index.at(b.sequence) + 1 == static_cast<std::int32_t>(p.blocks.size()) &&
         !(hooks_.sequence_before && hooks_.sequence_before(b.sequence));
}

// A block with an error after another such block is never reached: the one before alarms, and only
// an N makes a block a target (the first block with that N). It is counted, not kept (junk).
void LineReader::drop_if_unreachable(const Block& b, ReadState& state, Program& current) {
  std::vector<Block>& blocks = current.blocks;
  if (b.error < 0 || b.block_skip || state.blocks + blocks.size() < 2) return;
  if (b.sequence >= 0 && first_with_sequence(current, b)) return;
  const bool before_alarms = blocks.size() >= 2
                                 ? blocks[blocks.size() - 2].error >= 0 && !blocks[blocks.size() - 2].block_skip
                                 : state.last_alarms;
  if (!before_alarms) return;
  if (b.error + 1 == static_cast<std::int32_t>(current.errors.size())) current.errors.pop_back();
  if (b.comment >= 0 && b.comment + 1 == static_cast<std::int32_t>(current.comments.size()))
    current.comments.pop_back();
  blocks.pop_back();
}

// A line that starts no program (O or ':' first) and has no N (but a leading N of a number already
// given, which GOTO does not reach), '/', '%', DO, WHILE (W) or END: none of its blocks is a jump
// target, so after a block that alarms it can never run. Conservative: the letters anywhere on the
// line, comments too.
bool LineReader::cannot_be_a_target(std::string_view raw, const Program& p) const {
  std::size_t k = raw.find_first_not_of(" \t\r");
  if (k != std::string_view::npos && (to_upper(raw[k]) == 'O' || raw[k] == ':')) return false;
  if (k != std::string_view::npos && to_upper(raw[k]) == 'N') {
    std::size_t end = ++k;
    while (end < raw.size() && is_digit(raw[end]) && end - k <= 8) ++end;
    if (end == k || end - k > 8) return false;
    const std::int32_t n = std::stoi(std::string(raw.substr(k, end - k)));
    if (!p.sequence_index.contains(n) && !(hooks_.sequence_before && hooks_.sequence_before(n))) return false;
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

void LineReader::handle_block(std::uint32_t line, ReadState& state, Program*& current, Problems& syntax) {
  Scanner& ls = *scanner_;
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
  auto new_program = [&](int number) {
    ++state.program;
    state.blocks = 0;
    state.last_alarms = false;
    current = hooks_.new_program(number, line);
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
    state.started = true;
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
    state.started = true;
    drop_if_unreachable(b, state, *current);
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
      compile_block(s.subspan(i), *current, b, max_digits_);
    } catch (const SyntaxError& e) {
      current->words.resize(words_mark);
      current->code.resize(code_mark);
      b.kind = Statement::empty;
      b.words_begin = b.words_end = static_cast<std::uint32_t>(words_mark);
      b.target = b.value = b.cond = Expr{};
      add_error(*current, b, e.code, why(e.message, e.column), e.column, e.length, syntax);
    }
  }
  state.started = true;
  drop_if_unreachable(b, state, *current);
}

void LineReader::read(std::string_view text, ReadState& state, Program*& current, Problems& syntax,
                      std::size_t& unchecked) {
  const bool streamed = !file_.whole();
  std::size_t pos = 0;
  Scanner& ls = *scanner_;
  const std::size_t ended_lines = text.rfind('\n') + 1;  // the lines before end in '\n' (0: none)
  while (pos < text.size() && !state.done) {
    const std::uint32_t line = ++state.line;
    if (streamed) file_.line_read(line, state.offset + pos);
    if (pos < ended_lines && current && syntax.kept < kMaxDiagnostics) {
      if (const char* nl = plain_nc_line(text.data() + pos, line, *current, max_digits_)) {
        state.started = true;
        pos = static_cast<std::size_t>(nl - text.data()) + 1;
        continue;
      }
    }
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view raw(text.data() + pos, eol - pos);
    pos = eol + 1;

    std::size_t first = raw.find_first_not_of(" \t\r");
    if (first != std::string_view::npos && raw[first] == '%') {
      if (state.started) state.done = true;
      continue;
    }
    if (syntax.kept >= kMaxDiagnostics && current && last_alarms(current, state) && cannot_be_a_target(raw, *current)) {
      ++unchecked;
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
        handle_block(line, state, current, syntax);
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
    if (block_open || !ls.error.empty() || ls.has_comment) handle_block(line, state, current, syntax);
  }
  state.offset += std::min(pos, text.size());
}

}  // namespace text

using namespace text;

std::size_t compiled_size(std::size_t text_bytes, std::size_t lines) {
  return text_bytes + lines * (sizeof(std::size_t) + sizeof(Block) + sizeof(Word));
}

std::size_t memory_bound(std::size_t text_bytes, const ParseOptions& options) {
  return options.max_memory ? options.max_memory : std::max<std::size_t>(10 * text_bytes, std::size_t{256} << 20);
}

ParseResult parse(std::shared_ptr<const SourceFile> file, ParseOptions options) {
  const int max_digits = std::clamp(options.max_digits, 1, kMostDigits);
  if (const std::size_t need = compiled_size(file->size(), file->line_count()),
      bound = memory_bound(file->size(), options);
      need > bound)
    throw base::BoundExceeded(fmt::format(
        "{}: {} lines in {:.1f} MB would take at least {:.0f} MB of memory once read ({:.0f} bytes a line), more than "
        "the bound of {:.0f} MB ({}); --max-memory MB raises it",
        file->name(), file->line_count(), file->size() / 1e6, need / 1e6,
        static_cast<double>(need) / static_cast<double>(std::max<std::size_t>(file->line_count(), 1)), bound / 1e6,
        options.max_memory ? "--max-memory" : "ten times the program's size, at least 256 MB"));
  ParseResult result;
  ReadState state;
  LineReader::Hooks hooks;
  hooks.new_program = [&](int number, std::uint32_t line) {
    auto& p = result.programs.emplace_back(std::make_unique<Program>());
    p->number = number;
    p->file = file;
    // The first program of a file usually is all of it: reserving for its lines saves regrowth copies and
    // page faults on long expanded programs. Later programs grow as needed.
    if (result.programs.size() == 1) {
      const std::size_t lines_left = file->line_count() > line ? file->line_count() - line : 1;
      base::reserve_large(p->blocks, lines_left + 1);
      base::reserve_large(p->words, 2 * lines_left + 4);
    }
    return p.get();
  };
  LineReader reader(*file, max_digits, std::move(hooks));
  Program* current = nullptr;
  Problems syntax, loops;
  reader.read(file->text(), state, current, syntax, result.unchecked_lines);
  if (state.done) {
    std::uint32_t line = state.line;
    programs_after_end(file->text().substr(state.offset), line, state.line, result.after_end);
  }
  for (auto& p : result.programs) match_loops(*p, loops);
  merge_problems(syntax, loops, result);
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
