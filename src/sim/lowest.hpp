// The lowest value of a function of one parameter on an interval, to a stated tolerance, where a
// tool's lowest point along a move has no closed form: a convex function by golden section with
// a certificate from its secants, any other by branch and bound.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

namespace ncurve::sim {

// f convex on [lo, hi]: golden section until the secants' lower bound is within tolerance.
template <class F>
double lowest_convex(double lo, double hi, double tolerance, const F& f) {
  double a = lo, b = hi, fa = f(lo), fb = f(hi);
  if (!(hi > lo)) return std::min(fa, fb);
  constexpr double g = 0.3819660112501051;  // 2 - golden ratio
  double x1 = a + g * (b - a), x2 = b - g * (b - a), f1 = f(x1), f2 = f(x2);
  for (int k = 0; k < 200; ++k) {
    const double best = std::min({fa, f1, f2, fb});
    // a convex function lies above each secant's extension outside its chord
    const double s12 = (f2 - f1) / (x2 - x1);
    double bound = std::min({f1 - s12 * (x1 - a), f2 + s12 * (b - x2), f1, f2});
    const double sl = (f1 - fa) / (x1 - a), sr = (fb - f2) / (b - x2);  // left and right chords' slopes
    auto over_middle = [&](double t) { return std::max(f1 + sl * (t - x1), f2 + sr * (t - x2)); };
    double mid = std::min(over_middle(x1), over_middle(x2));
    if (sl != sr) {
      const double t = (f2 - f1 + sl * x1 - sr * x2) / (sl - sr);
      if (t > x1 && t < x2) mid = std::min(mid, over_middle(t));
    }
    bound = std::min(bound, mid);
    if (best - bound <= tolerance || !(x2 > x1)) return best;
    if (f1 < f2) {
      b = x2, fb = f2, x2 = x1, f2 = f1;
      x1 = a + g * (b - a), f1 = f(x1);
    } else {
      a = x1, fa = f1, x1 = x2, f1 = f2;
      x2 = b - g * (b - a), f2 = f(x2);
    }
  }
  return std::min({fa, f1, f2, fb});
}

// lower_bound(a, b) must be a true lower bound of f on [a, b] that tends to f as the interval
// shrinks; for the few spans where no convexity is known.
template <class F, class Bound>
double lowest_on(double lo, double hi, double tolerance, const F& f, const Bound& lower_bound) {
  double best = std::min(f(lo), f(hi));
  struct Span { double a, b; int depth; };
  std::array<Span, 128> stack;
  int n = 0;
  stack[n++] = {lo, hi, 0};
  while (n > 0) {
    const Span s = stack[--n];
    if (!(lower_bound(s.a, s.b) < best - tolerance)) continue;
    const double m = 0.5 * (s.a + s.b);
    best = std::min(best, f(m));
    // 60 halvings take any move's parameter below a rounding step
    if (s.depth >= 60 || n + 2 > static_cast<int>(stack.size())) continue;
    stack[n++] = {m, s.b, s.depth + 1};
    stack[n++] = {s.a, m, s.depth + 1};
  }
  return best;
}

}  // namespace ncurve::sim
