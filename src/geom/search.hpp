// Searches shared by the fits and the helicoid: the largest parameter step a predicate accepts,
// and the maximum of a function on an interval.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
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

// The largest t in (ta, stop] with err(t) <= tol, for an error that grows like the sag of a
// chord once past `floor` (err + floor ~ c (t - ta)^2, so sqrt(err + floor) is nearly linear in
// t): from a guess, that model brackets the answer, then regula falsi with the Illinois
// correction (bisection if it stalls) closes the bracket to `rel` of the step. err(t) <= tol
// must hold for t just past ta; fail() names the place when not even a tiny step does.
template <class Err, class Fail>
double longest_within(double ta, double stop, double guess, double tol, double floor, Err err, double span, Fail fail,
                      double rel = 1e-4, double accept = 1e-3) {
  const double root = std::sqrt(tol + floor);
  const double flat = std::sqrt(2 * floor) - root;  // g where err is at the floor
  auto g = [&](double t) {  // <= 0 exactly when err(t) <= tol
    double e = err(t);
    if (std::isnan(e)) return root;
    double v = std::sqrt(std::max(e, 0.0) + floor) - root;
    return e <= tol ? std::min(v, 0.0) : std::max(v, std::numeric_limits<double>::min());
  };
  // where the line through (ta, -root) and (t, gt) crosses zero, as a multiple of t - ta
  auto model_ratio = [&](double gt) { return root / std::max(root + gt, 1e-3 * root); };
  double t = std::clamp(guess, ta + 1e-12 * span, stop);
  double lo = ta, glo = -root, hi = stop, ghi = 0;
  double gt = g(t);
  if (gt <= 0) {
    for (double least = 1.002;; least = 1 + 8 * (least - 1)) {  // the model fails below a floor: grow
      lo = t, glo = gt;
      if (t >= stop) return stop;
      t = std::min(stop, ta + (t - ta) * std::max(least, 1.002 * model_ratio(gt)));
      gt = g(t);
      if (gt > 0) break;
    }
    hi = t, ghi = gt;
  } else {
    for (;;) {
      hi = t, ghi = gt;
      t = ta + (t - ta) * std::clamp(0.998 * model_ratio(gt), 0.1, 0.998);
      if (t - ta < 1e-12 * span) throw std::runtime_error(fail());
      gt = g(t);
      if (gt <= 0) break;
    }
    lo = t, glo = gt;
  }
  int stuck_side = 0;  // +1: hi stayed last time, -1: lo stayed
  double width_before = hi - lo, g_at_lo = glo;  // glo itself may be scaled down by Illinois
  for (int i = 0; i < 200 && hi - lo > rel * (hi - ta) && g_at_lo < -accept * root; ++i) {
    double next;
    if (i % 3 == 2 && hi - lo > 0.25 * width_before) {
      next = 0.5 * (lo + hi);
    } else {
      // regula falsi; from hi's model alone while lo is below the floor (no sag seen there yet)
      next = g_at_lo <= flat ? ta + (hi - ta) * model_ratio(ghi) : hi - ghi * (hi - lo) / (ghi - glo);
      const double margin = 0.25 * rel * (hi - ta);
      next = std::clamp(next, lo + margin, hi - margin);
    }
    if (i % 3 == 2) width_before = hi - lo;
    double gn = g(next);
    if (gn <= 0) {
      lo = next, glo = g_at_lo = gn;
      if (stuck_side == 1) ghi *= 0.5;
      stuck_side = 1;
    } else {
      hi = next, ghi = gn;
      if (stuck_side == -1) glo *= 0.5;
      stuck_side = -1;
    }
  }
  return lo;
}

struct Maximum {
  double value, at;
};

