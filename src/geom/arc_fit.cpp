// Arc fitting: biarcs tangent to the curve at both ends, split at its inflections, each the
// longest whose arcs, as the program writes them, keep within the tolerance.
#include "geom/approx.hpp"
#include "geom/fit_internal.hpp"
#include "geom/search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace ncurve::geom {
using namespace fit;

namespace {

// An arc in the plane (centre, radius, turn), or a line where the turn is too slight.
struct Arc2 {
  bool line = false;
  double cu = 0, cv = 0, r = 0;
  bool ccw = false;
};

// The arc from p (tangent dir) to q, in plane coordinates.
Arc2 arc_from_tangent(double pu, double pv, double tu, double tv, double qu, double qv) {
  double du = qu - pu, dv = qv - pv;
  double nu = -tv, nv = tu;  // left normal
  double side = du * nu + dv * nv;
  double chord2 = du * du + dv * dv;
  Arc2 a;
  if (std::fabs(side) <= 1e-12 * std::sqrt(chord2) || std::fabs(chord2 / (2 * side)) > 1e6) {
    a.line = true;
    return a;
  }
  double r = chord2 / (2 * side);  // signed: positive turns left
  a.cu = pu + nu * r;
  a.cv = pv + nv * r;
  a.r = std::fabs(r);
  a.ccw = r > 0;
  return a;
}

// The direction of travel at t in the plane, unnormalised. Where the curve stops (at an end of
// its range: validate() refuses a stop inside) the velocity is no guide: the tangent's limit is
// along the second derivative there (C'(t + s) ~ C''(t) s), else along the chord to a point a
// millionth of the range inside (a stop of higher order).
std::array<double, 2> travel(const Fit& f, double t, const Local& l) {
  const int u = f.plane.u_axis, v = f.plane.v_axis;
  const double span = f.curve.t1() - f.curve.t0();
  const double speed = std::hypot(l.d1[u], l.d1[v]), bend = std::hypot(l.d2[u], l.d2[v]);
  if (speed > 1e-6 * bend * span) return {l.d1[u], l.d1[v]};
  const double inward = t < 0.5 * (f.curve.t0() + f.curve.t1()) ? 1 : -1;  // into the range
  if (bend > 0) return {inward * l.d2[u], inward * l.d2[v]};
  const Vec3 q = f.place(f.curve.point(t + inward * 1e-6 * span));
  return {inward * (q[u] - l.p[u]), inward * (q[v] - l.p[v])};
}

// Biarc from (P0, T0) to (P1, T1) with equal control lengths; the two arcs (or lines) as pieces.
bool biarc(const Fit& f, double ta, double tb, std::vector<Piece>& out) {
  const int u = f.plane.u_axis, v = f.plane.v_axis;
  Local la = local(f, ta), lb = local(f, tb);
  Vec3 p0 = la.p, p1 = lb.p;
  const auto [t0u_, t0v_] = travel(f, ta, la);
  const auto [t1u_, t1v_] = travel(f, tb, lb);
  double t0u = t0u_, t0v = t0v_, t1u = t1u_, t1v = t1v_;
  double n0 = std::hypot(t0u, t0v), n1 = std::hypot(t1u, t1v);
  if (!(n0 > 0) || !(n1 > 0)) return false;
  t0u /= n0; t0v /= n0; t1u /= n1; t1v /= n1;
  double vu = p1[u] - p0[u], vv = p1[v] - p0[v];
  double su = t0u + t1u, sv = t0v + t1v;
  double vt = vu * su + vv * sv, vvv = vu * vu + vv * vv;
  double qa = 2 * (t0u * t1u + t0v * t1v - 1);  // |T0+T1|^2 - 4
  double d;
  if (std::fabs(qa) < 1e-12) {
    if (std::fabs(vt) < 1e-15) return false;
    d = vvv / (2 * vt);
  } else {
    double disc = vt * vt - qa * vvv;
    if (disc < 0) return false;
    d = (vt - std::sqrt(disc)) / qa;  // qa < 0: this root is the positive one
  }
  if (!(d > 0)) return false;
  // joint: midpoint of the control points
  double ju = 0.5 * (p0[u] + d * t0u + p1[u] - d * t1u);
  double jv = 0.5 * (p0[v] + d * t0v + p1[v] - d * t1v);
  // parameter of the curve point nearest the joint
  auto gap = [&](double t) {
    Vec3 q = f.place(f.curve.point(t));
    return std::hypot(q[u] - ju, q[v] - jv);
  };
  double lo = ta, hi = tb;
  for (int i = 0; i < 80; ++i) {
    double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (gap(m1) < gap(m2)) hi = m2; else lo = m1;
  }
  double tj = 0.5 * (lo + hi);
  Vec3 joint = p0;
  joint[u] = ju;
  joint[v] = jv;
  const int w = 3 - u - v;
  joint[w] = f.place(f.curve.point(tj))[w];
  Arc2 a1 = arc_from_tangent(p0[u], p0[v], t0u, t0v, ju, jv);
  // second arc: from p1 backwards along -T1 to the joint, then reversed
  Arc2 a2 = arc_from_tangent(p1[u], p1[v], -t1u, -t1v, ju, jv);
  a2.ccw = !a2.ccw;
  auto piece = [&](const Arc2& a, const Vec3& s, const Vec3& e, double t_s, double t_e) {
    Piece p;
    p.start = s;
    p.end = e;
    p.t0 = t_s;
    p.t1 = t_e;
    if (!a.line) {
      p.arc = true;
      p.ccw = a.ccw;
      p.centre = s;
      p.centre[u] = a.cu;
      p.centre[v] = a.cv;
    }
    return p;
  };
  out.push_back(piece(a1, p0, joint, ta, tj));
  out.push_back(piece(a2, joint, p1, tj, tb));
  return true;
}

double piece_error(const Fit& f, const Piece& p) {
  auto dist = [&](const Vec3& q) {
    return p.arc ? point_arc_distance(q, p, f.plane) : point_segment_distance(q, p.start, p.end);
  };
  return max_distance(f.curve, f.place, p.t0, p.t1, dist).distance;
}

// Snaps end points and centre as the program will carry them: the centre is written relative to
// the snapped start point, so it snaps on the same grid.
Piece snapped(const Fit& f, Piece p) {
  const Vec3 exact_centre = p.centre;
  p.start = f.grid.snap(p.start);
  p.end = f.grid.snap(p.end);
  if (!p.arc) return p;
  p.centre = f.grid.snap(p.centre);
  if (!f.arcs_with_r) return p;
  // R rounded to its increment; the centre where the control puts it (left of the chord for
  // G03 with R > 0, negative R beyond 180 degrees)
  const int u = f.plane.u_axis, v = f.plane.v_axis;
  double su = p.start[u], sv = p.start[v], du = p.end[u] - su, dv = p.end[v] - sv;
  double d = std::hypot(du, dv);
  double r = std::round(std::hypot(su - exact_centre[u], sv - exact_centre[v]) / f.r_step) * f.r_step;
  double side = du * (exact_centre[v] - sv) - dv * (exact_centre[u] - su);  // > 0: centre left of the chord
  bool major = (side > 0) != p.ccw;
  p.r = major ? -r : r;
  double half = d / 2, h = std::sqrt(std::max(0.0, r * r - half * half));
  double sign = (p.ccw ? 1.0 : -1.0) * (p.r > 0 ? 1.0 : -1.0);
  if (d > 0) {
    p.centre[u] = su + du / 2 - sign * h * dv / d;
    p.centre[v] = sv + dv / 2 + sign * h * du / d;
  }
  return p;
}

// The control's end-point radius check (No.3410) on the arc as written.
bool radius_check_passes(const Fit& f, const Piece& p) {
  if (!p.arc || f.arcs_with_r) return true;
  const int u = f.plane.u_axis, v = f.plane.v_axis;
  double rs = std::hypot(p.start[u] - p.centre[u], p.start[v] - p.centre[v]);
  double re = std::hypot(p.end[u] - p.centre[u], p.end[v] - p.centre[v]);
  return std::fabs(re - rs) <= f.arc_radius_limit;
}

}  // namespace

