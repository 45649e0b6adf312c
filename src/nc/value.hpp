// A macro variable's value: a real number or vacant (#0).
#pragma once

namespace ncurve::nc {

struct Value {
  double v = 0.0;
  bool vacant = true;

  static constexpr Value of(double x) { return Value{x, false}; }
  static constexpr Value empty() { return Value{}; }
  // Vacant acts as 0 in arithmetic and in GT/GE/LT/LE.
  constexpr double number() const { return vacant ? 0.0 : v; }
};

}  // namespace ncurve::nc
