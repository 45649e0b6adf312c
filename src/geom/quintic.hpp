// The quintic through two jets of a curve (point, first and second derivative at both ends of a
// step). Between jets a short step apart it follows a smooth curve to O(h^6), so a piece's
// deviation can be searched on it and only confirmed on the curve itself.
#pragma once
#include <array>

namespace ncurve::geom {

struct Quintic {
  using V = std::array<double, 3>;
  V origin{};             // the point at s = 0
  std::array<V, 5> c{};   // coefficients of s .. s^5 (s = 0..1 over the step), about origin

  // p, d1, d2 at the start and the end of a step h long in the curve parameter (derivatives
  // per unit of that parameter).
  static Quintic through(const V& p0, const V& d10, const V& d20, const V& p1, const V& d11, const V& d21,
                         double h) {
    Quintic q;
    q.origin = p0;
    for (int a = 0; a < 3; ++a) {
      const double dp = p1[a] - p0[a];
      const double v0 = h * d10[a], v1 = h * d11[a];
      const double a0 = h * h * d20[a], a1 = h * h * d21[a];
      q.c[0][a] = v0;
      q.c[1][a] = 0.5 * a0;
      q.c[2][a] = 10 * dp - 6 * v0 - 4 * v1 - 1.5 * a0 + 0.5 * a1;
      q.c[3][a] = -15 * dp + 8 * v0 + 7 * v1 + 1.5 * a0 - a1;
      q.c[4][a] = 6 * dp - 3 * v0 - 3 * v1 - 0.5 * a0 + 0.5 * a1;
    }
    return q;
  }

  V at(double s) const {
    V out;
    for (int a = 0; a < 3; ++a)
      out[a] = origin[a] + s * (c[0][a] + s * (c[1][a] + s * (c[2][a] + s * (c[3][a] + s * c[4][a]))));
    return out;
  }
};

}  // namespace ncurve::geom
