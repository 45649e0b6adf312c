// Chamfer and corner R points between lines and arcs of one plane.
#include "machine/path/corner_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace ncurve::machine::corner {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-6;                 // mm: points closer than this are one point
constexpr double kLeastAngle = kPi / 180.0;  // the manual's 1 degree: below it nothing is inserted

int direction(const Path& p) { return p.sweep >= 0 ? 1 : -1; }
double radius(const Path& p) { return norm(p.s - p.c); }

// The turn along arc p from `from` to `to` in p's direction, in [0, 2 pi); a point within the
// tolerance before `from` counts as `from`.
double turn(const Path& p, V2 from, V2 to) {
  const V2 u = from - p.c, v = to - p.c;
  double t = direction(p) * std::atan2(cross(u, v), dot(u, v));
  if (t < 0) t = t * radius(p) > -kTol ? 0 : t + 2 * kPi;
  return t;
}

// An offset of a path by a signed distance to its left: a line (point and direction) or a circle.
struct Offset {
  bool arc = false;
  V2 p, d;           // line
  V2 c;              // circle
  double rho = 0;    // circle radius (absolute)
  bool flipped = false;  // the offset circle lies across the centre (radius minus more than radius)
};

Offset offset(const Path& p, double to_left) {
  Offset o;
  if (!p.arc) {
    o.d = unit(p.e - p.s);
    o.p = p.s + to_left * perp(o.d);
    return o;
  }
  o.arc = true;
  o.c = p.c;
  const double r = radius(p) - direction(p) * to_left;  // the left of a counter-clockwise arc is inward
  o.rho = std::fabs(r);
  o.flipped = r < 0;
  return o;
}

std::vector<V2> meet(const Offset& a, const Offset& b) {
  if (!a.arc && !b.arc) {
    const auto x = line_line(a.p, a.d, b.p, b.d);
    return x ? std::vector<V2>{*x} : std::vector<V2>{};
  }
  if (a.arc != b.arc) {
    const Offset& ln = a.arc ? b : a;
    const Offset& ci = a.arc ? a : b;
    const V2 foot = ln.p + dot(ci.c - ln.p, ln.d) * ln.d;
    const double off = norm(ci.c - foot);
    const double h2 = ci.rho * ci.rho - off * off;
    if (h2 < -kTol * std::max(ci.rho, 1.0)) return {};
    const double h = std::sqrt(std::max(0.0, h2));
    return {foot + h * ln.d, foot - h * ln.d};
  }
  const V2 d = b.c - a.c;
  const double dist = norm(d);
  if (dist < kTol) return {};
  const double along = (a.rho * a.rho - b.rho * b.rho + dist * dist) / (2 * dist);
  const double h2 = a.rho * a.rho - along * along;
  if (h2 < -kTol * std::max(a.rho, 1.0)) return {};
  const double h = std::sqrt(std::max(0.0, h2));
  const V2 u = unit(d);
  const V2 base = a.c + along * u;
  return {base + h * perp(u), base - h * perp(u)};
}

// Where a circle about f touches path p (f on p's offset o).
V2 touch(const Path& p, const Offset& o, V2 f) {
  if (!p.arc) return p.s + dot(f - p.s, o.d) * o.d;
  return p.c + (o.flipped ? -radius(p) : radius(p)) * unit(f - p.c);
}

// The share of p from its start to x (x on p), or nullopt when x is off the drawn part.
std::optional<double> share(const Path& p, V2 x) {
  if (!p.arc) {
    const double len = norm(p.e - p.s);
    if (len < kTol) return std::nullopt;
    const double t = dot(x - p.s, unit(p.e - p.s));
    if (t < -kTol || t > len + kTol) return std::nullopt;
    return std::clamp(t / len, 0.0, 1.0);
  }
  const double whole = std::fabs(p.sweep);
  if (whole <= 0) return std::nullopt;
  const double from_start = turn(p, p.s, x);
  const double to_end = turn(p, x, p.e);
  if (from_start <= whole + kTol / radius(p)) return std::clamp(from_start / whole, 0.0, 1.0);
  if (to_end <= kTol / radius(p)) return 1.0;  // the end of a full circle
  return std::nullopt;
}

// The point at straight-line distance `amount` from p's end going back (back = true) or from its
// start going forward; nullopt when p is too short for it.
std::optional<V2> at_distance(const Path& p, double amount, bool back, double& part) {
  if (!p.arc) {
    const double len = norm(p.e - p.s);
    if (amount > len + kTol || len < kTol) return std::nullopt;
    const V2 d = unit(p.e - p.s);
    part = back ? std::max(0.0, (len - amount) / len) : std::min(1.0, amount / len);
    return back ? p.e - amount * d : p.s + amount * d;
  }
  const double r = radius(p);
  if (amount > 2 * r + kTol) return std::nullopt;
  const double delta = 2 * std::asin(std::min(1.0, amount / (2 * r)));
  const double whole = std::fabs(p.sweep);
  if (delta > whole + kTol / r) return std::nullopt;
  part = back ? std::max(0.0, (whole - delta) / whole) : std::min(1.0, delta / whole);
  const int dir = direction(p);
  return back ? p.c + rotate(p.e - p.c, -dir * delta) : p.c + rotate(p.s - p.c, dir * delta);
}
}  // namespace

V2 tangent(const Path& p, V2 x) {
  if (!p.arc) return unit(p.e - p.s);
  return direction(p) * perp(unit(x - p.c));
}

Cut cut_corner(const Path& a, const Path& b, Kind kind, double amount) {
  Cut cut;
  cut.a_end = a.e;
  cut.b_start = b.s;
  const V2 ta = tangent(a, a.e), tb = tangent(b, b.s);
  const double turning = std::atan2(std::fabs(cross(ta, tb)), dot(ta, tb));
  if (amount <= 0 || turning < kLeastAngle) {
    cut.none = true;
    return cut;
  }
  if (kind == Kind::chamfer) {
    auto ea = at_distance(a, amount, true, cut.a_part);
    if (!ea) return cut.fault = Fault::first_too_short, cut;
    auto sb = at_distance(b, amount, false, cut.b_part);
    if (!sb) return cut.fault = Fault::second_too_short, cut;
    cut.a_end = *ea;
    cut.b_start = *sb;
    return cut;
  }
  if (kPi - turning < 1e-9) return cut.fault = Fault::no_solution, cut;  // the path turns back on itself
  const int side = cross(ta, tb) > 0 ? 1 : -1;  // a left turn rounds on the left of both paths
  const Offset oa = offset(a, side * amount), ob = offset(b, side * amount);
  std::optional<V2> centre;
  for (V2 f : meet(oa, ob))
    if (!centre || norm(f - a.e) < norm(*centre - a.e)) centre = f;
  if (!centre) return cut.fault = Fault::no_solution, cut;
  const V2 ea = touch(a, oa, *centre), sb = touch(b, ob, *centre);
  const auto pa = share(a, ea);
  if (!pa) return cut.fault = Fault::first_too_short, cut;
  const auto pb = share(b, sb);
  if (!pb) return cut.fault = Fault::second_too_short, cut;
  cut.a_end = ea;
  cut.b_start = sb;
  cut.a_part = *pa;
  cut.b_part = *pb;
  cut.centre = *centre;
  cut.ccw = side > 0;
  return cut;
}

}  // namespace ncurve::machine::corner
