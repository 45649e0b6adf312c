// What the parser's stages share: a block's characters with their columns, the limits of a block,
// and a syntax error before it is attached to its block.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace ncurve::nc::text {

constexpr std::size_t kMaxBlockChars = 4096;  // significant characters of one block
constexpr int kMaxBracketNesting = 5;         // FANUC: brackets nest five deep at most
constexpr std::size_t kMaxComment = 256;      // characters of a comment kept (for #3000 messages)

struct Ch {
  char c;
  std::uint16_t col;
};

constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
constexpr char to_upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c; }

// mantissa / 10^fraction, correctly rounded while 10^fraction is exact (fraction <= 22); leading
// zeros after the point can make fraction larger than the 15 significant digits.
inline double scaled_decimal(std::int64_t mantissa, int fraction) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  double v = static_cast<double>(mantissa);
  while (fraction > 22) {
    v /= 1e22;
    fraction -= 22;
  }
  return fraction == 0 ? v : v / kPow10[fraction];  // v / 1 is v
}

struct SyntaxError {
  std::string code;
  std::string message;
  std::uint16_t column;
  std::uint32_t length = 1;
};

inline std::uint16_t clamp_col(std::size_t c) { return static_cast<std::uint16_t>(c < 65535 ? c : 65535); }

}  // namespace ncurve::nc::text