std::vector<double> inflections(const Curve& curve, const Placement& place, const Plane& plane) {
  auto turn = [&](double t) {
    const Vec3 d1 = place.direction(curve.d1(t)), d2 = place.direction(curve.d2(t));
    return d1[plane.u_axis] * d2[plane.v_axis] - d1[plane.v_axis] * d2[plane.u_axis];
  };
  std::vector<double> out;
  constexpr int kSamples = 2048;
  double t0 = curve.t0(), t1 = curve.t1();
  double prev_t = t0, prev = turn(t0);
  for (int i = 1; i <= kSamples; ++i) {
    double t = t0 + (t1 - t0) * i / kSamples;
    double v = turn(t);
    if ((prev < 0 && v > 0) || (prev > 0 && v < 0)) {
      double lo = prev_t, hi = t;
      for (int k = 0; k < 60; ++k) {
        double mid = 0.5 * (lo + hi);
        if ((turn(mid) > 0) == (prev > 0)) lo = mid; else hi = mid;
      }
      out.push_back(0.5 * (lo + hi));
    }
    if (v != 0) { prev = v; prev_t = t; }
  }
  return out;
}

Path fit_arcs(const Fit& f) {
  if (f.tol <= 2 * f.grid.worst_error())
    throw std::runtime_error(fmt::format("tolerance {} mm is too close to the coordinate rounding", f.tol));
  std::vector<double> breaks = inflections(f.curve, f.place, f.plane);
  breaks.push_back(f.curve.t1());
  Path path;
  double ta = f.curve.t0();
  const double span = f.curve.t1() - f.curve.t0();
  for (double stop : breaks) {
    while (ta < stop) {
      std::vector<Piece> trial;
      auto ok = [&](double tb) {
        trial.clear();
        if (!biarc(f, ta, tb, trial)) return false;
        for (auto& p : trial) {
          Piece s = snapped(f, p);
          if (!radius_check_passes(f, s) || piece_error(f, s) > f.tol) return false;
        }
        return true;
      };
      double guess = std::min(stop, ta + 4 * step_guess(f, local(f, ta), f.tol));
      double lo = longest_step(ta, stop, guess, ok, span, [&] {
        return fmt::format("{}: no arc from t = {:.6g} stays within {} mm", f.curve.name(), ta, f.tol);
      });
      ok(lo);
      for (auto& p : trial) {
        Piece s = snapped(f, p);
        path.max_deviation = std::max(path.max_deviation, piece_error(f, s));
        if (f.budget) f.budget->add();
        path.pieces.push_back(s);
      }
      ta = lo;
    }
  }
  return path;
}

}  // namespace ncurve::geom
