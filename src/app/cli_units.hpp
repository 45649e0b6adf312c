// Validators for numeric command-line options with units: each reads the whole argument as a
// finite number (NaN, infinities and overflow refused), checks its range and says what it must
// be in the option's unit, e.g. "--radius: must be a length above 0 mm, got nan" (CLI11 puts the
// option's name in front). Bounds print as written ("{:g}"), never as CLI11's 300-digit limits.
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>

namespace ncurve::app::units {

// One end of a range: the value and whether the value itself is allowed.
struct Bound {
  double value = 0;
  bool inclusive = false;
};
inline Bound above(double v) { return {v, false}; }
inline Bound at_least(double v) { return {v, true}; }
inline Bound below(double v) { return {v, false}; }
inline Bound at_most(double v) { return {v, true}; }

// The whole text as a finite double (leading and trailing spaces allowed); nothing otherwise.
inline std::optional<double> finite_number(const std::string& text) {
  std::size_t b = text.find_first_not_of(" \t"), e = text.find_last_not_of(" \t");
  if (b == std::string::npos) return std::nullopt;
  const std::string s = text.substr(b, e - b + 1);
  // strtod also reads hexadecimal, "inf" and "nan": only decimal numbers are taken
  if (s.find_first_not_of("+-.0123456789eE") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  // overflow reads as an infinity; underflow as a tiny or zero number, which is taken
  if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// "above 0 mm", "from 0 to 1", "of 0 mm or more", ... (unit empty for plain numbers).
inline std::string range_text(std::optional<Bound> lo, std::optional<Bound> hi, const std::string& unit) {
  const std::string u = unit.empty() ? "" : " " + unit;
  if (lo && hi) {
    if (lo->inclusive && hi->inclusive) return fmt::format("from {:g} to {:g}{}", lo->value, hi->value, u);
    return fmt::format("{} {:g} and {} {:g}{}", lo->inclusive ? "at least" : "above", lo->value,
                       hi->inclusive ? "at most" : "below", hi->value, u);
  }
  if (lo) return lo->inclusive ? fmt::format("of {:g}{} or more", lo->value, u) : fmt::format("above {:g}{}", lo->value, u);
  if (hi) return hi->inclusive ? fmt::format("of {:g}{} or less", hi->value, u) : fmt::format("below {:g}{}", hi->value, u);
  return "";  // any finite value
}

// A finite number within [lo, hi] (each end open or closed, or absent), whole if `whole`; the
// message names `what` ("a length") and the unit.
inline CLI::Validator number(const std::string& what, const std::string& unit, std::optional<Bound> lo = std::nullopt,
                             std::optional<Bound> hi = std::nullopt, bool whole = false) {
  const std::string range = range_text(lo, hi, unit);
  const std::string rule = "must be " + what + (range.empty() ? "" : " " + range);
  auto check = [=](std::string& input) -> std::string {
    const std::optional<double> v = finite_number(input);
    bool ok = v.has_value();
    if (ok && whole) ok = *v == std::floor(*v);
    if (ok && lo) ok = lo->inclusive ? *v >= lo->value : *v > lo->value;
    if (ok && hi) ok = hi->inclusive ? *v <= hi->value : *v < hi->value;
    if (ok) return {};
    return fmt::format("{}, got {}", rule, input.empty() ? "nothing" : input);
  };
  const std::string description = !range.empty() ? range : unit.empty() ? "NUMBER" : unit;
  return CLI::Validator(check, description, "");
}

// Lengths in mm; any finite length when both ends are absent.
inline CLI::Validator length_mm(std::optional<Bound> lo = std::nullopt, std::optional<Bound> hi = std::nullopt) {
  return number("a length", "mm", lo, hi);
}
// Angles in degrees.
inline CLI::Validator angle_deg(std::optional<Bound> lo = std::nullopt, std::optional<Bound> hi = std::nullopt) {
  return number("an angle", "degrees", lo, hi);
}
// Feeds in mm/min, above 0 unless told.
inline CLI::Validator feed_mm_min(Bound lo = above(0), std::optional<Bound> hi = std::nullopt) {
  return number("a feed", "mm/min", lo, hi);
}
// Position loop gains in 1/s ("/s" as the text output writes them), above 0.
inline CLI::Validator gain_per_s() { return number("a gain", "/s", above(0)); }
// A plain ratio such as the velocity feed-forward coefficient.
inline CLI::Validator ratio(Bound lo, Bound hi) { return number("a number", "", lo, hi); }
// A whole number from `lo` (a count of lobes, say).
inline CLI::Validator whole_number(double lo) { return number("a whole number", "", at_least(lo), std::nullopt, true); }

}  // namespace ncurve::app::units
