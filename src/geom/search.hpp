// Step searches shared by the fits: the largest parameter step a predicate accepts.
#pragma once
#include <algorithm>
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

}  // namespace ncurve::geom
