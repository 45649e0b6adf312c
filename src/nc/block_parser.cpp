#include "nc/block_parser.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ncurve::nc::text {
namespace {

enum class Kw {
  none, IF, WHILE, GOTO, DO, END, THEN,
  EQ, NE, GT, GE, LT, LE, AND, OR, XOR, MOD,
  SIN, COS, TAN, ASIN, ACOS, ATAN, SQRT, ABS, ROUND, FIX, FUP, LN, EXP, POW, ADP, BIN, BCD,
};

struct KwEntry {
  const char* text;
  Kw kw;
};

// Macro words and FANUC's two-letter abbreviations of them.
constexpr KwEntry kKeywords[] = {
    {"IF", Kw::IF},       {"WHILE", Kw::WHILE}, {"WH", Kw::WHILE}, {"GOTO", Kw::GOTO}, {"GO", Kw::GOTO},
    {"DO", Kw::DO},       {"END", Kw::END},     {"EN", Kw::END},   {"THEN", Kw::THEN}, {"TH", Kw::THEN},
    {"EQ", Kw::EQ},       {"NE", Kw::NE},       {"GT", Kw::GT},    {"GE", Kw::GE},     {"LT", Kw::LT},
    {"LE", Kw::LE},       {"AND", Kw::AND},     {"AN", Kw::AND},   {"OR", Kw::OR},     {"XOR", Kw::XOR},
    {"XO", Kw::XOR},      {"MOD", Kw::MOD},     {"MO", Kw::MOD},   {"SIN", Kw::SIN},   {"SI", Kw::SIN},
    {"COS", Kw::COS},     {"CO", Kw::COS},      {"TAN", Kw::TAN},  {"TA", Kw::TAN},    {"ASIN", Kw::ASIN},
    {"AS", Kw::ASIN},     {"ACOS", Kw::ACOS},   {"AC", Kw::ACOS},  {"ATAN", Kw::ATAN}, {"AT", Kw::ATAN},
    {"SQRT", Kw::SQRT},   {"SQ", Kw::SQRT},     {"ABS", Kw::ABS},  {"AB", Kw::ABS},    {"ROUND", Kw::ROUND},
    {"RO", Kw::ROUND},    {"FIX", Kw::FIX},     {"FI", Kw::FIX},   {"FUP", Kw::FUP},   {"FU", Kw::FUP},
    {"LN", Kw::LN},       {"EXP", Kw::EXP},     {"EX", Kw::EXP},   {"POW", Kw::POW},   {"PO", Kw::POW},
    {"ADP", Kw::ADP},     {"AD", Kw::ADP},      {"BIN", Kw::BIN},  {"BI", Kw::BIN},    {"BCD", Kw::BCD},
    {"BC", Kw::BCD},
};

bool is_macro_statement_word(Kw k) {
  return k == Kw::IF || k == Kw::WHILE || k == Kw::GOTO || k == Kw::DO || k == Kw::END || k == Kw::THEN;
}

Op function_op(Kw k) {
  switch (k) {
    case Kw::SIN: return Op::sin;
    case Kw::COS: return Op::cos;
    case Kw::TAN: return Op::tan;
    case Kw::ASIN: return Op::asin;
    case Kw::ACOS: return Op::acos;
    case Kw::SQRT: return Op::sqrt;
    case Kw::ABS: return Op::abs;
    case Kw::ROUND: return Op::round;
    case Kw::FIX: return Op::fix;
    case Kw::FUP: return Op::fup;
    case Kw::LN: return Op::ln;
    case Kw::EXP: return Op::exp;
    case Kw::ADP: return Op::adp;
    case Kw::BIN: return Op::bin;
    case Kw::BCD: return Op::bcd;
    default: return Op::konst;
  }
}

// Parses one block (already stripped of spaces and comments, upper case) into a Block.
class BlockParser {
public:
  // max_digits: every digit typed counts, as on the control; a curve's expression (outside any
  // program) counts significant digits only.
  BlockParser(std::span<const Ch> s, Program& prog, int max_digits, bool leading_zeros_count = true)
      : s_(s), prog_(prog), max_digits_(max_digits), leading_zeros_count_(leading_zeros_count) {}

  void statement(Block& b) {
    if (i_ == s_.size()) return;
    b.column = s_[i_].col;
    if (peek() == '#') return assignment(b, Statement::assign);
    if (output_statement(b)) return;
    std::size_t len = 0;
    Kw k = keyword_at(i_, len);
    if (is_macro_statement_word(k)) return macro_statement(b, k, len);
    nc_words(b);
  }

