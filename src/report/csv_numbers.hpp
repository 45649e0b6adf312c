// The CSV's numbers as text, written straight into a row: six decimals as std::to_chars writes
// them, and a column's recent values kept as text, since a row repeats most of the rows before.
#pragma once
#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>

namespace ncurve::report {

// The most a column's ",v" takes: the widest double, -1.8e308, in fixed notation with 6 decimals.
constexpr std::size_t kFixed6Most = 330;

// Writes ",v" at p with v in six decimals, as std::to_chars(v, fixed, 6) writes it; returns the end.
// p has room for kFixed6Most characters.
char* fixed6(char* p, double v);
// Appends ",v" with v in six decimals (the CSV's columns).
void fixed6(fmt::memory_buffer& b, double v);

// Writes ",v" with v as fmt's "{}" writes it (the shortest text that reads back as v); returns the end.
char* shortest(char* p, double v);

// A column's last two values and their texts: the next row's value is often one of them (a hole's
// X and Y over its three rows, Z between the R plane and the bottom, F between rapid and feed).
template <char* (*Write)(char*, double)>
class RecentNumbers {
public:
  // Writes ",v" at p; p has room for kFixed6Most characters and 32 more.
  char* put(char* p, double v) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
    for (int i : {last_, 1 - last_})
      if (kept_[i].size && kept_[i].bits == bits) {
        std::memcpy(p, kept_[i].text, sizeof kept_[i].text);  // whole: p has the room
        last_ = i;
        return p + kept_[i].size;
      }
    char* end = Write(p, v);
    const std::size_t n = static_cast<std::size_t>(end - p);
    if (n <= sizeof kept_[0].text) {
      last_ = 1 - last_;
      kept_[last_].bits = bits;
      kept_[last_].size = static_cast<std::uint8_t>(n);
      std::memcpy(kept_[last_].text, p, sizeof kept_[last_].text);
    }
    return end;
  }

private:
  struct Kept {
    std::uint64_t bits = 0;
    std::uint8_t size = 0;  // 0: nothing kept
    char text[31];
  };
  Kept kept_[2];
  int last_ = 0;
};

}  // namespace ncurve::report
