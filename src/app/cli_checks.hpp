// Checks of the numbers a user types, with messages in the units of the option: validators for
// CLI11 options (positive_mm(), range_mm(), degrees(), finite(), whole() ...), strict number
// reading for values the parser leaves as text (--t FROM:TO, curve parameters), and the nearest
// name for a misspelt one. NaN and infinities are never a valid value.
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ncurve::app {

// The whole of `text` as a number (a leading + allowed; no spaces, no trailing characters);
// nullopt if it is not one. NaN and infinities are read as such: see NumberRule.
inline std::optional<double> read_number(std::string_view text) {
  if (text.starts_with('+')) {
    text.remove_prefix(1);
    if (text.starts_with('-')) return std::nullopt;
  }
  if (text.empty() || text.starts_with('+') || text.starts_with(' ')) return std::nullopt;
  double v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

// What a numeric option takes: `what` (with its article: "a length"), its unit ("mm"; empty for a
// pure number) and bounds; whole: an integer.
struct NumberRule {
  struct Bound {
    double value;
    bool inclusive;
  };
  std::string what = "a number";
  std::string unit;
  std::optional<Bound> lo, hi;
  bool whole = false;

  // "a length above 0 mm", "a whole number from 1 to 9999", "an angle in degrees"
  std::string describe() const {
    const std::string unit_after = unit.empty() ? "" : " " + unit;
    auto bound = [](double v) { return fmt::format("{:g}", v); };
    if (lo && hi && lo->inclusive && hi->inclusive)
      return fmt::format("{} from {} to {}{}", what, bound(lo->value), bound(hi->value), unit_after);
    std::string out = what;
    if (lo) out += fmt::format(" {} {}", lo->inclusive ? "of at least" : "above", bound(lo->value));
    if (lo && hi) out += " and";
    if (hi) out += fmt::format(" {} {}", hi->inclusive ? "of at most" : "below", bound(hi->value));
    if (lo || hi) return out + unit_after;
    return unit.empty() ? "a finite " + what.substr(what.find(' ') + 1) : fmt::format("{} in {}", what, unit);
  }

  // "" if `text` is such a number, else why not (without the option's name).
  std::string check(const std::string& text) const {
    const std::optional<double> v = read_number(text);
    if (!v) return fmt::format("'{}' is not a number (expected {})", text, describe());
    const bool ok = std::isfinite(*v) && (!lo || (lo->inclusive ? *v >= lo->value : *v > lo->value)) &&
                    (!hi || (hi->inclusive ? *v <= hi->value : *v < hi->value)) &&
                    (!whole || (*v == std::trunc(*v) && std::fabs(*v) < 1e15));
    return ok ? std::string() : fmt::format("must be {}, got {}", describe(), text);
  }

  // The value of `text` for the option named `option`; throws std::runtime_error naming both.
  double read(const std::string& text, std::string_view option) const {
    if (const std::string why = check(text); !why.empty()) throw std::runtime_error(fmt::format("{}: {}", option, why));
    return *read_number(text);
  }

  // For CLI11's check(): the parser then reports "--OPTION: " and the reason.
  CLI::Validator validator() const {
    const NumberRule rule = *this;
    return CLI::Validator([rule](std::string& text) { return rule.check(text); }, "", "number");
  }
};

inline NumberRule finite_number(std::string what, std::string unit = "") {
  return {std::move(what), std::move(unit), std::nullopt, std::nullopt, false};
}
inline NumberRule positive_number(std::string what, std::string unit) {
  return {std::move(what), std::move(unit), NumberRule::Bound{0, false}, std::nullopt, false};
}
inline NumberRule non_negative_number(std::string what, std::string unit) {
  return {std::move(what), std::move(unit), NumberRule::Bound{0, true}, std::nullopt, false};
}

// Validators for CLI11 options.
inline CLI::Validator positive_mm() { return positive_number("a length", "mm").validator(); }
inline CLI::Validator non_negative_mm() { return non_negative_number("a length", "mm").validator(); }
inline CLI::Validator range_mm(double lo, double hi) {
  return NumberRule{"a length", "mm", NumberRule::Bound{lo, true}, NumberRule::Bound{hi, true}, false}.validator();
}
inline CLI::Validator degrees() { return finite_number("an angle", "degrees").validator(); }
inline CLI::Validator finite(std::string what = "a number", std::string unit = "") {
  return finite_number(std::move(what), std::move(unit)).validator();
}
inline CLI::Validator positive(std::string what, std::string unit) {
  return positive_number(std::move(what), std::move(unit)).validator();
}
inline CLI::Validator non_negative(std::string what, std::string unit) {
  return non_negative_number(std::move(what), std::move(unit)).validator();
}
inline CLI::Validator whole(long lo, long hi) {
  return NumberRule{"a whole number", "", NumberRule::Bound{static_cast<double>(lo), true},
                    NumberRule::Bound{static_cast<double>(hi), true}, true}
      .validator();
}

// The candidate `word` most likely stands for (see below).
inline std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& candidates);

// One of `choices`: "'arc' is not a form (expanded, arcs, ...); did you mean arcs?"
inline CLI::Validator one_of(std::string what, std::vector<std::string> choices) {
  return CLI::Validator(
      [what, choices](std::string& text) {
        if (std::find(choices.begin(), choices.end(), text) != choices.end()) return std::string();
        std::string list;
        for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
        std::string out = fmt::format("'{}' is not {} ({})", text, what, list);
        if (auto near = nearest_name(text, choices)) out += fmt::format("; did you mean {}?", *near);
        return out;
      },
      // the choices in the option's type name, as CLI::IsMember shows them (help, completion)
      fmt::format("{{{}}}", fmt::join(choices, ",")), "one of");
}

// The long option names of a command (without the leading --), for suggestions.
inline std::vector<std::string> long_options(const CLI::App& app) {
  std::vector<std::string> out;
  for (const CLI::Option* o : app.get_options())
    for (const std::string& name : o->get_lnames()) out.push_back(name);
  return out;
}

// Edit distance (insertions, deletions, substitutions and swaps of neighbours), ignoring case.
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  auto low = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t change = low(a[i - 1]) == low(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + change});
      if (i > 1 && j > 1 && low(a[i - 1]) == low(b[j - 2]) && low(a[i - 2]) == low(b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

// The candidate `word` most likely stands for: the same but for case or one edit away (three
// letters at least), else one
// that begins the word or that the word begins (three letters at least: --tolerance for --tol),
// else the nearest within a third of the word's length; nullopt if none is near.
inline std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& candidates) {
  std::optional<std::string> near;
  // a word of one or two letters is one edit from any other such: only its other case
  std::size_t near_distance = word.size() < 3 ? 1 : std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < near_distance) near = c, near_distance = d;
  }
  if (near && near_distance <= 1) return near;
  auto begins = [](std::string_view s, std::string_view prefix) {
    return prefix.size() >= 3 && prefix.size() <= s.size() && edit_distance(s.substr(0, prefix.size()), prefix) == 0;
  };
  std::optional<std::string> prefix;
  std::size_t longest = 0;
  for (const std::string& c : candidates) {
    if ((begins(word, c) || begins(c, word)) && std::min(c.size(), word.size()) > longest)
      prefix = c, longest = std::min(c.size(), word.size());
  }
  return prefix ? prefix : near;
}

}  // namespace ncurve::app