// Brent's method: the maximum of f in [a, b] from x inside it (f(x) >= f at both ends), by
// parabolic steps through the best three points, golden-section steps where a parabola is not
// trusted; stops when x is known within `resolution`.
template <class F>
Maximum brent_maximum(F f, double a, double b, double x, double fx, double resolution) {
  constexpr double kGoldenStep = 0.3819660112501051;  // (3 - sqrt 5) / 2
  double w = x, v = x, fw = fx, fv = fx;  // second and third best points (f values, maximising)
  double d = 0, e = 0;                    // this step and the one before the last
  for (int i = 0; i < 100; ++i) {
    const double m = 0.5 * (a + b);
    const double tol1 = std::max(0.5 * resolution, 4e-16 * std::fabs(x)), tol2 = 2 * tol1;
    if (std::fabs(x - m) <= tol2 - 0.5 * (b - a)) break;
    bool parabolic = false;
    if (std::fabs(e) > tol1) {
      double r = (x - w) * (fv - fx), q = (x - v) * (fw - fx);  // on -f: a minimisation
      double p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p; else q = -q;
      double e_before = e;
      e = d;
      if (std::fabs(p) < std::fabs(0.5 * q * e_before) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        parabolic = true;
        double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = x < m ? tol1 : -tol1;
      }
    }
    if (!parabolic) {
      e = (x < m ? b : a) - x;
      d = kGoldenStep * e;
    }
    const double u = std::fabs(d) >= tol1 ? x + d : x + (d > 0 ? tol1 : -tol1);
    const double fu = f(u);
    if (fu >= fx) {
      (u < x ? b : a) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu >= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu >= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return {fx, x};
}

// Each local maximum of f on [lo, hi] that `samples` equal steps show (a sample no lower than
// its neighbours), placed by refine(a, b, x, f(x)) between the neighbours a and b of the sample x
// (below: Brent's method within `resolution`, default a billionth of [lo, hi]; the value is then
// exact to about 1e-17 of its curvature scale); an end sample falling away from the end is that
// end's maximum. on_max(Maximum) is called for each. Every one is refined, not only the highest
// sample: two samples straddling a hump can both lie below an end that the hump itself overtops.
template <class F, class OnMax, class Refine>
void each_sampled_maximum(F f, double lo, double hi, int samples, double resolution, OnMax on_max, Refine refine) {
  constexpr int kMostSamples = 64;
  if (samples < 1 || samples > kMostSamples) throw std::invalid_argument("each_sampled_maximum: 1..64 samples");
  double at[kMostSamples + 1], value[kMostSamples + 1];
  for (int i = 0; i <= samples; ++i) {
    at[i] = i == samples ? hi : lo + (hi - lo) * i / samples;
    value[i] = f(at[i]);
    if (std::isnan(value[i])) return on_max(Maximum{value[i], at[i]});  // undefined there: no maximum
  }
  if (resolution <= 0) resolution = 1e-9 * (hi - lo);
  for (int i = 0; i <= samples; ++i) {
    const bool above_before = i == 0 || value[i] > value[i - 1];
    const bool above_after = i == samples || value[i] >= value[i + 1];
    if (!above_before || !above_after) continue;
    if (i == 0 && f(lo + resolution) <= value[0]) {
      on_max(Maximum{value[0], lo});
      continue;
    }
    if (i == samples && f(hi - resolution) <= value[samples]) {
      on_max(Maximum{value[samples], hi});
      continue;
    }
    const Maximum sample{value[i], at[i]};
    const Maximum m = refine(at[std::max(0, i - 1)], at[std::min(samples, i + 1)], at[i], value[i]);
    on_max(m.value > sample.value ? m : sample);
  }
}

template <class F, class OnMax>
void each_sampled_maximum(F f, double lo, double hi, int samples, double resolution, OnMax on_max) {
  if (resolution <= 0) resolution = 1e-9 * (hi - lo);
  each_sampled_maximum(f, lo, hi, samples, resolution, on_max, [&](double a, double b, double x, double fx) {
    return brent_maximum(f, a, b, x, fx, resolution);
  });
}

// The largest value of f on [lo, hi] (the highest of each_sampled_maximum's; NaN where f is).
template <class F>
Maximum sampled_maximum(F f, double lo, double hi, int samples, double resolution = 0) {
  Maximum best{-std::numeric_limits<double>::infinity(), lo};
  each_sampled_maximum(f, lo, hi, samples, resolution, [&](const Maximum& m) {
    if (std::isnan(m.value) || m.value > best.value) best = m;
  });
  return best;
}

}  // namespace ncurve::geom
