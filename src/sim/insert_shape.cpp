#include "sim/insert_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine/profile.hpp"

namespace ncurve::sim {

using geom::V2;

namespace {

constexpr double kPi = std::numbers::pi;
double radians(double deg) { return deg * kPi / 180; }

// A length made safe: not finite or negative is 0, and at most `most`.
double safe_length(double v, double most) { return std::isfinite(v) && v > 0 ? std::min(v, most) : 0.0; }

// No tool dimension beyond this, mm (a fuzzed library or offset).
constexpr double kMostLength = 1000;

double signed_area(const std::vector<V2>& p) {
  double a = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) a += geom::cross(p[i], p[(i + 1) % n]);
  return a / 2;
}

ToolOutline counter_clockwise(std::vector<V2> p) {
  if (signed_area(p) < 0) std::reverse(p.begin(), p.end());
  return {std::move(p)};
}

// The points of the arc about c of radius r from angle a0 through sweep, both ends included,
// appended to `out` (the first one only when `first`). The arc's points at multiples of 90 degrees
// are vertices, so that the polygon reaches as far along X and Z as the circle does.
void add_arc(std::vector<V2>& out, V2 c, double r, double a0, double sweep, bool first = true) {
  const double a1 = a0 + sweep;
  std::vector<double> breaks{a0};
  const double q = kPi / 2;
  if (sweep > 0)
    for (double k = std::floor(a0 / q) + 1; k * q < a1; ++k) breaks.push_back(k * q);
  else
    for (double k = std::ceil(a0 / q) - 1; k * q > a1; --k) breaks.push_back(k * q);
  breaks.push_back(a1);
  if (first) out.push_back(c + r * V2{std::cos(a0), std::sin(a0)});
  for (std::size_t i = 1; i < breaks.size(); ++i) {
    const double from = breaks[i - 1], span = breaks[i] - from;
    const int n = arc_chords(r, std::fabs(span));
    for (int k = 1; k <= n; ++k) {
      const double a = k == n ? breaks[i] : from + span * k / n;
      V2 p = c + r * V2{std::cos(a), std::sin(a)};
      if (k == n && i + 1 < breaks.size()) {  // a quadrant point: exactly one radius along an axis
        const long m = std::lround(a / q) % 4;
        p = c + r * (m == 0 ? V2{1, 0} : m == 1 || m == -3 ? V2{0, 1} : m == 2 || m == -2 ? V2{-1, 0} : V2{0, -1});
      }
      out.push_back(p);
    }
  }
}

ToolOutline pointed(double r, int tip, double included, double clearance, const InsertSize& size) {
  const machine::TipDirection d = machine::tip_direction(tip);
  const double A = radians(included);
  const V2 nose = tip == 0 || tip == 9 ? V2{} : -(r * V2{static_cast<double>(d.z), static_cast<double>(d.x)});
  V2 e1, e2;  // the two edges' directions from the nose into the insert
  if ((d.x != 0) == (d.z != 0)) {  // a diagonal tip, or 0 and 9
    const double sz = d.z != 0 ? d.z : -1, sx = d.x != 0 ? d.x : -1;  // 0 and 9: as tip 3
    const double c = radians(clearance), beta = kPi / 2 - c - A;
    e1 = {-sz * std::sin(c), -sx * std::cos(c)};        // across the spindle axis
    e2 = {-sz * std::cos(beta), -sx * std::sin(beta)};  // along it, behind the tool
  } else {
    const V2 back{static_cast<double>(-d.z), static_cast<double>(-d.x)};
    e1 = geom::rotate(back, A / 2);
    e2 = geom::rotate(back, -A / 2);
  }
  const V2 bisector = geom::unit(e1 + e2);
  const double half = A / 2;
  const V2 corner = nose - (r / std::sin(half)) * bisector;  // where the two edges' lines meet
  const double side = std::max(size.inscribed_circle, 2 * r) / std::sin(A);
  std::vector<V2> p;
  if (r > 0) {
    const V2 t1 = corner + (r / std::tan(half)) * e1, t2 = corner + (r / std::tan(half)) * e2;
    const double a1 = std::atan2(t1.y - nose.y, t1.x - nose.x), a2 = std::atan2(t2.y - nose.y, t2.x - nose.x);
    add_arc(p, nose, r, a1, std::remainder(a2 - a1, 2 * kPi));  // the short way: round the front
  } else {
    p.push_back(corner);
  }
  p.push_back(corner + side * e2);
  p.push_back(corner + side * (e1 + e2));
  p.push_back(corner + side * e1);
  return counter_clockwise(std::move(p));
}

ToolOutline blade(double r, int tip, double width, const InsertSize& size) {
  const double rc = std::min(r, width / 2);
  const double length = std::max(safe_length(size.blade_length, kMostLength), 2 * rc + kChordError);
  // the blade in its own frame (u along the cutting edge from the reference corner, v into the blade)
  std::vector<V2> c;
  if (rc > 0) {
    add_arc(c, {rc, rc}, rc, kPi, kPi / 2);
    add_arc(c, {width - rc, rc}, rc, 3 * kPi / 2, kPi / 2, width - rc > rc);
  } else {
    c = {{0, 0}, {width, 0}};
  }
  c.push_back({width, length});
  c.push_back({0, length});
  const machine::TipDirection d = machine::tip_direction(tip);
  V2 origin{}, u{1, 0}, v{0, 1};  // tips 0 and 9: as tip 3, from its corner's nose centre
  if (tip == 0 || tip == 9) {
    origin = {rc, rc};
  } else if (d.x != 0) {
    v = {0, static_cast<double>(-d.x)};
    if (d.z > 0) u = {-1, 0};
    if (d.z == 0) origin = {width / 2, 0};
  } else {
    v = {static_cast<double>(-d.z), 0};
    u = {0, 1};
    origin = {width / 2, 0};
  }
  std::vector<V2> p;
  p.reserve(c.size());
  for (const V2& q : c) p.push_back((q.x - origin.x) * u + (q.y - origin.y) * v);
  return counter_clockwise(std::move(p));
}

}  // namespace