  Expr standalone_expression() {
    Expr e = begin_expr();
    expression();
    if (i_ != s_.size()) fail("PS0114", "unexpected text after the expression");
    return finish_expr(e);
  }

private:
  std::span<const Ch> s_;
  Program& prog_;
  int max_digits_;
  bool leading_zeros_count_;
  int fraction_ = 0;  // digits after the point of the last number read
  std::size_t i_ = 0;
  int depth_ = 0;      // bracket nesting
  int stack_ = 0;      // evaluation stack depth while emitting
  int max_stack_ = 0;
  bool condition_ = false;

  char peek(std::size_t ahead = 0) const { return i_ + ahead < s_.size() ? s_[i_ + ahead].c : '\0'; }
  std::uint16_t col() const { return i_ < s_.size() ? s_[i_].col : (s_.empty() ? 1 : s_.back().col + 1); }

  [[noreturn]] void fail(std::string code, std::string message, std::uint32_t length = 1) const {
    throw SyntaxError{std::move(code), std::move(message), col(), length};
  }

  Kw keyword_at(std::size_t at, std::size_t& len) const {
    std::size_t run = 0;
    while (at + run < s_.size() && is_upper(s_[at + run].c)) ++run;
    len = 0;
    if (run < 2) return Kw::none;
    Kw best = Kw::none;
    for (const auto& e : kKeywords) {
      std::size_t n = std::strlen(e.text);
      if (n > run || n <= len) continue;
      bool same = true;
      for (std::size_t j = 0; j < n && same; ++j) same = s_[at + j].c == e.text[j];
      if (same) { best = e.kw; len = n; }
    }
    return best;
  }

  Kw take_keyword() {
    std::size_t len = 0;
    Kw k = keyword_at(i_, len);
    if (k != Kw::none) i_ += len;
    return k;
  }

  void expect(char c, const char* what) {
    if (peek() != c) fail("PS0114", fmt::format("expected '{}' {}", c, what));
    ++i_;
  }

  // ---- code emission ----
  Expr begin_expr() const { return Expr{static_cast<std::uint32_t>(prog_.code.size()), 0}; }
  Expr finish_expr(Expr e) const {
    e.end = static_cast<std::uint32_t>(prog_.code.size());
    return e;
  }
  void emit(Op op, std::uint16_t column, std::int32_t var = 0, double k = 0) {
    if (op == Op::konst || op == Op::var) ++stack_;
    if (op >= Op::add && op <= Op::le) --stack_;
    if (op == Op::atan2_slash || op == Op::atan2_comma || op == Op::pow) --stack_;
    max_stack_ = std::max(max_stack_, stack_);
    if (max_stack_ >= kMaxEvalStack) fail("PS0114", "expression is too complex");
    prog_.code.push_back(Instr{op, column, var, k});
  }

  // ---- numbers ----
  // Up to max_digits_ (15 at most) digits: the integer mantissa and the power of ten are exact
  // doubles, so one division gives the correctly rounded value, as strtod would.
  double number(bool& decimal_point) {
    std::size_t start = i_;
    std::int64_t mantissa = 0;
    int digits = 0, fraction = 0;
    decimal_point = false;
    for (char c = peek(); is_digit(c) || c == '.'; c = peek()) {
      if (c == '.') {
        if (decimal_point) fail("PS0007", "a number has two decimal points");
        decimal_point = true;
      } else {
        if ((leading_zeros_count_ || mantissa != 0 || c != '0') && ++digits > max_digits_) {
          std::size_t end = i_;
          while (end < s_.size() && (is_digit(s_[end].c) || s_[end].c == '.')) ++end;
          i_ = start;
          fail("PS0003",
               leading_zeros_count_ ? fmt::format("too many digits; this control takes {} (leading zeros count; "
                                                  "machine profile number_digits)", max_digits_)
                                    : fmt::format("too many digits; at most {} significant", max_digits_),
               static_cast<std::uint32_t>(end - start));
        }
        mantissa = mantissa * 10 + (c - '0');
        if (decimal_point) ++fraction;
      }
      ++i_;
    }
    if (i_ - start == 1 && decimal_point) {
      i_ = start;
      fail("PS0007", "a decimal point without digits");
    }
    fraction_ = fraction;
    return scaled_decimal(mantissa, fraction);
  }

