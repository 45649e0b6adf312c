// What the deviation measure and the line and arc fits share (private to src/geom): vector
// arithmetic, the placed curve's local shape, and the sampling of a piece's deviation.
#pragma once
#include <algorithm>
#include <cmath>

#include "geom/approx.hpp"

namespace ncurve::geom::fit {

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

using Local = PlacedJet;
inline Local local(const Fit& f, double t) { return placed_jet(f.curve, f.place, t); }

// Outward unit normal (away from the centre of curvature) and curvature of the placed curve.
inline double outward(const Local& l, Vec3& n) {
  double s2 = dot(l.d1, l.d1);
  Vec3 perp = sub(l.d2, scale(l.d1, dot(l.d2, l.d1) / s2));
  double len = norm(perp);
  n = len > 0 ? scale(perp, -1.0 / len) : Vec3{0, 0, 0};
  return len / s2;
}

// A piece within a tolerance is short: six samples find its humps (at most three: both ends and
// the middle, when its ends sit off the curve), Brent's method places each to a millionth of it.
inline constexpr int kPieceSamples = 6;
inline constexpr double kPieceResolution = 1e-6;

// A first guess of the parameter step for a sag h where the curve is l (from its curvature k).
inline double step_guess(const Fit& f, const Local& l, double k, double h) {
  double speed = norm(l.d1);
  double range = f.curve.t1() - f.curve.t0();
  if (!(k > 1e-12) || !(speed > 0)) return range;
  return std::min(range, std::sqrt(8 * h / k) / speed);
}
inline double step_guess(const Fit& f, const Local& l, double h) {
  Vec3 n;
  return step_guess(f, l, outward(l, n), h);
}

}  // namespace ncurve::geom::fit
