#include "gen/shape_models.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "geom/approx.hpp"

namespace ncurve::gen {

namespace {

using geom::Vec3;

double speed(const geom::Curve& c, double t) {
  Vec3 d = c.d1(t);
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

// Composite 5-point Gauss-Legendre: exact to rounding on a block's smooth stretch of curve.
double arc_length(const geom::Curve& c, double a, double b) {
  static constexpr double x[5] = {0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static constexpr double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                  0.2369268850561891};
  constexpr int kPieces = 4;
  double h = (b - a) / kPieces, sum = 0;
  for (int p = 0; p < kPieces; ++p) {
    double mid = a + h * (p + 0.5);
    for (int i = 0; i < 5; ++i) sum += w[i] * speed(c, mid + 0.5 * h * x[i]);
  }
  return std::fabs(sum * 0.5 * h);
}

void compare(ModelError& e, double model, double truth, std::uint32_t line, std::size_t block) {
  e.max = std::max(e.max, model);
  double diff = std::fabs(model - truth);
  if (diff > e.max_error) {
    e.max_error = diff;
    e.line = line;
    e.block = block;
  }
  if (truth > 0) e.max_relative = std::max(e.max_relative, diff / truth);
}

}  // namespace

ShapeModels shape_models(const std::vector<machine::Move>& contour, const geom::Curve& curve, const Options& o,
                         const Stats& measured) {
  ShapeModels out;
  const AxisMap map = axis_map(curve, o);
  const geom::Placement& place = map;
  const geom::Plane plane = plane_of(o.profile);
  const int u = plane.u_axis, v = plane.v_axis;
  out.centre = map(Vec3{0, 0, 0});
  double t_prev = measured.start_t;
  for (std::size_t i = 0; i < contour.size() && i < measured.deviation.size(); ++i) {
    const machine::Move& m = contour[i];
    const auto [t_end, deviation] = measured.deviation[i];
    const double t0 = t_prev;
    t_prev = t_end;
    BlockShape b;
    b.line = m.line;
    b.t0 = t0;
    b.t1 = t_end;
    b.deviation = deviation;
    b.arc = arc_length(curve, t0, t_end);
    if (m.kind != machine::MoveKind::line) {
      constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
      b.arc_move = true;
      b.chord = b.radius = b.yang = b.joshi = b.narayan = b.khan = kNone;
      out.blocks.push_back(b);
      continue;
    }
    ++out.lines;
    const Vec3 a{m.start[0], m.start[1], m.start[2]}, e{m.end[0], m.end[1], m.end[2]};
    b.chord = std::sqrt((e[0] - a[0]) * (e[0] - a[0]) + (e[1] - a[1]) * (e[1] - a[1]) + (e[2] - a[2]) * (e[2] - a[2]));
    const double k = curve.curvature(0.5 * (t0 + t_end));
    b.radius = k > 0 ? 1 / k : std::numeric_limits<double>::infinity();
    if (k > 0) {
      const double half = 0.5 * b.chord;
      b.yang = half < b.radius ? b.radius - std::sqrt(b.radius * b.radius - half * half) : b.radius;
    }
    b.joshi = geom::max_distance(curve, place, t0, t_end, [&](const Vec3& p) {
                return geom::radial_distance(p, a, e, out.centre, plane);
              }).distance;
    // the angle the chord subtends at the centre
    const double au = a[u] - out.centre[u], av = a[v] - out.centre[v];
    const double eu = e[u] - out.centre[u], ev = e[v] - out.centre[v];
    const double phi = std::fabs(std::atan2(au * ev - av * eu, au * eu + av * ev));
    b.narayan = phi > 1e-12 ? b.chord * phi / (2 * std::sin(phi / 2)) : b.chord;
    b.khan = std::numbers::pi / (2 * std::numbers::sqrt2) * b.chord;

    compare(out.yang, b.yang, b.deviation, b.line, i);
    compare(out.joshi, b.joshi, b.deviation, b.line, i);
    compare(out.narayan, b.narayan, b.arc, b.line, i);
    compare(out.khan, b.khan, b.arc, b.line, i);
    out.arc_length += b.arc;
    out.narayan_length += b.narayan;
    out.khan_length += b.khan;
    out.blocks.push_back(b);
  }
  return out;
}

}  // namespace ncurve::gen
