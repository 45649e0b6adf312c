// Stored stroke checks: the limits and the stage that checks each move against them.
#include "machine/path/stroke_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

namespace ncurve::machine {

namespace {
constexpr double kEps = 1e-9;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr const char* kAxisLetters = "XYZABC";

// The point of a move at the fraction t of its path (arcs: of the sweep, the radius and the
// helical axis changing linearly).
AxisVector point_at(const Move& m, double t) {
  AxisVector p{};
  for (int a = 0; a < kAxes; ++a) p[a] = m.start[a] + t * (m.end[a] - m.start[a]);
  if (m.kind != MoveKind::arc) return p;
  const PlaneAxes pa = plane_axes(m.plane);
  const double cp = m.center[pa.p], cq = m.center[pa.q];
  const double rs = std::hypot(m.start[pa.p] - cp, m.start[pa.q] - cq);
  const double re = std::hypot(m.end[pa.p] - cp, m.end[pa.q] - cq);
  const double angle = std::atan2(m.start[pa.q] - cq, m.start[pa.p] - cp) + t * m.sweep;
  const double r = rs + t * (re - rs);
  p[pa.p] = cp + r * std::cos(angle);
  p[pa.q] = cq + r * std::sin(angle);
  return p;
}

// The fractions of an arc's path where it passes a quadrant point (an extreme of an in-plane axis).
std::vector<double> quadrant_fractions(const Move& m) {
  std::vector<double> ts;
  if (m.kind != MoveKind::arc || m.sweep == 0) return ts;
  const PlaneAxes pa = plane_axes(m.plane);
  const double a0 = std::atan2(m.start[pa.q] - m.center[pa.q], m.start[pa.p] - m.center[pa.p]);
  const double sweep = std::fabs(m.sweep);
  for (int k = 0; k < 4; ++k) {
    double along = (k * std::numbers::pi / 2 - a0) * (m.sweep > 0 ? 1 : -1);
    along = std::fmod(along, 2 * std::numbers::pi);
    if (along < 0) along += 2 * std::numbers::pi;
    if (along < sweep) ts.push_back(along / sweep);
  }
  return ts;
}

// Where a segment first runs into the open box (lo, hi) along the axes of mask: the axis it
// enters through and the sign of its motion there; nullopt when it stays out.
struct Entry {
  int axis;
  int sign;
};
std::optional<Entry> enters_box(const AxisVector& p0, const AxisVector& p1, const AxisVector& lo,
                                const AxisVector& hi, unsigned mask) {
  double t_in = -kInf, t_out = kInf;
  int axis = -1;
  for (int a = 0; a < kAxes; ++a) {
    if (!(mask & (1u << a))) continue;
    const double d = p1[a] - p0[a];
    const double l = lo[a] + kEps, h = hi[a] - kEps;
    if (l >= h) return std::nullopt;  // no inside along this axis
    if (d == 0) {
      if (p0[a] <= l || p0[a] >= h) return std::nullopt;
      continue;
    }
    double t0 = (l - p0[a]) / d, t1 = (h - p0[a]) / d;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_in) t_in = t0, axis = a;
    t_out = std::min(t_out, t1);
  }
  if (!(t_in < t_out) || t_out <= 0 || t_in >= 1) return std::nullopt;
  if (t_in <= 0 || axis < 0) {  // it starts inside: the axis that moves the most
    axis = -1;
    for (int a = 0; a < kAxes; ++a)
      if ((mask & (1u << a)) && (axis < 0 || std::fabs(p1[a] - p0[a]) > std::fabs(p1[axis] - p0[axis]))) axis = a;
  }
  return Entry{axis, p1[axis] >= p0[axis] ? 1 : -1};
}

unsigned basic_axes(const std::array<bool, kAxes>& has) {  // check 2 works on X, Y and Z
  unsigned m = 0;
  for (int a = 0; a < 3; ++a)
    if (has[a]) m |= 1u << a;
  return m;
}
}  // namespace

StrokeLimits StrokeLimits::power_on(const MachineProfile& p, const std::array<bool, kAxes>& has_axis) {
  StrokeLimits l;
  l.limit1_plus = p.stroke1_plus;
  l.limit1_minus = p.stroke1_minus;
  for (int a = 0; a < kAxes; ++a) {
    if (!has_axis[a] || l.limit1_plus[a] < l.limit1_minus[a]) l.limit1_plus[a] = kInf, l.limit1_minus[a] = -kInf;
    l.area_plus[a] = std::max(p.stroke2_plus[a], p.stroke2_minus[a]);
    l.area_minus[a] = std::min(p.stroke2_plus[a], p.stroke2_minus[a]);
  }
  l.area_axes = basic_axes(has_axis);
  l.area_outside = p.stroke2_outside;
  return l;
}

