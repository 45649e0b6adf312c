#include "nc/plain_line.hpp"

#include "nc/text.hpp"

namespace ncurve::nc::text {

namespace {
constexpr bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
constexpr unsigned digit(char c) { return static_cast<unsigned>(c - '0'); }  // < 10 for a digit
// A letter's index 0..25 (either case); 26 or more for anything else.
constexpr unsigned letter_index(char c) { return static_cast<unsigned>((c | 0x20) - 'a'); }

// Reads a run of digits from p into m (m * 10^count + value); returns how many.
inline int read_digits(const char*& p, std::uint64_t& m) {
  const char* first = p;
  for (; digit(*p) < 10; ++p) m = m * 10 + digit(*p);  // wraps past 19 digits, then unused
  return static_cast<int>(p - first);
}
}  // namespace

const char* plain_nc_line(const char* begin, std::uint32_t line, Program& prog, int max_digits) {
  const char* p = begin;  // every loop below stops at the line's '\n'
  while (blank(*p)) ++p;
  if (*p == '\n') return nullptr;
  const std::size_t words_mark = prog.words.size();
  std::int32_t sequence = -1;  // N1..N99999999 written first, digits only, then a word
  if ((*p | 0x20) == 'n') {
    std::uint64_t n = 0;
    const int digits = read_digits(++p, n);
    if (digits == 0 || digits > 8 || (!blank(*p) && letter_index(*p) >= 26)) return nullptr;
    sequence = static_cast<std::int32_t>(n);
    while (blank(*p)) ++p;
    if (*p == '\n') return nullptr;  // N alone: the general scanner's empty block
  }
  const std::uint16_t first_col = static_cast<std::uint16_t>(p - begin + 1);  // the first word's
  constexpr std::uint32_t kMotionLetters = 1u << ('G' - 'A') | 1u << ('X' - 'A') | 1u << ('Y' - 'A') |
                                           1u << ('Z' - 'A') | 1u << ('F' - 'A');
  std::uint32_t letters = 0, twice = 0;
  bool g_plain = true;  // no G word, or G00 / G01
  bool g_word = false;
  bool negative_feed = false;
  auto give_up = [&]() -> const char* {
    prog.words.resize(words_mark);
    return nullptr;
  };
  while (*p != '\n') {
    const unsigned k = letter_index(*p);
    if (k >= 26 || k == 'O' - 'A' || k == 'N' - 'A') return give_up();  // O, N or the general scanner's
    Word& w = prog.words.emplace_back();
    w.letter = static_cast<char>('A' + k);
    w.column = static_cast<std::uint16_t>(p - begin + 1);
    ++p;
    while (blank(*p)) ++p;
    const bool negative = *p == '-';
    p += negative || *p == '+';
    std::uint64_t mantissa = 0;
    int digits = read_digits(p, mantissa);
    int fraction = -1;
    if (*p == '.') {
      ++p;
      fraction = read_digits(p, mantissa);
      digits += fraction;
    }
    while (blank(*p)) ++p;
    // blanks inside the number, a second point, or what follows not a letter: the general scanner's
    if (digits == 0 || digits > max_digits || (*p != '\n' && letter_index(*p) >= 26)) return give_up();
    w.decimal_point = fraction >= 0;
    w.decimals = static_cast<std::uint8_t>(fraction > 0 ? fraction : 0);
    const double v = fraction > 0 ? scaled_decimal(static_cast<std::int64_t>(mantissa), fraction) : static_cast<double>(mantissa);
    w.value = negative ? -v : v;
    twice |= letters & (1u << k);
    letters |= 1u << k;
    if (k == 'G' - 'A') g_word = true, g_plain = !w.decimal_point && (w.value == 0 || w.value == 1);
    if (k == 'F' - 'A') negative_feed = negative;
  }
  if (static_cast<std::size_t>(p - begin) > kMaxBlockChars) return give_up();
  Block& b = prog.blocks.emplace_back();
  b.kind = Statement::nc;
  if ((letters & ~kMotionLetters) == 0 && twice == 0 && !negative_feed)
    b.plain_motion = !g_word ? PlainMotion::modal : g_plain ? PlainMotion::coded : PlainMotion::no;
  b.line = line;
  b.column = first_col;
  if (sequence >= 0) {
    b.sequence = sequence;
    prog.sequence_index.emplace(sequence, static_cast<std::int32_t>(prog.blocks.size() - 1));
  }
  b.words_begin = static_cast<std::uint32_t>(words_mark);
  b.words_end = static_cast<std::uint32_t>(prog.words.size());
  return p;
}

}  // namespace ncurve::nc::text
