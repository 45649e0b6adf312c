// The one point/vector type of a plane, its arithmetic and the intersections of lines and circles:
// cutter compensation, corners, developed paths, coordinate rotation and the helicoid's profiles.
// Each operation is written out once so that every caller rounds the same way.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

namespace ncurve::geom {

struct V2 {
  double x = 0, y = 0;
};

inline V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
inline V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
inline V2 operator-(V2 a) { return {-a.x, -a.y}; }
inline V2 operator*(double k, V2 a) { return {k * a.x, k * a.y}; }
inline V2 operator/(V2 a, double k) { return {a.x / k, a.y / k}; }
inline double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }  // > 0: b turns left of a

// The length, by std::hypot (no overflow of the squares).
inline double norm(V2 a) { return std::hypot(a.x, a.y); }
// The length as sqrt(x x + y y): it may differ from norm() in the last bit; cutter compensation's
// figures are defined with it.
inline double sqrt_norm(V2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }

// sqrt_norm(a) < len, sqrt_norm(a) > len (len > 0) and sqrt_norm(a) < sqrt_norm(b), without the
// square roots where the squares differ by more than a millionth: there their rounding cannot
// change the answer, so the answer is sqrt_norm's, to the last bit.
inline bool sqrt_norm_below(V2 a, double len) {
  const double sq = a.x * a.x + a.y * a.y, l2 = len * len;
  if (sq < 0.999999 * l2) return true;
  if (sq > 1.000001 * l2) return false;
  return std::sqrt(sq) < len;
}
inline bool sqrt_norm_less(V2 a, V2 b) {
  const double sa = a.x * a.x + a.y * a.y, sb = b.x * b.x + b.y * b.y;
  if (sa < 0.999999 * sb) return true;
  if (sa >= sb) return false;
  return std::sqrt(sa) < std::sqrt(sb);
}

// a divided by its length (the zero vector stays zero); sqrt_unit by sqrt_norm.
inline V2 unit(V2 a) {
  const double n = norm(a);
  return n > 0 ? V2{a.x / n, a.y / n} : V2{};
}
inline V2 sqrt_unit(V2 a) {
  const double n = sqrt_norm(a);
  return n > 0 ? V2{a.x / n, a.y / n} : V2{};
}

inline V2 perp(V2 a) { return {-a.y, a.x}; }  // a turned +90 degrees: the left normal of a direction

// a turned counter-clockwise by the angle of cosine c and sine s, or by `radians`.
inline V2 rotate(V2 a, double c, double s) { return {a.x * c - a.y * s, a.x * s + a.y * c}; }
inline V2 rotate(V2 a, double radians) { return rotate(a, std::cos(radians), std::sin(radians)); }

// Where the lines p1 + u d1 and p2 + v d2 meet; nullopt when they are parallel (|d1 x d2| < 1e-12).
inline std::optional<V2> line_line(V2 p1, V2 d1, V2 p2, V2 d2) {
  const double den = cross(d1, d2);
  if (std::fabs(den) < 1e-12) return std::nullopt;
  const double u = cross(p2 - p1, d2) / den;
  return p1 + u * d1;
}

// The meeting points of a line or circle with a circle: none or two (a touching pair twice), held
// in place (no heap: compensation asks for them at every corner).
struct MeetingPoints {
  V2 p[2];
  int n = 0;
  std::size_t size() const { return static_cast<std::size_t>(n); }
  bool empty() const { return n == 0; }
  const V2& operator[](std::size_t i) const { return p[i]; }
  const V2* begin() const { return p; }
  const V2* end() const { return p + n; }
};

// The points of the line a + u d on the circle (c, R), in growing u (a tangent line gives its point
// twice); none when the line misses the circle by more than rounding, or d is zero.
inline MeetingPoints line_circle(V2 a, V2 d, V2 c, double R) {
  const V2 f = a - c;
  const double A = dot(d, d), B = 2 * dot(f, d), C = dot(f, f) - R * R;
  const double disc = B * B - 4 * A * C;
  if (disc < -1e-12 * std::max(1.0, R * R) || A == 0) return {};
  const double root = std::sqrt(std::max(0.0, disc));
  return {{a + ((-B - root) / (2 * A)) * d, a + ((-B + root) / (2 * A)) * d}, 2};
}

// The points where circles (c1, r1) and (c2, r2) meet, the one left of the way from c1 to c2 first
// (touching circles give their point twice); none for concentric circles (centres within 1e-9) or
// circles apart or nested by more than 1e-9.
inline MeetingPoints circle_circle(V2 c1, double r1, V2 c2, double r2) {
  const V2 d = c2 - c1;
  const double D = sqrt_norm(d);
  if (D < 1e-9 || D > r1 + r2 + 1e-9 || D < std::fabs(r1 - r2) - 1e-9) return {};
  const double a = (r1 * r1 - r2 * r2 + D * D) / (2 * D);
  const double h = std::sqrt(std::max(0.0, r1 * r1 - a * a));
  const V2 u = (1 / D) * d;
  const V2 m = c1 + a * u;
  return {{m + h * perp(u), m - h * perp(u)}, 2};
}

}  // namespace ncurve::geom
