#include "nc/plain_line.hpp"

#include "nc/text.hpp"

namespace ncurve::nc::text {

namespace {
constexpr bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
}  // namespace

bool plain_nc_line(std::string_view raw, std::uint32_t line, Program& prog, int max_digits) {
  if (raw.size() > kMaxBlockChars) return false;
  const char* const begin = raw.data();
  const char* const end = begin + raw.size();
  const char* p = begin;
  while (p != end && blank(*p)) ++p;
  if (p == end) return false;
  const std::size_t words_mark = prog.words.size();
  const std::uint16_t first_col = static_cast<std::uint16_t>(p - begin + 1);
  while (p != end) {
    const char letter = to_upper(*p);
    if (!is_upper(letter) || letter == 'O' || letter == 'N') break;
    Word& w = prog.words.emplace_back();
    w.letter = letter;
    w.column = static_cast<std::uint16_t>(p - begin + 1);
    ++p;
    while (p != end && blank(*p)) ++p;
    bool negative = false;
    if (p != end && (*p == '-' || *p == '+')) negative = *p++ == '-';
    // digits and one decimal point, blanks between them ignored
    std::uint64_t mantissa = 0;  // wraps past max_digits, then unused
    int digits = 0, fraction = -1;
    for (; p != end; ++p) {
      const char c = *p;
      if (is_digit(c)) {
        mantissa = mantissa * 10 + (c - '0');
        ++digits;
        fraction += fraction >= 0;
      } else if (c == '.') {
        if (fraction >= 0) {
          digits = 0;  // a second point: not a plain word
          break;
        }
        fraction = 0;
      } else if (!blank(c)) {
        break;
      }
    }
    if (digits == 0 || digits > max_digits || (p != end && !is_upper(to_upper(*p)))) {
      prog.words.resize(words_mark);
      return false;
    }
    w.decimal_point = fraction >= 0;
    w.decimals = static_cast<std::uint8_t>(fraction > 0 ? fraction : 0);
    const double v = fraction > 0 ? scaled_decimal(static_cast<std::int64_t>(mantissa), fraction) : static_cast<double>(mantissa);
    w.value = negative ? -v : v;
  }
  if (p != end) {  // O, N or a character of the general scanner's
    prog.words.resize(words_mark);
    return false;
  }
  Block& b = prog.blocks.emplace_back();
  b.kind = Statement::nc;
  b.line = line;
  b.column = first_col;
  b.words_begin = static_cast<std::uint32_t>(words_mark);
  b.words_end = static_cast<std::uint32_t>(prog.words.size());
  return true;
}

}  // namespace ncurve::nc::text
