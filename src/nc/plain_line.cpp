#include "nc/plain_line.hpp"

#include "nc/text.hpp"

namespace ncurve::nc::text {

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

}  // namespace ncurve::nc::text
