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

  // The coefficients of s .. s^5 of one coordinate, from its change dp over the step and its
  // first and second derivatives at the start (d10, d20) and the end (d11, d21).
  static std::array<double, 5> coefficients(double dp, double d10, double d20, double d11, double d21, double h) {
    const double v0 = h * d10, v1 = h * d11;
    const double a0 = h * h * d20, a1 = h * h * d21;
    return {v0, 0.5 * a0, 10 * dp - 6 * v0 - 4 * v1 - 1.5 * a0 + 0.5 * a1,
            -15 * dp + 8 * v0 + 7 * v1 + 1.5 * a0 - a1, 6 * dp - 3 * v0 - 3 * v1 - 0.5 * a0 + 0.5 * a1};
  }

  // p, d1, d2 at the start and the end of a step h long in the curve parameter (derivatives
  // per unit of that parameter).
  static Quintic through(const V& p0, const V& d10, const V& d20, const V& p1, const V& d11, const V& d21,
                         double h) {
    Quintic q;
    q.origin = p0;
    for (int a = 0; a < 3; ++a) {
      const std::array<double, 5> k = coefficients(p1[a] - p0[a], d10[a], d20[a], d11[a], d21[a], h);
      for (int i = 0; i < 5; ++i) q.c[i][a] = k[i];
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
