// Stored stroke checks: limit 1 (No.1320/No.1321, OT0500/OT0501) and the area of check 2
// (G22/G23, No.1322/No.1323, No.1300#0 OUT; OT0502/OT0503), on the moves as the tool makes them,
// in machine coordinates. Without a limit the check costs one flag test a move (docs/reference-moves.md).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "machine/executor.hpp"

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

void Executor::init_stroke_check() {
  stroke1_plus_ = profile_.stroke1_plus;
  stroke1_minus_ = profile_.stroke1_minus;
  for (int a = 0; a < kAxes; ++a) {
    if (!has_axis_[a] || stroke1_plus_[a] < stroke1_minus_[a]) stroke1_plus_[a] = kInf, stroke1_minus_[a] = -kInf;
    stroke2_plus_[a] = std::max(profile_.stroke2_plus[a], profile_.stroke2_minus[a]);
    stroke2_minus_[a] = std::min(profile_.stroke2_plus[a], profile_.stroke2_minus[a]);
  }
  stroke_area_switch(!profile_.stroke2_off_at_power_on);
}

// G22 X Y Z I J K: the corners of the area of check 2 in machine coordinates (lathe X and I as
// diameters), then check 2 on.
void Executor::stroke_area_command() {
  const char corner[3][2] = {{'X', 'I'}, {'Y', 'J'}, {'Z', 'K'}};
  for (int a = 0; a < 3; ++a) {
    if (!has_axis_[a]) continue;
    const double scale = a == 0 && profile_.lathe() && profile_.diameter_x ? 0.5 : 1.0;
    if (has(corner[a][0])) stroke2_plus_[a] = dimension(word(corner[a][0])) * scale;
    if (has(corner[a][1])) stroke2_minus_[a] = dimension(word(corner[a][1])) * scale;
    if (stroke2_plus_[a] < stroke2_minus_[a]) std::swap(stroke2_plus_[a], stroke2_minus_[a]);
  }
  stroke_area_switch(true);
}

void Executor::stroke_area_switch(bool on) {
  modal_.stroke2_on = on;
  bool area = profile_.stroke2_outside;  // outside forbidden: even an empty area forbids everything
  if (!area) {  // inside forbidden: only an area with an inside can be entered
    area = true;
    const unsigned mask = basic_axes(has_axis_);
    for (int a = 0; a < 3; ++a)
      if ((mask & (1u << a)) && !(stroke2_plus_[a] > stroke2_minus_[a])) area = false;
  }
  bool limit1 = false;
  for (int a = 0; a < kAxes; ++a) limit1 = limit1 || std::isfinite(stroke1_plus_[a]) || std::isfinite(stroke1_minus_[a]);
  stroke_check_ = limit1 || (modal_.stroke2_on && area);
}

// The control stops the tool at the limit (No.1300#7 BFA: just before it, or just past it);
// ncurve stops before the block's move, and names the axis, where the move would go and the limit.
void Executor::check_stroke(const Move& m) const {
  if (!m.is_motion()) return;
  auto fail = [&](std::string code, std::string message) {
    throw nc::Alarm(nc::Diagnostic{nc::Severity::error, std::move(code), std::move(message), nc::Span{m.file, m.line, 1, 1}});
  };
  AxisVector shift{};
  for (int a = 0; a < kAxes; ++a) shift[a] = coords_.origin[a] + coords_.tool_shift[a];
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
  auto shown = [&](int a, double v) { return program_units(a, v); };
  for (int a = 0; a < kAxes; ++a) {
    if (hi[a] > stroke1_plus_[a] + kEps)
      fail("OT0500", fmt::format("{}+ overtravel (stored stroke limit 1): the move goes to {} {:.4f} (machine "
                                 "coordinates), past the limit {:.4f} (No.1320)",
                                 kAxisLetters[a], kAxisLetters[a], shown(a, hi[a]), shown(a, stroke1_plus_[a])));
    if (lo[a] < stroke1_minus_[a] - kEps)
      fail("OT0501", fmt::format("{}- overtravel (stored stroke limit 1): the move goes to {} {:.4f} (machine "
                                 "coordinates), past the limit {:.4f} (No.1321)",
                                 kAxisLetters[a], kAxisLetters[a], shown(a, lo[a]), shown(a, stroke1_minus_[a])));
  }
  if (!modal_.stroke2_on) return;
  const unsigned mask = basic_axes(has_axis_);
  auto area = [&] {
    std::string s;
    for (int a = 0; a < 3; ++a)
      if (mask & (1u << a))
        s += fmt::format("{}{} {:.4f}..{:.4f}", s.empty() ? "" : ", ", kAxisLetters[a], shown(a, stroke2_minus_[a]),
                         shown(a, stroke2_plus_[a]));
    return s;
  };
  if (profile_.stroke2_outside) {  // No.1300#0 OUT = 1: the tool stays inside the area
    for (int a = 0; a < 3; ++a) {
      if (!(mask & (1u << a))) continue;
      if (hi[a] > stroke2_plus_[a] + kEps)
        fail("OT0502", fmt::format("{}+ overtravel (stored stroke check 2): the move goes to {} {:.4f} (machine "
                                   "coordinates), out of the area {} (G22, outside forbidden: No.1300#0 = 1)",
                                   kAxisLetters[a], kAxisLetters[a], shown(a, hi[a]), area()));
      if (lo[a] < stroke2_minus_[a] - kEps)
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
    if (const auto e = enters_box(from, to, stroke2_minus_, stroke2_plus_, mask)) {
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
