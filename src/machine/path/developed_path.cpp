// Sampling of polar (G12.1) and cylindrical (G07.1) interpolation paths (developed_path.hpp).
#include "machine/path/developed_path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncurve::machine {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kCentre = 1e-7;   // mm: a path this close to the centre runs through it
constexpr int kMaxDepth = 40;      // halvings of one piece
constexpr double kArcPiece = kPi / 18;  // arcs are first cut into pieces of 10 degrees about their centre

double wrap_pi(double a) { return std::remainder(a, 2 * kPi); }  // -pi .. pi

// The parameters in (0, 1) where the path runs through the centre (within kCentre).
std::vector<double> centre_crossings(const PlanePath& path) {
  std::vector<double> out;
  if (!path.arc) {
    const V2 d = path.e - path.s;
    const double len2 = dot(d, d);
    if (len2 < 1e-24) return out;
    const double t = -dot(path.s, d) / len2;
    if (std::fabs(cross(path.s, d)) / std::sqrt(len2) < kCentre && t > 1e-12 && t < 1 - 1e-12) out.push_back(t);
    return out;
  }
  if (std::fabs(norm(path.c) - path.rs) >= kCentre || path.sweep == 0) return out;
  // the centre of the plane seen from the arc's centre, measured along the sweep
  const double at = std::atan2(-path.c.y, -path.c.x);
  double along = at - path.a0;
  if (path.sweep > 0) along = std::fmod(std::fmod(along, 2 * kPi) + 2 * kPi, 2 * kPi);
  else along = -std::fmod(std::fmod(-along, 2 * kPi) + 2 * kPi, 2 * kPi);
  const double t = along / path.sweep;
  if (t > 1e-12 && t < 1 - 1e-12) out.push_back(t);
  return out;
}

struct PolarSampler {
  const PlanePath& path;
  double tol;
  std::size_t max_points;
  int sign;
  std::vector<PolarPoint>& out;

  // The machine's point at t; at the centre the angle holds (`prev`).
  PolarPoint point(double t, double prev) const {
    const V2 p = path.at(t);
    const double r = norm(p);
    if (r < kCentre) return {t, 0.0, prev};
    double a = std::atan2(p.y, p.x) + (sign < 0 ? kPi : 0.0);
    a = prev + wrap_pi(a - prev);
    return {t, sign * r, a};
  }

  bool within(const PolarPoint& a, const PolarPoint& b) const {
    if (std::fabs(b.angle - a.angle) > kPi / 2) return false;  // keeps the angle's unwrapping unambiguous
    for (double u : {0.25, 0.5, 0.75}) {
      const V2 q = polar_to_plane(a.linear + u * (b.linear - a.linear), a.angle + u * (b.angle - a.angle));
      if (path.distance(q) > tol) return false;
    }
    return true;
  }

  void refine(const PolarPoint& a, const PolarPoint& b, int depth) {
    if (depth >= kMaxDepth || out.size() >= max_points || within(a, b)) {
      out.push_back(b);
      return;
    }
    const PolarPoint m = point((a.t + b.t) / 2, a.angle);
    refine(a, m, depth + 1);
    const PolarPoint reached = out.back();
    refine(reached, point(b.t, reached.angle), depth + 1);
  }
};
}  // namespace

V2 polar_to_plane(double linear, double angle) { return {linear * std::cos(angle), linear * std::sin(angle)}; }

PlanePath PlanePath::of(const Move& m, int p, int q) {
  PlanePath path;
  path.s = {m.start[p], m.start[q]};
  path.e = {m.end[p], m.end[q]};
  if (m.kind != MoveKind::arc) return path;
  path.arc = true;
  path.c = {m.center[p], m.center[q]};
  path.sweep = m.sweep;
  path.rs = norm(path.s - path.c);
  path.re = norm(path.e - path.c);
  path.a0 = std::atan2(path.s.y - path.c.y, path.s.x - path.c.x);
  return path;
}

V2 PlanePath::at(double t) const {
  if (t <= 0) return s;
  if (t >= 1) return e;
  if (!arc) return {s.x + t * (e.x - s.x), s.y + t * (e.y - s.y)};
  const double a = a0 + t * sweep;
  const double r = rs + t * (re - rs);
  return {c.x + r * std::cos(a), c.y + r * std::sin(a)};
}

double PlanePath::distance(V2 point) const {
  if (!arc) {
    const V2 d = e - s;
    const double len2 = dot(d, d);
    const double t = len2 > 0 ? std::clamp(dot(point - s, d) / len2, 0.0, 1.0) : 0.0;
    return norm(point - at(t));
  }
  const V2 v = point - c;
  double along = std::atan2(v.y, v.x) - a0;  // the radius at the point's angle (a spiral from rs to re)
  along = sweep >= 0 ? std::fmod(std::fmod(along, 2 * kPi) + 2 * kPi, 2 * kPi)
                     : -std::fmod(std::fmod(-along, 2 * kPi) + 2 * kPi, 2 * kPi);
  const double t = sweep != 0 ? std::clamp(along / sweep, 0.0, 1.0) : 0.0;
  return std::fabs(norm(v) - (rs + t * (re - rs)));
}

std::vector<PolarPoint> polar_points(const PlanePath& path, double tol, int& sign, double& angle,
                                     std::size_t max_points) {
  std::vector<PolarPoint> out;
  PolarSampler sampler{path, std::max(tol, 1e-6), max_points, sign, out};
  out.push_back(sampler.point(0, angle));
  std::vector<double> breaks{0};
  for (double t : centre_crossings(path)) breaks.push_back(t);
  breaks.push_back(1);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    if (i > 0) sampler.sign = -sampler.sign;  // through the centre: the linear axis goes past it
    const double ta = breaks[i], tb = breaks[i + 1];
    const int pieces = path.arc ? std::max(1, static_cast<int>(std::ceil(std::fabs(path.sweep) * (tb - ta) / kArcPiece)))
                                : 1;
    for (int k = 1; k <= pieces; ++k) {
      const PolarPoint a = out.back();
      const PolarPoint b = sampler.point(k == pieces ? tb : ta + (tb - ta) * k / pieces, a.angle);
      sampler.refine(a, b, 0);
    }
  }
  sign = sampler.sign;
  angle = out.back().angle;
  return out;
}

std::vector<double> chord_steps(const PlanePath& path, double tol, std::size_t max_points) {
  if (!path.arc) return {0.0, 1.0};
  const double r = std::max(path.rs, path.re);
  tol = std::max(tol, 1e-6);
  std::size_t n = 1;
  if (r > tol) {
    const double step = 2 * std::acos(1 - tol / r);
    n = static_cast<std::size_t>(std::ceil(std::fabs(path.sweep) / step));
  } else {
    n = static_cast<std::size_t>(std::ceil(std::fabs(path.sweep) / (kPi / 2)));
  }
  n = std::clamp<std::size_t>(n, 1, max_points);
  std::vector<double> t(n + 1);
  for (std::size_t k = 0; k <= n; ++k) t[k] = static_cast<double>(k) / static_cast<double>(n);
  return t;
}

}  // namespace ncurve::machine
