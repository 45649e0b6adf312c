#include "report/csv_numbers.hpp"

#include <fmt/compile.h>

#include <charconv>
#include <cmath>

namespace ncurve::report {
namespace {

constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Writes the two digits of n < 100 at p.
void pair(char* p, std::uint32_t n) { std::memcpy(p, kPairs + 2 * n, 2); }

int digits(std::uint32_t n) {
  int d = 1;
  for (; n >= 10; n /= 10) ++d;
  return d;
}

}  // namespace

// From |v| * 10^6 where that product, within half a unit of its last place of the exact one,
// decides the rounding beyond doubt (correctly rounded, a tie to even as to_chars and fmt's
// "{:.6f}" do); else (a tie or near one, a large value) by to_chars.
char* fixed6(char* p, double v) {
  const double a = std::fabs(v);
  if (a < 1e9) {
    const double y = a * 1e6;  // below 2^53: its integer part exact
    const double whole = std::floor(y);
    const double frac = y - whole;  // exact
    if (std::fabs(frac - 0.5) > y * 2.3e-16 + 1e-300) {
      const std::uint64_t n = static_cast<std::uint64_t>(whole) + (frac > 0.5 ? 1 : 0);
      std::uint32_t units = static_cast<std::uint32_t>(n / 1000000);
      std::uint32_t fraction = static_cast<std::uint32_t>(n % 1000000);
      *p++ = ',';
      if (std::signbit(v)) *p++ = '-';
      char* end = p + digits(units) + 7;
      char* q = end;
      for (int i = 0; i < 3; ++i, fraction /= 100) pair(q -= 2, fraction % 100);
      *--q = '.';
      for (; units >= 100; units /= 100) pair(q -= 2, units % 100);
      if (units >= 10) pair(q - 2, units);
      else q[-1] = static_cast<char>('0' + units);
      return end;
    }
  }
  *p = ',';
  return std::to_chars(p + 1, p + kFixed6Most, v, std::chars_format::fixed, 6).ptr;
}

void fixed6(fmt::memory_buffer& b, double v) {
  char text[kFixed6Most];
  b.append(text, fixed6(text, v));
}

char* shortest(char* p, double v) { return fmt::format_to(p, FMT_COMPILE(",{}"), v); }

}  // namespace ncurve::report