  // ---- expressions ----
  void expression() {
    sum();
    std::size_t len = 0;
    Kw k = keyword_at(i_, len);
    if (k >= Kw::EQ && k <= Kw::LE) {
      if (!condition_) fail("PS0114", "EQ, NE, GT, GE, LT and LE may only be used in IF and WHILE conditions", len);
      std::uint16_t c = col();
      i_ += len;
      sum();
      static constexpr Op kRel[] = {Op::eq, Op::ne, Op::gt, Op::ge, Op::lt, Op::le};
      emit(kRel[static_cast<int>(k) - static_cast<int>(Kw::EQ)], c);
      Kw again = keyword_at(i_, len);
      if (again >= Kw::EQ && again <= Kw::LE)
        fail("PS0114", "two comparisons in one bracket; bracket each one: [[a GT b] AND [c LT d]]", len);
    }
  }

  void sum() {
    term();
    for (;;) {
      std::uint16_t c = col();
      std::size_t len = 0;
      if (peek() == '+' || peek() == '-') {
        Op op = peek() == '+' ? Op::add : Op::sub;
        ++i_;
        term();
        emit(op, c);
      } else if (Kw k = keyword_at(i_, len); k == Kw::OR || k == Kw::XOR) {
        i_ += len;
        term();
        emit(k == Kw::OR ? Op::bor : Op::bxor, c);
      } else {
        return;
      }
    }
  }

  void term() {
    unary();
    for (;;) {
      std::uint16_t c = col();
      std::size_t len = 0;
      if (peek() == '*' || peek() == '/') {
        Op op = peek() == '*' ? Op::mul : Op::div;
        ++i_;
        unary();
        emit(op, c);
      } else if (Kw k = keyword_at(i_, len); k == Kw::AND || k == Kw::MOD) {
        i_ += len;
        unary();
        emit(k == Kw::AND ? Op::band : Op::mod, c);
      } else {
        return;
      }
    }
  }

  void unary() {
    if (peek() == '-' || peek() == '+') {
      std::uint16_t c = col();
      bool negative = peek() == '-';
      ++i_;
      if (peek() == '-' || peek() == '+') fail("PS0006", "two signs in a row");
      primary();
      if (negative) emit(Op::neg, c);
      return;
    }
    primary();
  }

  void bracketed(bool allow_condition) {
    std::uint16_t c = col();
    expect('[', "");
    if (++depth_ > kMaxBracketNesting) {
      i_--;
      fail("PS0118", fmt::format("brackets nested more than {} deep", kMaxBracketNesting));
    }
    bool saved = condition_;
    condition_ = condition_ && allow_condition;
    if (peek() == ']') fail("PS0114", "empty brackets");
    expression();
    condition_ = saved;
    if (peek() != ']') {
      if (i_ == s_.size()) fail("PS0114", fmt::format("missing ']' for the '[' at column {}", c));
      fail("PS0114", "expected ']' or an operator");
    }
    ++i_;
    --depth_;
  }

  void variable() {
    std::uint16_t c = col();
    expect('#', "");
    if (peek() == '[') {
      bracketed(false);
      emit(Op::var_indirect, c);
      return;
    }
    if (!is_digit(peek()))
      fail("PS0114", "'#' must be followed by a variable number or [expression]");
    bool dp = false;
    double n = number(dp);
    if (dp) fail("PS0114", "a variable number has no decimal point");
    if (n > 99999999) fail("PS0115", "variable number out of range");
    emit(Op::var, c, static_cast<std::int32_t>(n));
  }

  void primary() {
    char c = peek();
    std::uint16_t column = col();
    if (is_digit(c) || c == '.') {
      bool dp = false;
      double v = number(dp);
      emit(Op::konst, column, 0, v);
      return;
    }
    if (c == '#') return variable();
    if (c == '[') return bracketed(true);
    if (is_upper(c)) {
      std::size_t len = 0;
      Kw k = keyword_at(i_, len);
      if (k == Kw::ATAN) {  // ATAN[a]/[b], ATAN[a,b] (30i) or ATAN[a]
        i_ += len;
        if (function_arguments("ATAN") == 2) {
          emit(Op::atan2_comma, column);
        } else if (peek() == '/' && peek(1) == '[') {
          ++i_;
          bracketed(false);
          emit(Op::atan2_slash, column);
        } else {
          emit(Op::atan1, column);
        }
        return;
      }
      if (k == Kw::POW) {
        i_ += len;
        std::size_t open = i_;
        if (function_arguments("POW") != 2) {
          i_ = open;
          fail("PS0114", "POW takes two arguments: POW[base,exponent]");
        }
        emit(Op::pow, column);
        return;
      }
      Op f = function_op(k);
      if (f != Op::konst) {
        i_ += len;
        if (peek() != '[') fail("PS0114", "a function's argument must be in brackets");
        bracketed(false);
        emit(f, column);
        return;
      }
      fail("PS0114", fmt::format("'{}' is not a function or value", c));
    }
    if (c == '\0') fail("PS0114", "expression ends too early");
    fail("PS0114", fmt::format("unexpected '{}' in an expression", c));
  }