int arc_chords(double r, double angle, double error) {
  if (!(r > 0) || !(angle > 0) || !std::isfinite(r) || !std::isfinite(angle)) return 1;
  const double step = error >= r ? kPi : 2 * std::acos(1 - error / r);
  const double n = std::ceil(angle / step);
  return n >= kMaxArcChords ? kMaxArcChords : std::max(1, static_cast<int>(n));
}

ToolOutline insert_outline(const LatheInsert& insert, const InsertSize& size) {
  const double r = safe_length(insert.nose_radius, kMostLength);
  const int tip = insert.tip >= 0 && insert.tip <= 9 ? insert.tip : 0;
  const double width = safe_length(insert.width, kMostLength);
  InsertSize s = size;
  s.inscribed_circle = std::max(safe_length(size.inscribed_circle, kMostLength), kChordError);
  if (width > 0) return blade(r, tip, width, s);
  const double angle = std::isfinite(insert.insert_angle) ? std::clamp(insert.insert_angle, 1.0, 179.0) : 80.0;
  const double clearance = std::isfinite(insert.clearance_angle) ? std::clamp(insert.clearance_angle, -89.0, 89.0) : 5.0;
  return pointed(r, tip, angle, clearance, s);
}

ToolOutline axial_tool_outline(const MillTool& tool) {
  const double R = safe_length(tool.diameter, 2 * kMostLength) / 2;
  if (!(R > 0)) return {};
  // the end's profile as (height above the tip along +Z, offset across the axis), from -R to R
  std::vector<V2> p;
  const bool point = (tool.kind == MillKind::drill || tool.kind == MillKind::chamfer) && tool.point_angle > 0 &&
                     tool.point_angle < 180;
  double rim = 0;
  if (point) {
    rim = R / std::tan(radians(tool.point_angle) / 2);
    p = {{rim, -R}, {0, 0}, {rim, R}};
  } else if (tool.kind == MillKind::ball || tool.kind == MillKind::bull_nose) {
    const double rc = tool.kind == MillKind::ball ? R : std::clamp(safe_length(tool.corner_radius, R), 0.0, R);
    rim = rc;
    if (rc > 0) {
      add_arc(p, {rc, -(R - rc)}, rc, -kPi / 2, -kPi / 2);  // from (rc, -R) round to (0, -(R - rc))
      add_arc(p, {rc, R - rc}, rc, kPi, -kPi / 2, R > rc);   // from (0, R - rc) round to (rc, R)
    } else {
      p = {{0, -R}, {0, R}};
    }
  } else {
    p = {{0, -R}, {0, R}};
  }
  double length = safe_length(tool.flute_length, kMostLength);
  if (length == 0) length = safe_length(tool.stick_out, kMostLength);
  if (length == 0) length = 4 * 2 * R;
  length = std::max(length, rim + kChordError);
  p.push_back({length, R});
  p.push_back({length, -R});
  return counter_clockwise(std::move(p));
}

ToolOutline tool_outline(const Tool& tool, const InsertSize& size) {
  if (const auto* i = std::get_if<LatheInsert>(&tool)) return insert_outline(*i, size);
  return axial_tool_outline(std::get<MillTool>(tool));
}

}  // namespace ncurve::sim
