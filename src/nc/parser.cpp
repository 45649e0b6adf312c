// Splits program text into blocks and compiles each block's words and expressions.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <span>

#include "base/bounds.hpp"
#include "base/memory.hpp"
#include "nc/program.hpp"

namespace ncurve::nc {
namespace {

constexpr std::size_t kMaxBlockChars = 4096;  // significant characters of one block
constexpr int kMaxBracketNesting = 5;         // FANUC: brackets nest five deep at most
constexpr std::size_t kMaxComment = 256;             // characters of a comment kept (for #3000 messages)

struct Ch {
  char c;
  std::uint16_t col;
};

constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
constexpr char to_upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c; }

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

// mantissa / 10^fraction, correctly rounded while 10^fraction is exact (fraction <= 22); leading
// zeros after the point can make fraction larger than the 15 significant digits.
double scaled_decimal(std::int64_t mantissa, int fraction) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  double v = static_cast<double>(mantissa);
  while (fraction > 22) {
    v /= 1e22;
    fraction -= 22;
  }
  return v / kPow10[fraction];
}

struct SyntaxError {
  std::string code;
  std::string message;
  std::uint16_t column;
  std::uint32_t length = 1;
};

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

std::uint16_t clamp_col(std::size_t c) { return static_cast<std::uint16_t>(std::min<std::size_t>(c, 65535)); }

// Expanded programs are mostly blocks of plain words (X1.234 Y-5. F100.). Such a line is compiled
// straight from the raw text; anything else (macros, comments, N, '/', errors) returns false and
// goes through the general scanner and BlockParser, which give the same result for plain lines.
bool plain_nc_line(std::string_view raw, std::uint32_t line, Program& prog, int max_digits) {
  const std::size_t words_mark = prog.words.size();
  auto bail = [&] {
    prog.words.resize(words_mark);
    return false;
  };
  auto skip_blanks = [&](std::size_t k) {
    while (k < raw.size() && (raw[k] == ' ' || raw[k] == '\t' || raw[k] == '\r')) ++k;
    return k;
  };
  if (raw.size() > kMaxBlockChars) return false;
  std::size_t k = skip_blanks(0);
  if (k == raw.size()) return false;
  const std::uint16_t first_col = clamp_col(k + 1);
  while (k < raw.size()) {
    const char letter = to_upper(raw[k]);
    if (!is_upper(letter) || letter == 'O' || letter == 'N') return bail();
    Word w;
    w.letter = letter;
    w.column = clamp_col(k + 1);
    k = skip_blanks(k + 1);
    bool negative = false;
    if (k < raw.size() && (raw[k] == '-' || raw[k] == '+')) {
      negative = raw[k] == '-';
      k = skip_blanks(k + 1);
    }
    std::int64_t mantissa = 0;
    int digits = 0, fraction = 0;
    for (; k < raw.size(); k = skip_blanks(k + 1)) {
      const char c = raw[k];
      if (c == '.') {
        if (w.decimal_point) return bail();
        w.decimal_point = true;
      } else if (is_digit(c)) {
        if (++digits > max_digits) return bail();
        mantissa = mantissa * 10 + (c - '0');
        if (w.decimal_point) ++fraction;
      } else {
        break;
      }
    }
    if (digits == 0) return bail();
    if (k < raw.size() && !is_upper(to_upper(raw[k]))) return bail();
    w.value = scaled_decimal(mantissa, fraction);
    if (negative) w.value = -w.value;
    prog.words.push_back(w);
  }
  Block& b = prog.blocks.emplace_back();
  b.kind = Statement::nc;
  b.line = line;
  b.column = first_col;
  b.words_begin = static_cast<std::uint32_t>(words_mark);
  b.words_end = static_cast<std::uint32_t>(prog.words.size());
  return true;
}

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
      BlockParser bp(s.subspan(i), *current, max_digits);
      std::size_t words_mark = current->words.size(), code_mark = current->code.size();
      try {
        bp.statement(b);
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
  BlockParser bp(chars, p, kMostDigits, false);
  try {
    bp.standalone_expression();
  } catch (const SyntaxError& e) {
    throw Alarm(Diagnostic{Severity::error, e.code, fmt::format("{}: column {}: {}", origin, e.column, e.message),
                           Span{}});
  }
  return CompiledExpr{std::move(p.code)};
}

}  // namespace ncurve::nc
