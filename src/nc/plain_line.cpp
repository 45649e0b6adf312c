#include "nc/plain_line.hpp"

#include <array>
#include <bit>

#include "nc/text.hpp"

namespace ncurve::nc::text {

namespace {
enum : std::uint8_t { kBlank = 1, kLetter = 2 };
constexpr std::array<std::uint8_t, 256> kClass = [] {
  std::array<std::uint8_t, 256> c{};
  c[' '] = c['\t'] = c['\r'] = kBlank;
  for (int k = 0; k < 26; ++k) c['A' + k] = c['a' + k] = kLetter;
  return c;
}();
constexpr bool blank(char c) { return kClass[static_cast<unsigned char>(c)] & kBlank; }
constexpr bool letter(char c) { return kClass[static_cast<unsigned char>(c)] & kLetter; }
constexpr unsigned digit(char c) { return static_cast<unsigned>(c - '0'); }  // < 10 for a digit
// A letter's index 0..25 (either case); 26 or more for anything else.
constexpr unsigned letter_index(char c) { return static_cast<unsigned>((c | 0x20) - 'a'); }

constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

// Reads a run of digits from p into m (m * 10^count + value); returns how many.
inline int read_digits(const char*& p, std::uint64_t& m) {
  const char* first = p;
  for (; digit(*p) < 10; ++p) m = m * 10 + digit(*p);  // wraps past 19 digits, then unused
  return static_cast<int>(p - first);
}

// A number's digits and point, one character at a time.
inline void read_number(const char*& p, std::uint64_t& mantissa, int& digits, int& fraction) {
  digits = read_digits(p, mantissa);
  fraction = -1;
  if (*p == '.') {
    ++p;
    fraction = read_digits(p, mantissa);
    digits += fraction;
  }
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
    if (digits == 0 || digits > 8 || (!blank(*p) && !letter(*p))) return nullptr;
    sequence = static_cast<std::int32_t>(n);
    while (blank(*p)) ++p;
    if (*p == '\n') return nullptr;  // N alone: the general scanner's empty block
  }
  const std::uint16_t first_col = static_cast<std::uint16_t>(p - begin + 1);  // the first word's
  constexpr std::uint32_t kMotionLetters = 1u << ('G' - 'A') | 1u << ('X' - 'A') | 1u << ('Y' - 'A') |
                                           1u << ('Z' - 'A') | 1u << ('F' - 'A');
  constexpr std::uint32_t kNotHere = 1u << ('N' - 'A') | 1u << ('O' - 'A');  // the general scanner's
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
    if (!letter(*p) || (kNotHere >> k & 1u)) return give_up();
    const std::uint16_t column = static_cast<std::uint16_t>(p - begin + 1);
    ++p;
    while (blank(*p)) ++p;
    const bool negative = *p == '-';
    p += negative || *p == '+';
    std::uint64_t mantissa = 0;
    int digits, fraction;
    read_number(p, mantissa, digits, fraction);
    while (blank(*p)) ++p;
    // blanks inside the number, a second point, or what follows not a letter: the general scanner's
    if (digits == 0 || digits > max_digits || (*p != '\n' && !letter(*p))) return give_up();
    // no branch on the data: over 10^0 when there is no fraction, the sign's bit set by xor
    static_assert(kMostDigits <= 22);  // 10^digits is exact in a double: one rounding, as scaled_decimal
    const double v = static_cast<double>(static_cast<std::int64_t>(mantissa)) / kPow10[fraction > 0 ? fraction : 0];
    Word& w = prog.words.emplace_back();
    w.letter = static_cast<char>('A' + k);
    w.column = column;
    w.decimal_point = fraction >= 0;
    w.decimals = static_cast<std::uint8_t>(fraction > 0 ? fraction : 0);
    w.value = std::bit_cast<double>(std::bit_cast<std::uint64_t>(v) ^ (std::uint64_t{negative} << 63));
    twice |= letters & (1u << k);
    letters |= 1u << k;
    if (k == 'G' - 'A') g_word = true, g_plain = fraction < 0 && (mantissa == 0 || mantissa == 1);
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