  // [a] or [a,b] after a function name; returns how many arguments were given.
  int function_arguments(const char* name) {
    std::uint16_t open = col();
    if (peek() != '[') fail("PS0114", fmt::format("{} needs its argument in brackets", name));
    ++i_;
    if (++depth_ > kMaxBracketNesting) fail("PS0118", "brackets nested more than 5 deep");
    bool saved = condition_;
    condition_ = false;
    expression();
    int count = 1;
    if (peek() == ',') {
      ++i_;
      expression();
      count = 2;
    }
    condition_ = saved;
    if (peek() != ']') fail("PS0114", fmt::format("missing ']' for the '[' at column {}", open));
    ++i_;
    --depth_;
    return count;
  }

  // A value for an address: number, #i, -#i, [expr], -[expr].
  void word_value(Word& w) {
    bool negative = false;
    std::uint16_t sign_col = col();
    if (peek() == '-' || peek() == '+') {
      negative = peek() == '-';
      ++i_;
    }
    char c = peek();
    if (is_digit(c) || c == '.') {
      w.value = number(w.decimal_point);
      w.decimals = static_cast<std::uint8_t>(std::min(fraction_, 255));
      if (negative) w.value = -w.value;
      return;
    }
    if (c == '#' || c == '[') {
      w.literal = false;
      Expr e = begin_expr();
      stack_ = max_stack_ = 0;
      if (c == '#') variable(); else bracketed(false);
      if (negative) emit(Op::neg, sign_col);
      w.expr = finish_expr(e);
      return;
    }
    fail("PS0005", fmt::format("no value after address {}", w.letter));
  }

  void nc_words(Block& b) {
    b.kind = Statement::nc;
    b.words_begin = static_cast<std::uint32_t>(prog_.words.size());
    while (i_ < s_.size()) {
      char c = peek();
      if (c == ',') {  // ,C ,R (chamfering, corner R) and ,A (angle): kept as the letters c, r, a
        comma_word();
        continue;
      }
      if (!is_upper(c)) {
        if (c == '+' || c == '-' || is_digit(c) || c == '.')
          fail("PS0004", "a number or sign without an address (arithmetic in a word needs brackets: X[#1+5.])");
        if (c == '=') fail("PS0009", "'=' in an NC block: only a variable (#i) can be assigned");
        if (c == ':' && prog_.words.size() == b.words_begin)
          fail("PS0005", "no program number after ':' (the program number address of ISO code, as O)");
        if (c == ':') fail("PS0009", "':' (the program number address of ISO code, as O) is only allowed at the start of a block");
        fail("PS0009", fmt::format("'{}' is not an address", c));
      }
      std::size_t len = 0;
      Kw k = keyword_at(i_, len);
      if (is_macro_statement_word(k))
        fail("PS0127", "an NC statement and a macro statement in one block", static_cast<std::uint32_t>(len));
      if (len > 0 || (i_ + 1 < s_.size() && is_upper(peek(1)))) {
        std::string run;
        for (std::size_t j = i_; j < s_.size() && is_upper(s_[j].c); ++j) run += s_[j].c;
        fail("PS0009", fmt::format("'{}' is not an address: an address is one letter followed by a value", run),
             static_cast<std::uint32_t>(run.size()));
      }
      if ((c == 'O' || c == 'N') && prog_.words.size() == b.words_begin && !is_digit(peek(1)))
        fail("PS0005", fmt::format("no {} after address {}", c == 'O' ? "program number" : "sequence number", c));
      if (c == 'O' || c == 'N') fail("PS0009", fmt::format("address {} is only allowed at the start of a block", c));
      Word w;
      w.letter = c;
      w.column = col();
      ++i_;
      word_value(w);
      prog_.words.push_back(w);
    }
    b.words_end = static_cast<std::uint32_t>(prog_.words.size());
  }

