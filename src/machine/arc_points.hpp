// Points along an arc move, its chords within a tolerance: for the writers that need points (CSV,
// the SVG plot) and for cutting an arc outside G17 as lines (the verifier).
#pragma once
#include <algorithm>
#include <cmath>

#include "machine/move.hpp"

namespace ncurve::machine {

// The most points an arc is written as (CSV): a bound on the output of one move.
constexpr long kMostArcPoints = 100'000;

// Points of an arc move (excluding its start), spaced so the chord error is within tolerance.
template <class F>
void arc_points(const Move& m, double tolerance, F&& point) {
  int p = 0, q = 1, n = 2;
  if (m.plane == 18) { p = 2; q = 0; n = 1; }
  else if (m.plane == 19) { p = 1; q = 2; n = 0; }
  double cp = m.center[p], cq = m.center[q];
  double rs = std::hypot(m.start[p] - cp, m.start[q] - cq);
  double re = std::hypot(m.end[p] - cp, m.end[q] - cq);
  double a0 = std::atan2(m.start[q] - cq, m.start[p] - cp);
  double r = std::max(rs, re);
  double step = 2 * std::acos(std::max(-1.0, 1 - std::max(tolerance, 1e-9) / std::max(r, 1e-12)));
  if (!(step > 1e-6)) step = 1e-6;
  // at most kMostArcPoints points (a chord error beyond the tolerance only where the radius is above
  // about 2.5e8 times it); in doubles, so that a NaN or huge sweep converts to a count safely
  const double wanted = std::ceil(std::fabs(m.sweep) / step);
  const long count = wanted >= 1 ? static_cast<long>(std::min(wanted, static_cast<double>(kMostArcPoints))) : 1;
  for (long i = 1; i <= count; ++i) {
    if (i == count) {
      point(m.end);
      break;
    }
    double t = static_cast<double>(i) / count;
    double a = a0 + m.sweep * t;
    double rr = rs + (re - rs) * t;  // FANUC moves on a spiral when the radii differ within No.3410
    AxisVector v = m.start;
    for (int k = 0; k < kAxes; ++k) v[k] = m.start[k] + (m.end[k] - m.start[k]) * t;
    v[p] = cp + rr * std::cos(a);
    v[q] = cq + rr * std::sin(a);
    (void)n;
    point(v);
  }
}

}  // namespace ncurve::machine
