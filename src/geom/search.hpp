// Searches shared by the fits and the helicoid: the largest parameter step a predicate accepts,
// and the maximum of a function on an interval.
#pragma once
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ncurve::geom {

// Bisection on t in (lo, hi]: the largest t found with ok(t), given ok(lo) and !ok(hi).
template <class Ok>
double largest_ok(double lo, double hi, Ok ok, double span) {
  for (int i = 0; i < 60 && hi - lo > 1e-7 * span; ++i) {
    double mid = 0.5 * (lo + hi);
    if (ok(mid)) lo = mid; else hi = mid;
  }
  return lo;
}

// The largest t in (ta, stop] with ok(t): from a guess, grow or shrink until the answer is
// bracketed, then bisect. fail() names the place when not even a tiny step is ok.
template <class Ok, class Fail>
double longest_step(double ta, double stop, double guess, Ok ok, double span, Fail fail) {
  double lo, hi;
  if (ok(guess)) {
    lo = hi = guess;
    while (hi < stop) {
      hi = std::min(stop, ta + (hi - ta) * 1.5);
      if (!ok(hi)) break;
      lo = hi;
    }
    if (lo == stop) return stop;
  } else {
    hi = guess;
    lo = ta + (guess - ta) * 0.6;
    while (!ok(lo)) {
      hi = lo;
      lo = ta + (lo - ta) * 0.6;
      if (lo - ta < 1e-12 * span) throw std::runtime_error(fail());
    }
  }
  return largest_ok(lo, hi, ok, span);
}

struct Maximum {
  double value, at;
};

// The largest value of f on [lo, hi]: `samples` equal steps, then golden-section search between
// the neighbours of the best sample (f unimodal there) until the bracket is narrower than
// `resolution` (default: to rounding).
template <class F>
Maximum sampled_maximum(F f, double lo, double hi, int samples, double resolution = 0) {
  constexpr double kGolden = 0.6180339887498949;
  Maximum best{f(lo), lo};
  int best_i = 0;
  for (int i = 1; i <= samples; ++i) {
    double t = lo + (hi - lo) * i / samples;
    double v = f(t);
    if (v > best.value) best = {v, t}, best_i = i;
  }
  double a = lo + (hi - lo) * std::max(0, best_i - 1) / samples;
  double b = lo + (hi - lo) * std::min(samples, best_i + 1) / samples;
  double x1 = b - kGolden * (b - a), x2 = a + kGolden * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 40 && b - a > std::max(resolution, 1e-12 * (1 + std::fabs(b))); ++i) {
    if (f1 > f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - kGolden * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + kGolden * (b - a), f2 = f(x2);
    }
  }
  if (f1 > best.value) best = {f1, x1};
  if (f2 > best.value) best = {f2, x2};
  return best;
}

}  // namespace ncurve::geom