  void comma_word() {
    Word w;
    w.column = col();
    ++i_;
    const char c = peek();
    if (c != 'C' && c != 'R' && c != 'A')
      fail("PS0053", "a comma must be followed by C (chamfering), R (corner R) or A (angle)");
    w.letter = static_cast<char>(c - 'A' + 'a');
    ++i_;
    word_value(w);
    prog_.words.push_back(w);
  }

  void assignment(Block& b, Statement kind) {
    b.kind = kind;
    std::uint16_t c = col();
    expect('#', "");
    if (peek() == '[') {
      Expr e = begin_expr();
      stack_ = max_stack_ = 0;
      bracketed(false);
      b.target = finish_expr(e);
    } else {
      if (!is_digit(peek()))
        fail("PS0114", "'#' must be followed by a variable number or [expression]");
      bool dp = false;
      double n = number(dp);
      if (dp || n > 99999999) fail("PS0115", "bad variable number");
      b.target_var = static_cast<std::int32_t>(n);
      if (b.target_var == 0) {
        i_ = 0;
        throw SyntaxError{"PS0116", "#0 is always vacant and cannot be assigned", c, 2};
      }
    }
    if (peek() != '=') {
      if (i_ == s_.size()) fail("PS0114", "a variable alone is not a statement: expected '='");
      fail("PS0127", "expected '=' after the variable (NC words cannot follow a variable)");
    }
    ++i_;
    if (i_ == s_.size()) fail("PS0114", "nothing after '='");
    Expr e = begin_expr();
    stack_ = max_stack_ = 0;
    expression();
    b.value = finish_expr(e);
    if (i_ != s_.size()) {
      if (is_upper(peek()))
        fail("PS0127", "an NC word after an assignment: a macro statement and NC words in one block");
      if (peek() == ':')
        fail("PS0114", "':' after the expression: ':' is the program number address of ISO code (as O), only "
                       "allowed at the start of a block; a block ends with ';' or the end of the line");
      fail("PS0114", "expected an operator or the end of the block");
    }
  }

  Expr condition() {
    if (peek() != '[') fail("PS0114", "the condition must be in brackets: IF [#1 GT 0] ...");
    Expr e = begin_expr();
    stack_ = max_stack_ = 0;
    condition_ = true;
    bracketed(true);
    condition_ = false;
    return finish_expr(e);
  }

  Expr jump_target() {
    if (i_ == s_.size()) fail("PS0128", "GOTO needs a sequence number");
    Expr e = begin_expr();
    stack_ = max_stack_ = 0;
    expression();
    return finish_expr(e);
  }

  std::uint8_t loop_number() {
    if (!is_digit(peek())) fail("PS0126", "DO and END need a loop number 1, 2 or 3");
    bool dp = false;
    std::uint16_t c = col();
    double n = number(dp);
    if (dp || n < 1 || n > 3) throw SyntaxError{"PS0126", "the loop number of DO/END must be 1, 2 or 3", c, 1};
    return static_cast<std::uint8_t>(n);
  }

  bool word_at(const char* w) const {
    std::size_t n = std::strlen(w);
    for (std::size_t j = 0; j < n; ++j)
      if (peek(j) != w[j]) return false;
    return true;
  }

  // External output commands (FANUC operator's manual, custom macro: external output commands):
  // POPEN, PCLOS, DPRNT [a #b [cd] ...], BPRNT [a #b [c] ...]. Characters: letters, digits and
  // * / + - ? @ & _ ('*' is sent as a space); spaces are not sent (they are not read).
  bool output_statement(Block& b) {
    static constexpr struct {
      const char* word;
      Statement kind;
    } kWords[] = {{"POPEN", Statement::popen},
                  {"PCLOS", Statement::pclos},
                  {"DPRNT", Statement::dprnt},
                  {"BPRNT", Statement::bprnt}};
    for (const auto& w : kWords) {
      if (!word_at(w.word)) continue;
      i_ += 5;
      b.kind = w.kind;
      if (w.kind == Statement::dprnt || w.kind == Statement::bprnt) print_items(b, w.kind == Statement::dprnt);
      if (i_ != s_.size()) fail("PS0114", fmt::format("unexpected text after {}", w.word));
      return true;
    }
    return false;
  }