void StrokeLimits::update(bool area_on) {
  bool area = area_outside;  // outside forbidden: even an empty area forbids everything
  if (!area) {  // inside forbidden: only an area with an inside can be entered
    area = true;
    for (int a = 0; a < 3; ++a)
      if ((area_axes & (1u << a)) && !(area_plus[a] > area_minus[a])) area = false;
  }
  bool limit1 = false;
  for (int a = 0; a < kAxes; ++a) limit1 = limit1 || std::isfinite(limit1_plus[a]) || std::isfinite(limit1_minus[a]);
  in_force = limit1 || (area_on && area);
}

void StrokeCheck::fail(const Move& m, const char* code, const std::string& message) const {
  alarm_(m, code, message);
  throw nc::Alarm(nc::Diagnostic{nc::Severity::error, code, message, nc::Span{m.file, m.line, 1, 1}});
}

// The control stops the tool at the limit (No.1300#7 BFA: just before it, or just past it);
// ncurve stops before the block's move, and names the axis, where the move would go and the limit.
void StrokeCheck::check(const Move& m) const {
  if (!m.is_motion()) return;
  const StrokeLimits& l = limits_;
  auto fail = [&](const char* code, const std::string& message) { this->fail(m, code, message); };
  const AxisVector shift = frame_.machine_shift();
  auto machine = [&](AxisVector p) {
    for (int a = 0; a < kAxes; ++a) p[a] += shift[a];
    return p;
  };
  AxisVector lo = machine(m.start), hi = lo;
  auto extend = [&](const AxisVector& p) {
    for (int a = 0; a < kAxes; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  };
  extend(machine(m.end));
  for (double t : quadrant_fractions(m)) extend(machine(point_at(m, t)));
  auto shown = [&](int a, double v) { return frame_.program_units(a, v); };
  for (int a = 0; a < kAxes; ++a) {
    if (hi[a] > l.limit1_plus[a] + kEps)
      fail("OT0500", fmt::format("{}+ overtravel (stored stroke limit 1): the move goes to {} {:.4f} (machine "
                                 "coordinates), past the limit {:.4f} (No.1320)",
                                 kAxisLetters[a], kAxisLetters[a], shown(a, hi[a]), shown(a, l.limit1_plus[a])));
    if (lo[a] < l.limit1_minus[a] - kEps)
      fail("OT0501", fmt::format("{}- overtravel (stored stroke limit 1): the move goes to {} {:.4f} (machine "
                                 "coordinates), past the limit {:.4f} (No.1321)",
                                 kAxisLetters[a], kAxisLetters[a], shown(a, lo[a]), shown(a, l.limit1_minus[a])));
  }
  if (!frame_.area_check_on()) return;
  const unsigned mask = l.area_axes;
  auto area = [&] {
    std::string s;
    for (int a = 0; a < 3; ++a)
      if (mask & (1u << a))
        s += fmt::format("{}{} {:.4f}..{:.4f}", s.empty() ? "" : ", ", kAxisLetters[a], shown(a, l.area_minus[a]),
                         shown(a, l.area_plus[a]));
    return s;
  };
  if (l.area_outside) {  // No.1300#0 OUT = 1: the tool stays inside the area
    for (int a = 0; a < 3; ++a) {
      if (!(mask & (1u << a))) continue;
      if (hi[a] > l.area_plus[a] + kEps)
        fail("OT0502", fmt::format("{}+ overtravel (stored stroke check 2): the move goes to {} {:.4f} (machine "
                                   "coordinates), out of the area {} (G22, outside forbidden: No.1300#0 = 1)",
                                   kAxisLetters[a], kAxisLetters[a], shown(a, hi[a]), area()));
      if (lo[a] < l.area_minus[a] - kEps)
        fail("OT0503", fmt::format("{}- overtravel (stored stroke check 2): the move goes to {} {:.4f} (machine "
                                   "coordinates), out of the area {} (G22, outside forbidden: No.1300#0 = 1)",
                                   kAxisLetters[a], kAxisLetters[a], shown(a, lo[a]), area()));
    }
    return;
  }
  // the inside is forbidden: a line is one segment, an arc chords of at most 1 degree
  const int pieces = m.kind == MoveKind::arc
                         ? std::max(4, static_cast<int>(std::ceil(std::fabs(m.sweep) / (std::numbers::pi / 180))))
                         : 1;
  AxisVector from = machine(m.start);
  for (int i = 1; i <= pieces; ++i) {
    const AxisVector to = i == pieces ? machine(m.end) : machine(point_at(m, static_cast<double>(i) / pieces));
    if (const auto e = enters_box(from, to, l.area_minus, l.area_plus, mask)) {
      const int a = e->axis;
      fail(e->sign > 0 ? "OT0502" : "OT0503",
           fmt::format("{}{} overtravel (stored stroke check 2): the move enters the forbidden area {} (machine "
                       "coordinates; G22, inside forbidden: No.1300#0 = 0)",
                       kAxisLetters[a], e->sign > 0 ? '+' : '-', area()));
    }
    from = to;
  }
}

}  // namespace ncurve::machine