  void print_items(Block& b, bool decimal) {
    const char* name = decimal ? "DPRNT" : "BPRNT";
    if (peek() != '[') fail("PS0114", fmt::format("{} needs its items in brackets: {}[...]", name, name));
    const std::uint16_t open = col();
    ++i_;
    b.words_begin = static_cast<std::uint32_t>(prog_.prints.size());
    for (;;) {
      const char c = peek();
      if (c == ']') break;
      if (c == '\0') fail("PS0114", fmt::format("missing ']' for the '[' of {} at column {}", name, open));
      PrintItem item;
      item.column = col();
      if (c == '#') {
        Expr e = begin_expr();
        stack_ = max_stack_ = 0;
        variable();
        item.var = finish_expr(e);
        print_format(item, decimal);
      } else {
        const bool allowed = is_upper(c) || is_digit(c) || std::strchr("*/+-?@&_", c) != nullptr;
        if (!allowed)
          fail("PS0114", fmt::format("'{}' cannot be output by {} (letters, digits and * / + - ? @ & _; '*' is a "
                                     "space)", c, name));
        while (peek() != '\0' && (is_upper(peek()) || is_digit(peek()) || std::strchr("*/+-?@&_", peek())))
          item.text += peek(), ++i_;
      }
      prog_.prints.push_back(std::move(item));
    }
    ++i_;
    b.words_end = static_cast<std::uint32_t>(prog_.prints.size());
  }

  // [cd] after a DPRNT variable (integer and decimal digits, together at most 8), [c] after a BPRNT
  // one (decimal places).
  void print_format(PrintItem& item, bool decimal) {
    const char* need = decimal ? "[cd]: its integer digits c and decimal digits d, e.g. #100[53]"
                               : "[c]: its decimal places, e.g. #100[3]";
    if (peek() != '[') fail("PS0114", fmt::format("a variable of {} needs its format {}", decimal ? "DPRNT" : "BPRNT", need));
    const std::uint16_t at = col();
    ++i_;
    std::string digits;
    while (is_digit(peek())) digits += peek(), ++i_;
    if (peek() != ']' || digits.size() != (decimal ? 2u : 1u))
      throw SyntaxError{"PS0114", fmt::format("bad format: {} needs {}", decimal ? "DPRNT" : "BPRNT", need), at, 1};
    ++i_;
    if (decimal) {
      item.integers = static_cast<std::uint8_t>(digits[0] - '0');
      item.decimals = static_cast<std::uint8_t>(digits[1] - '0');
      if (item.integers + item.decimals > 8 || item.integers + item.decimals == 0)
        throw SyntaxError{"PS0114", fmt::format("DPRNT format [{}]: integer and decimal digits together are 1 to 8",
                                                digits), at, 4};
    } else {
      item.decimals = static_cast<std::uint8_t>(digits[0] - '0');
    }
  }

  void macro_statement(Block& b, Kw k, std::size_t len) {
    i_ += len;
    switch (k) {
      case Kw::GOTO:
        b.kind = Statement::go_to;
        b.value = jump_target();
        break;
      case Kw::IF: {
        b.cond = condition();
        Kw then = take_keyword();
        if (then == Kw::GOTO) {
          b.kind = Statement::if_goto;
          b.value = jump_target();
        } else if (then == Kw::THEN) {
          if (peek() != '#') fail("PS0114", "THEN must be followed by an assignment #i = ...");
          assignment(b, Statement::if_then);
        } else {
          fail("PS0114", "IF [condition] must be followed by GOTO n or THEN #i = ...");
        }
        break;
      }
      case Kw::WHILE: {
        b.cond = condition();
        if (take_keyword() != Kw::DO) fail("PS0114", "WHILE [condition] must be followed by DO m");
        b.kind = Statement::while_do;
        b.loop_id = loop_number();
        break;
      }
      case Kw::DO:
        b.kind = Statement::do_loop;
        b.loop_id = loop_number();
        break;
      case Kw::END:
        b.kind = Statement::end_loop;
        b.loop_id = loop_number();
        break;
      default:
        i_ -= len;
        fail("PS0114", "THEN without IF");
    }
    if (i_ != s_.size()) fail("PS0114", "unexpected text after the statement");
  }
};

}  // namespace

void compile_block(std::span<const Ch> s, Program& prog, Block& b, int max_digits) {
  BlockParser(s, prog, max_digits).statement(b);
}

void compile_standalone(std::span<const Ch> s, Program& prog) {
  BlockParser(s, prog, kMostDigits, false).standalone_expression();
}

}  // namespace ncurve::nc::text
