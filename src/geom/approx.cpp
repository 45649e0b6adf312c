#include "geom/approx.hpp"
#include "base/memory.hpp"
#include "base/parallel.hpp"
#include "base/vector_clones.hpp"
#include "geom/quintic.hpp"
#include "geom/search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace ncurve::geom {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

using Local = PlacedJet;
Local local(const Fit& f, double t) { return placed_jet(f.curve, f.place, t); }

// Outward unit normal (away from the centre of curvature) and curvature of the placed curve.
double outward(const Local& l, Vec3& n) {
  double s2 = dot(l.d1, l.d1);
  Vec3 perp = sub(l.d2, scale(l.d1, dot(l.d2, l.d1) / s2));
  double len = norm(perp);
  n = len > 0 ? scale(perp, -1.0 / len) : Vec3{0, 0, 0};
  return len / s2;
}


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

}  // namespace

Grid::Grid(const Vec3& step) : step_(step), per_mm_{} {
  for (int a = 0; a < 3; ++a)
    if (step[a] > 0) per_mm_[a] = 1 / step[a];
}

Vec3 Grid::snap(const Vec3& p) const {
  // to the nearest whole number by adding and taking away 1.5 * 2^52 (exact below 2^51, ties to
  // even; IEEE arithmetic keeps it from being folded away): a library call fewer than std::round
  constexpr double kShift = 0x1.8p52;
  Vec3 out;
  for (int a = 0; a < 3; ++a) {
    if (!(step_[a] > 0)) {
      out[a] = p[a];
      continue;
    }
    const double steps = p[a] * per_mm_[a];
    out[a] = (std::fabs(steps) < 0x1p51 ? (steps + kShift) - kShift : std::round(steps)) * step_[a];
  }
  return out;
}

double Grid::worst_error() const { return 0.5 * norm(step_); }

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) { return Segment(a, b).distance(p); }

double radial_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& centre, const Plane& plane) {
  const int u = plane.u_axis, v = plane.v_axis;
  // centre + s (p - centre) on the line a + r (b - a): solve the 2x2 system for s
  double du = p[u] - centre[u], dv = p[v] - centre[v];
  double eu = b[u] - a[u], ev = b[v] - a[v];
  double det = du * ev - dv * eu;
  if (std::fabs(det) < 1e-300) return point_segment_distance(p, a, b);  // ray along the chord
  double s = ((a[u] - centre[u]) * ev - (a[v] - centre[v]) * eu) / det;
  return std::fabs(1 - s) * std::hypot(du, dv);
}

double point_arc_distance(const Vec3& p, const Piece& arc, const Plane& plane) {
  const int u = plane.u_axis, v = plane.v_axis, w = 3 - u - v;
  double a0 = std::atan2(arc.start[v] - arc.centre[v], arc.start[u] - arc.centre[u]);
  double a1 = std::atan2(arc.end[v] - arc.centre[v], arc.end[u] - arc.centre[u]);
  double sweep = arc.ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-12) sweep += 2 * std::numbers::pi;
  double r0 = std::hypot(arc.start[u] - arc.centre[u], arc.start[v] - arc.centre[v]);
  double r1 = std::hypot(arc.end[u] - arc.centre[u], arc.end[v] - arc.centre[v]);
  double ap = std::atan2(p[v] - arc.centre[v], p[u] - arc.centre[u]);
  double along = arc.ccw ? ap - a0 : a0 - ap;
  while (along < 0) along += 2 * std::numbers::pi;
  while (along >= 2 * std::numbers::pi) along -= 2 * std::numbers::pi;
  if (along <= sweep) {
    double f = along / sweep;
    double r = r0 + (r1 - r0) * f;
    double pw = arc.start[w] + (arc.end[w] - arc.start[w]) * f;
    double radial = std::hypot(p[u] - arc.centre[u], p[v] - arc.centre[v]) - r;
    return std::hypot(radial, p[w] - pw);
  }
  return std::min(norm(sub(p, arc.start)), norm(sub(p, arc.end)));
}

// A piece within a tolerance is short: six samples find its humps (at most three: both ends and
// the middle, when its ends sit off the curve), Brent's method places each to a millionth of it.
constexpr int kPieceSamples = 6;
constexpr double kPieceResolution = 1e-6;
// On the quintic the place of a maximum matters less: the curve's confirms it.
constexpr double kModelResolution = 1e-4;
// A segment's deviation has its humps at the ends (off the curve) and in the middle: four samples.
constexpr int kLineSamples = 4;
// Newton's method squares the error at each step: after a step this short the hump is placed
// within kModelResolution (unless the distance's third derivative is 16 times its second).
constexpr double kNewtonSettled = 2.5e-3;

Worst max_distance(const Curve& curve, const Placement& place, double ta, double tb,
                   const std::function<double(const Vec3&)>& dist) {
  auto m = sampled_maximum([&](double t) { return dist(place(curve.point(t))); }, ta, tb, kPieceSamples,
                           kPieceResolution * (tb - ta));
  return {m.value, m.at};
}

PlacedJet placed_jet(const Curve::Jet& j, const Placement& place) {
  return {place(j.p), place.direction(j.d1), place.direction(j.d2)};
}

PlacedJet placed_jet(const Curve& curve, const Placement& place, double t) { return placed_jet(curve.jet(t), place); }

namespace {

// The highest two maxima of dist over the quintic through the jets at both ends of a step h
// long, in s = 0..1 (second: value -inf if there is one hump).
struct ModelMaxima {
  Maximum best{-std::numeric_limits<double>::infinity(), 0}, second = best;
  void note(const Maximum& x) {  // NaN stays the best
    if (std::isnan(best.value)) return;
    if (std::isnan(x.value) || x.value > best.value) second = best, best = x;
    else if (x.value > second.value) second = x;
  }
};
// f's two highest maxima over s = 0..1, each placed by refine (see each_sampled_maximum).
template <class F, class Refine>
ModelMaxima two_highest(F f, int samples, Refine refine) {
  ModelMaxima m;
  each_sampled_maximum(f, 0.0, 1.0, samples, kModelResolution, [&](const Maximum& x) { m.note(x); }, refine);
  return m;
}

template <class Dist>
ModelMaxima on_quintic(const PlacedJet& a, const PlacedJet& b, double h, Dist dist, int samples) {
  const Quintic q = Quintic::through(a.p, a.d1, a.d2, b.p, b.d1, b.d2, h);
  auto at = [&](double s) { return dist(s == 0 ? a.p : s == 1 ? b.p : q.at(s)); };
  return two_highest(at, samples, [&](double lo, double hi, double x, double fx) {
    return brent_maximum(at, lo, hi, x, fx, kModelResolution);
  });
}

// The same for a segment, in its frame: the quintic's part along the segment (x, from its
// start) and across it (y, z) are scalar quintics, and the distance is the part across plus any
// part along beyond an end. The humps across are where g = y y' + z z' = 0 (z = 0 for a curve in
// a plane through the segment), found by Newton's method from each highest sample, kept between
// the samples either side; else a search of the distance itself. Squared distances are compared,
// one square root per maximum.
class SegmentQuintic {
public:
  using Poly = std::array<double, 6>;  // sum c[k] s^k

  SegmentQuintic(const PlacedJet& a, const PlacedJet& b, double h, const Segment& ab) {
    length_ = norm(ab.vector());
    const Vec3 along = length_ > 0 ? scale(ab.vector(), 1 / length_) : Vec3{1, 0, 0};
    // across: perpendicular to `along` and to the axis it has least of (a curve in a plane of axes: z = 0)
    int least = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(along[i]) < std::fabs(along[least])) least = i;
    const Vec3 start = sub(a.p, ab.start()), end = sub(b.p, ab.start());
    const int w = least;
    if (along[w] == 0 && start[w] == 0 && end[w] == 0 && a.d1[w] == 0 && a.d2[w] == 0 && b.d1[w] == 0 &&
        b.d2[w] == 0) {
      // segment and jets in the plane of the other two axes, (u, v): across is (-along v, along u)
      const int u = (w + 1) % 3, v = (w + 2) % 3;
      auto x = [&](const Vec3& e) { return along[u] * e[u] + along[v] * e[v]; };
      auto y = [&](const Vec3& e) { return along[u] * e[v] - along[v] * e[u]; };
      put(x_, x(start), Quintic::coefficients(x(end) - x(start), x(a.d1), x(a.d2), x(b.d1), x(b.d2), h));
      put(y_, y(start), Quintic::coefficients(y(end) - y(start), y(a.d1), y(a.d2), y(b.d1), y(b.d2), h));
      z_ = Poly{};
      at_end_ = squared(x(end), y(end), 0.0);
    } else {
      Vec3 axis{0, 0, 0};
      axis[least] = 1;
      Vec3 across = cross(along, axis);
      across = scale(across, 1 / norm(across));
      const Vec3 other = cross(along, across);
      const Quintic q = Quintic::through(a.p, a.d1, a.d2, b.p, b.d1, b.d2, h);
      for (auto [poly, e] : {std::pair{&x_, along}, std::pair{&y_, across}, std::pair{&z_, other}}) {
        (*poly)[0] = dot(e, start);
        for (std::size_t k = 0; k < 5; ++k) (*poly)[k + 1] = dot(e, q.c[k]);
      }
      at_end_ = squared(dot(along, end), dot(across, end), dot(other, end));
    }
    flat_ = z_ == Poly{};
    derive(y_, y1_, y2_);
    if (!flat_) derive(z_, z1_, z2_);
  }

  // the squared distance at s
  double at(double s) const {
    if (s == 1) return at_end_;
    const Poly pw = powers(s);
    return squared(poly(x_, pw), poly(y_, pw), flat_ ? 0.0 : poly(z_, pw));
  }

  // Newton's method on g from start, within (lo, hi): the maximum it settles on, else false.
  bool newton(double lo, double hi, double start, Maximum& found) const {
    double s = start;
    for (int iteration = 0; iteration < 12; ++iteration) {
      const Poly pw = powers(s);
      const double v = poly(y_, pw), v1 = poly(y1_, pw), v2 = poly(y2_, pw);
      double g = v * v1, dg = v1 * v1 + v * v2;
      if (!flat_) {
        const double w = poly(z_, pw), w1 = poly(z1_, pw), w2 = poly(z2_, pw);
        g += w * w1, dg += w1 * w1 + w * w2;
      }
      if (!(dg < 0)) return false;
      const double next = s - g / dg;
      if (!(next > lo && next < hi)) return false;
      if (std::fabs(next - s) < kNewtonSettled) {
        found = {at(next), next};
        return true;
      }
      s = next;
    }
    return false;
  }

  // The hump that Newton's method finds from the middle (its distance); value NaN if none.
  Maximum middle_hump() const {
    Maximum m{std::numeric_limits<double>::quiet_NaN(), 0.5};
    if (newton(0, 1, 0.5, m)) m.value = std::sqrt(m.value);
    return m;
  }

  // each sample no lower than its neighbours: an end one falling away from the end is that
  // end's maximum, else Newton's method from the vertex of the parabola through it and its
  // neighbours (see each_sampled_maximum)
  ModelMaxima maxima(int samples) const {
    constexpr int kMostSamples = 16;
    if (samples < 2 || samples > kMostSamples) throw std::invalid_argument("SegmentQuintic::maxima: 2..16 samples");
    ModelMaxima m;
    std::array<double, kMostSamples + 1> value;
    const double step = 1.0 / samples;
    auto sample = [&](int i) { return i == samples ? 1.0 : i * step; };
    auto at_fn = [this](double s) { return at(s); };
    for (int i = 0; i <= samples; ++i) {
      value[i] = at(sample(i));
      if (std::isnan(value[i])) {
        m.note({value[i], sample(i)});
        return m;
      }
    }
    for (int i = 0; i <= samples; ++i) {
      if (!((i == 0 || value[i] > value[i - 1]) && (i == samples || value[i] >= value[i + 1]))) continue;
      Maximum x{value[i], sample(i)};
      const bool end_maximum = i == 0 ? !(rising(0) > 0) : i == samples && !(rising(1) < 0);
      if (!end_maximum) {
        const double lo = sample(std::max(0, i - 1)), hi = sample(std::min(samples, i + 1));
        double start = x.at;
        if (i > 0 && i < samples) {
          const double bend = value[i - 1] - 2 * value[i] + value[i + 1];
          if (bend < 0) start = std::clamp(x.at + 0.5 * step * (value[i - 1] - value[i + 1]) / bend, lo, hi);
        }
        Maximum refined;
        if (!newton(lo, hi, start, refined)) refined = brent_maximum(at_fn, lo, hi, x.at, x.value, kModelResolution);
        if (refined.value > x.value) x = refined;
      }
      m.note(x);
    }
    for (Maximum* found : {&m.best, &m.second})
      if (found->value >= 0) found->value = std::sqrt(found->value);
    return m;
  }

private:
  static void put(Poly& p, double at_start, const std::array<double, 5>& c) {
    p[0] = at_start;
    for (std::size_t k = 0; k < 5; ++k) p[k + 1] = c[k];
  }
  static Poly powers(double s) {
    const double s2 = s * s, s4 = s2 * s2;
    return {1, s, s2, s2 * s, s4, s4 * s};
  }
  // summed in pairs: short chains of dependent operations
  static double poly(const Poly& c, const Poly& pw) {
    return (c[0] + c[1] * pw[1]) + (c[2] * pw[2] + c[3] * pw[3]) + (c[4] * pw[4] + c[5] * pw[5]);
  }
  // the first and second derivatives' coefficients
  static void derive(const Poly& c, Poly& c1, Poly& c2) {
    for (std::size_t k = 0; k < 5; ++k) c1[k] = static_cast<double>(k + 1) * c[k + 1];
    for (std::size_t k = 0; k < 4; ++k) c2[k] = static_cast<double>((k + 1) * (k + 2)) * c[k + 2];
    c1[5] = c2[4] = c2[5] = 0;
  }
  double squared(double px, double py, double pz) const {
    const double beyond = px < 0 ? px : px > length_ ? px - length_ : 0.0;
    return py * py + pz * pz + beyond * beyond;
  }
  // half the squared distance's slope at s = 0 or 1
  double rising(double s) const {
    auto value_slope = [s](const Poly& c, double& v, double& v1) {
      if (s == 0) {
        v = c[0], v1 = c[1];
      } else {
        v = c[0] + c[1] + c[2] + c[3] + c[4] + c[5];
        v1 = c[1] + 2 * c[2] + 3 * c[3] + 4 * c[4] + 5 * c[5];
      }
    };
    double px, px1, py, py1, pz, pz1;
    value_slope(x_, px, px1);
    value_slope(y_, py, py1);
    value_slope(z_, pz, pz1);
    const double beyond = px < 0 ? px : px > length_ ? px - length_ : 0.0;
    return py * py1 + pz * pz1 + beyond * px1;
  }

  Poly x_, y_, z_, y1_, y2_, z1_{}, z2_{};
  double length_ = 0, at_end_ = 0;
  bool flat_ = false;
};

ModelMaxima on_quintic(const PlacedJet& a, const PlacedJet& b, double h, const Segment& ab, int samples) {
  return SegmentQuintic(a, b, h, ab).maxima(samples);
}

// The curve's maximum near the quintic's: the curve must agree with the quintic there within
// trust and be no higher a thousandth of the step to either side (so its maximum lies between);
// the parabola through the three values places it. NaN if not. At an end of the step the
// quintic's value is the curve's.
constexpr double kConfirmStep = 1e-3;
template <class OnCurve>
double confirmed(OnCurve on_curve, double ta, double h, const Maximum& model, double trust) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (model.at == 0 || model.at == 1) return model.value;
  const double t = ta + h * model.at, d = kConfirmStep * h;
  if (t - d < ta || t + d > ta + h) return kNaN;  // too near an end to bracket
  const double v = on_curve(t);
  if (!(std::fabs(v - model.value) <= trust)) return kNaN;
  const double before = on_curve(t - d), after = on_curve(t + d);
  const double slack = 1e-6 * trust;
  if (before > v + slack || after > v + slack) return kNaN;
  const double bend = before + after - 2 * v;  // <= 0 about a maximum
  if (bend >= 0) return std::max({v, before, after});
  return v - 0.125 * (after - before) * (after - before) / bend;  // the parabola's vertex value
}

// Where a segment's hump on the model is confirmed by the curve's jet: true and its parameter t;
// false where no jet is needed (the model's value stands at an end; too near one to bracket: NaN,
// confirmed_without_jet).
bool hump_on_curve(double ta, double h, const Maximum& model, double& t) {
  t = ta + h * model.at;
  return !(model.at == 0 || model.at == 1) && !(t - kConfirmStep * h < ta || t + kConfirmStep * h > ta + h);
}
double confirmed_without_jet(const Maximum& model) {
  return model.at == 0 || model.at == 1 ? model.value : std::numeric_limits<double>::quiet_NaN();
}

// The same for a segment from the curve's jet j there: the distance across the segment, its slope
// and bend; the maximum where the slope's tangent line crosses zero, which must lie within a
// thousandth of the step h; its value by the parabola. NaN if not (or where the segment's nearest
// point is an end).
double confirmed(const PlacedJet& j, const Segment& segment, double h, const Maximum& model, double trust) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const Vec3& ab = segment.vector();
  const double length2 = dot(ab, ab);
  if (!(length2 > 0)) return kNaN;
  const Vec3 r = sub(j.p, segment.start());
  const double along = dot(r, ab) / length2;
  if (!(along > 0 && along < 1)) return kNaN;
  auto across = [&](const Vec3& e, double part) { return sub(e, scale(ab, part)); };
  const Vec3 w = across(r, along), w1 = across(j.d1, dot(j.d1, ab) / length2), w2 = across(j.d2, dot(j.d2, ab) / length2);
  const double v = norm(w);
  if (!(std::fabs(v - model.value) <= trust) || !(v > 0)) return kNaN;
  const double slope = dot(w, w1) / v;
  const double bend = (dot(w1, w1) + dot(w, w2) - slope * slope) / v;
  if (!(bend < 0) || std::fabs(slope) > -bend * kConfirmStep * h) return kNaN;
  return v - 0.5 * slope * slope / bend;
}

double confirmed(const Curve& curve, const Placement& place, const Segment& segment, double ta, double h,
                 const Maximum& model, double trust) {
  double t;
  if (!hump_on_curve(ta, h, model, t)) return confirmed_without_jet(model);
  return confirmed(placed_jet(curve, place, t), segment, h, model, trust);
}

// The curve's maximum over the quintic's humps (on_curve(hump): its value confirmed, or NaN):
// each one within trust of the highest confirmed on the curve; NaN if one is not.
template <class OnCurve>
Maximum confirmed(OnCurve on_curve, const ModelMaxima& model, double trust) {
  Maximum out{on_curve(model.best), model.best.at};
  if (model.second.value >= model.best.value - trust) {
    const double v = on_curve(model.second);
    if (std::isnan(v) || v > out.value) out = {v, model.second.at};
  }
  return out;
}

// The maxima that model(h) finds on the quintic, confirmed on the curve (on_curve(h, hump));
// else the curve searched.
template <class Dist, class Model, class OnCurve>
Worst confirmed_maximum(const Curve& curve, const Placement& place, double ta, double tb, const PlacedJet& a,
                        Dist dist, double trust, Model model, OnCurve on_curve) {
  const double h = tb - ta;
  if (!(h > 0)) return {dist(a.p), ta};
  const Maximum v = confirmed([&](const Maximum& hump) { return on_curve(h, hump); }, model(h), trust);
  if (std::isnan(v.value)) return max_distance(curve, place, ta, tb, dist);
  return {v.value, ta + h * v.at};
}

// The same for a segment, its quintic's maxima from model(h).
template <class Model>
Worst segment_maximum(const Curve& curve, const Placement& place, double ta, double tb, const PlacedJet& a,
                      const Segment& segment, double trust, Model model) {
  auto on_curve = [&](double h, const Maximum& m) { return confirmed(curve, place, segment, ta, h, m, trust); };
  return confirmed_maximum(curve, place, ta, tb, a, [&](const Vec3& p) { return segment.distance(p); }, trust, model,
                           on_curve);
}

}  // namespace

Worst max_distance(const Curve& curve, const Placement& place, double ta, double tb, const PlacedJet& a,
                   const PlacedJet& b, const std::function<double(const Vec3&)>& dist, double trust, int samples) {
  auto on_curve = [&](double h, const Maximum& m) {
    return confirmed([&](double t) { return dist(place(curve.point(t))); }, ta, h, m, trust);
  };
  return confirmed_maximum(curve, place, ta, tb, a, dist, trust,
                           [&](double h) { return on_quintic(a, b, h, dist, samples); }, on_curve);
}

Worst max_distance(const Curve& curve, const Placement& place, double ta, double tb, const PlacedJet& a,
                   const PlacedJet& b, const Segment& segment, double trust) {
  return segment_maximum(curve, place, ta, tb, a, segment, trust,
                         [&](double h) { return on_quintic(a, b, h, segment, kLineSamples); });
}

void max_distances(const Curve& curve, const Placement& place, std::span<const SegmentPiece> pieces, double trust,
                   std::span<Worst> out) {
  // each piece's humps on its quintic (the second where it comes within trust of the best, as
  // confirmed() takes it), then the jets for all of them together
  struct Hump {
    std::size_t piece;
    Maximum model;
    double value;
  };
  std::vector<Hump> humps;
  std::vector<double> ts;
  std::vector<std::size_t> jet_of;  // humps[i]'s jet: jets[jet_of[i]], or none (kNone)
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  humps.reserve(2 * pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const SegmentPiece& p = pieces[i];
    const double h = p.tb - p.ta;
    if (!(h > 0)) {
      out[i] = {p.segment.distance(p.a.p), p.ta};
      continue;
    }
    const ModelMaxima m = on_quintic(p.a, p.b, h, p.segment, kLineSamples);
    humps.push_back({i, m.best, 0});
    if (m.second.value >= m.best.value - trust) humps.push_back({i, m.second, 0});
  }
  jet_of.assign(humps.size(), kNone);
  for (std::size_t k = 0; k < humps.size(); ++k) {
    const SegmentPiece& p = pieces[humps[k].piece];
    double t;
    if (hump_on_curve(p.ta, p.tb - p.ta, humps[k].model, t)) {
      jet_of[k] = ts.size();
      ts.push_back(t);
    } else {
      humps[k].value = confirmed_without_jet(humps[k].model);
    }
  }
  std::vector<Curve::Jet> jets(ts.size());
  curve.jets(ts, jets);
  for (std::size_t k = 0; k < humps.size(); ++k) {
    if (jet_of[k] == kNone) continue;
    const SegmentPiece& p = pieces[humps[k].piece];
    humps[k].value = confirmed(placed_jet(jets[jet_of[k]], place), p.segment, p.tb - p.ta, humps[k].model, trust);
  }
  // the best hump, or the second where it is NaN or higher; the curve searched where NaN
  for (std::size_t k = 0; k < humps.size();) {
    const std::size_t i = humps[k].piece;
    Maximum worst{humps[k].value, humps[k].model.at};
    for (++k; k < humps.size() && humps[k].piece == i; ++k)
      if (std::isnan(humps[k].value) || humps[k].value > worst.value) worst = {humps[k].value, humps[k].model.at};
    const SegmentPiece& p = pieces[i];
    if (std::isnan(worst.value)) {
      out[i] = max_distance(curve, place, p.ta, p.tb, [&](const Vec3& q) { return p.segment.distance(q); });
    } else {
      out[i] = {worst.value, p.ta + (p.tb - p.ta) * worst.at};
    }
  }
}

namespace {

// max_distance with the placed curve points at both ends already known.
template <class Dist>
double deviation(const Fit& f, double ta, double tb, const Vec3& at_ta, const Vec3& at_tb, Dist dist) {
  auto at = [&](double t) { return dist(t == ta ? at_ta : t == tb ? at_tb : f.place(f.curve.point(t))); };
  return sampled_maximum(at, ta, tb, kPieceSamples, kPieceResolution * (tb - ta)).value;
}

struct Vertex {
  Vec3 at;           // as emitted (snapped)
  Local curve;       // the placed curve there
  Vec3 aimed;        // before snapping
  Vec3 normal;       // the curve's outward normal there
  double curvature;  // and its curvature
};

// Vertices: exact curve points at both ends of the range, elsewhere the curve point moved outward
// by `offset` (a band of +-tol holds segments about 1.4 times longer than chords), then snapped.
Vertex vertex(const Fit& f, double t, double offset) {
  Vertex v;
  v.curve = local(f, t);
  v.curvature = outward(v.curve, v.normal);
  v.aimed = v.curve.p;
  if (offset > 0 && t > f.curve.t0() && t < f.curve.t1()) v.aimed = add(v.curve.p, scale(v.normal, offset));
  v.at = f.grid.snap(v.aimed);
  return v;
}

double segment_error(const Fit& f, double ta, double tb, const Vertex& a, const Vertex& b, bool radial = false) {
  if (radial)
    return deviation(f, ta, tb, a.curve.p, b.curve.p,
                     [&](const Vec3& p) { return radial_distance(p, a.at, b.at, f.centre, f.plane); });
  const Segment ab(a.at, b.at);
  return deviation(f, ta, tb, a.curve.p, b.curve.p, [&](const Vec3& p) { return ab.distance(p); });
}

// A first guess of the parameter step for a sag h where the curve is l (from its curvature k).
double step_guess(const Fit& f, const Local& l, double k, double h) {
  double speed = norm(l.d1);
  double range = f.curve.t1() - f.curve.t0();
  if (!(k > 1e-12) || !(speed > 0)) return range;
  return std::min(range, std::sqrt(8 * h / k) / speed);
}
double step_guess(const Fit& f, const Local& l, double h) {
  Vec3 n;
  return step_guess(f, l, outward(l, n), h);
}

// Steps are searched to 0.3 %: closer, the coordinate rounding decides more than the step does.
constexpr double kStepRel = 3e-3;

// The scan's test of kScanBatch steps at once, its loops on vectors: over[j] is whether the hump
// P at hump_at * s[j] on the quintic lies farther than `limit` from the line from A (`start`) to
// B, the end at s[j] moved by `offset` and snapped: |AP x AB|^2 > limit^2 |AB|^2, computed as
// the scan computes one step (the same operations in the same order). False if a coordinate is
// beyond the fast rounding's reach (the scan then tests those steps one at a time).
// With kAxes = 2, z left out: where the quintic, the offset and the start have none, z adds zeros
// (the same figures).
constexpr std::size_t kScanBatch = 8;
template <int kAxes>
[[gnu::always_inline]] inline bool scan_batch_on(const Quintic& q, const Vec3& offset, const Vec3& start,
                                                 const Grid& grid, double hump_at, double limit2, const double* s,
                                                 bool* over) {
  constexpr double kShift = 0x1.8p52;
  double ab[3][kScanBatch] = {}, ap[3][kScanBatch] = {}, steps[kScanBatch];
  bool in_reach = true;
  for (int a = 0; a < kAxes; ++a) {
    const double o = q.origin[a], c0 = q.c[0][a], c1 = q.c[1][a], c2 = q.c[2][a], c3 = q.c[3][a], c4 = q.c[4][a];
    const double moved = offset[a], from = start[a], step = grid.step()[a], per_mm = grid.per_mm()[a];
    for (std::size_t j = 0; j < kScanBatch; ++j) {
      const double sj = s[j], sh = hump_at * sj;
      ab[a][j] = (o + sj * (c0 + sj * (c1 + sj * (c2 + sj * (c3 + sj * c4))))) + moved;
      ap[a][j] = (o + sh * (c0 + sh * (c1 + sh * (c2 + sh * (c3 + sh * c4))))) - from;
    }
    if (step > 0) {
      for (std::size_t j = 0; j < kScanBatch; ++j) {
        steps[j] = ab[a][j] * per_mm;
        ab[a][j] = ((steps[j] + kShift) - kShift) * step - from;
      }
      for (std::size_t j = 0; j < kScanBatch; ++j) in_reach = in_reach && std::fabs(steps[j]) < 0x1p51;
    } else {
      for (std::size_t j = 0; j < kScanBatch; ++j) ab[a][j] -= from;
    }
  }
  for (std::size_t j = 0; j < kScanBatch; ++j) {
    const double cz = ap[0][j] * ab[1][j] - ap[1][j] * ab[0][j];
    if constexpr (kAxes == 2) {
      over[j] = cz * cz > limit2 * (ab[0][j] * ab[0][j] + ab[1][j] * ab[1][j]);
    } else {
      const double cx = ap[1][j] * ab[2][j] - ap[2][j] * ab[1][j];
      const double cy = ap[2][j] * ab[0][j] - ap[0][j] * ab[2][j];
      const double length2 = ab[0][j] * ab[0][j] + ab[1][j] * ab[1][j] + ab[2][j] * ab[2][j];
      over[j] = cx * cx + cy * cy + cz * cz > limit2 * length2;
    }
  }
  return in_reach;
}
NCURVE_VECTOR_CLONES bool scan_batch(const Quintic& q, const Vec3& offset, const Vec3& start, const Grid& grid,
                                     double hump_at, double limit2, const double* s, bool* over) {
  return scan_batch_on<3>(q, offset, start, grid, hump_at, limit2, s, over);
}
NCURVE_VECTOR_CLONES bool scan_batch_xy(const Quintic& q, const Vec3& offset, const Vec3& start, const Grid& grid,
                                        double hump_at, double limit2, const double* s, bool* over) {
  return scan_batch_on<2>(q, offset, start, grid, hump_at, limit2, s, over);
}

double band_offset(const Fit& f, bool band) { return band ? std::max(0.0, f.tol - f.grid.worst_error()) : 0.0; }
// how far a segment's deviation on the quintic and on the curve may differ (see confirmed)
double trust_of(const Fit& f) { return 1e-3 * f.tol; }

// Greedy longest segments from `from` to `to` (vertices there as anywhere else in the curve),
// room made for `expected` of them; ended early at the first vertex at or beyond `stop`. With
// `errors`, each segment's deviation is noted there.
Path lines_greedy(const Fit& f, bool band, bool radial, double from, double to, std::size_t expected = 0,
                  double stop = std::numeric_limits<double>::infinity(), std::vector<double>* errors = nullptr) {
  Path path;
  path.pieces.reserve(expected);
  const double t_end = to;
  const double span = f.curve.t1() - f.curve.t0();
  const double offset = band_offset(f, band);
  const double trust = trust_of(f);
  double ta = from;
  Vertex a = vertex(f, ta, offset);
  double learned = 1;  // the last step over its curvature prediction (the band, the rounding)
  while (ta < t_end && ta < stop) {
    Vertex b{};
    double b_error = 0, b_t = ta;  // the longest segment within the tolerance tried so far
    ModelMaxima b_model{};
    const double predicted = step_guess(f, a.curve, a.curvature, f.tol + offset);
    // a step tried on the quintic; the longest within the tolerance kept in b
    struct Tried {
      double e;
      ModelMaxima m;
      Vertex end;
    };
    auto tried_with = [&](double tb, const Vertex& end, const SegmentQuintic& model) {
      Tried r{0, model.maxima(kLineSamples), end};
      r.e = r.m.best.value;
      if (r.e <= f.tol && tb > b_t) b = r.end, b_error = r.e, b_t = tb, b_model = r.m;
      return r;
    };
    auto tried_on_model = [&](double tb) {
      const Vertex end = vertex(f, tb, offset);
      return tried_with(tb, end, SegmentQuintic(a.curve, end.curve, tb - ta, Segment(a.at, end.at)));
    };
    auto longest = [&](bool on_model) {
      b_t = ta;
      auto error_to = [&](double tb) {
        if (on_model) return tried_on_model(tb).e;
        Vertex end = vertex(f, tb, offset);
        const double e = segment_error(f, ta, tb, a, end, radial);
        if (e <= f.tol && tb > b_t) b = end, b_error = e, b_t = tb;
        return e;
      };
      double tb = longest_within(ta, t_end, std::min(t_end, ta + predicted * learned), f.tol, offset, error_to, span, [&] {
        return fmt::format("{}: no segment from t = {:.6g} stays within {} mm (tolerance below the machine increment?)",
                           f.curve.name(), ta, f.tol);
      }, kStepRel);
      if (tb != b_t) throw std::logic_error("lines_greedy: the step found was not the longest one measured");
      return tb;
    };
    // The step by a scan: the curve's jet at a first step, the guess, gives the quintic over it,
    // from which the error of longer and shorter steps is estimated without the curve: their end
    // vertex aimed and snapped, their hump where the first step's lies in proportion (its
    // distance is stationary there, so the estimate is off by second-order terms; the first
    // step's own error calibrates it). From a little beyond where the estimate without rounding meets the
    // tolerance, down in steps of 0.1 %, each step estimated within goes on trial until one is:
    // the rounding of the end vertex makes some steps a few per cent longer than others around
    // them, and the scan finds them. NaN where that does not settle it (no hump inside, three
    // trials over).
    auto scanned = [&]() {
      constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
      constexpr double kAbove = 0.02, kBelow = 0.04, kStep = 0.001;
      constexpr int kTrials = 3;
      b_t = ta;
      const double h0 = std::min(t_end, ta + predicted * learned) - ta, t0 = ta + h0;
      const Vertex first = vertex(f, t0, offset);
      // its hump by Newton's method from the middle; the first step goes on trial when the scan
      // comes down to it (or at once, where that finds no hump above both ends or the step ends
      // the curve)
      const SegmentQuintic first_model(a.curve, first.curve, h0, Segment(a.at, first.at));
      Maximum hump = first_model.middle_hump();
      bool first_tried = false;
      if (t0 == t_end || !(hump.value * hump.value > std::max(first_model.at(0), first_model.at(1)))) {
        const Tried r = tried_with(t0, first, first_model);
        first_tried = true;
        if (t0 == t_end && r.e <= f.tol) return t_end;
        hump = {-1, 0};
        for (const Maximum& m : {r.m.best, r.m.second})
          if (m.at > 0 && m.at < 1 && m.value > hump.value) hump = m;
        if (!(hump.value >= 0)) return kNaN;
      }
      const Quintic q = Quintic::through(a.curve.p, a.curve.d1, a.curve.d2, first.curve.p, first.curve.d1,
                                         first.curve.d2, h0);
      const Vec3 offset_vector = offset > 0 ? scale(first.normal, offset) : Vec3{0, 0, 0};
      const bool in_xy = q.c[0][2] == 0 && q.c[1][2] == 0 && q.c[2][2] == 0 && q.c[3][2] == 0 && q.c[4][2] == 0 &&
                         offset_vector[2] == 0 && q.origin[2] == a.at[2] && !(f.grid.step()[2] > 0);
      // |AP x AB|^2 and |AB|^2 (the hump's distance from the line squared is their ratio) for the
      // step h, from a to the end aimed at (snapped, or both ends as aimed)
      auto across = [&](double h, bool snapped, double& length2) {
        const double s = h / h0;
        const Vec3& start = snapped ? a.at : a.aimed;
        const Vec3 aimed = add(q.at(s), offset_vector);
        const Vec3 ab = sub(snapped ? f.grid.snap(aimed) : aimed, start);
        const Vec3 c = cross(sub(q.at(hump.at * s), start), ab);
        length2 = dot(ab, ab);
        return dot(c, c);
      };
      auto estimate = [&](double h, bool snapped) {
        double length2 = 0;
        const double c2 = across(h, snapped, length2);
        return std::sqrt(c2 / length2);
      };
      const double calibration = hump.value - estimate(h0, true);
      const double smooth = estimate(h0, false) + calibration;
      if (!(smooth + offset > 0)) return kNaN;
      const double h_tol = h0 * std::sqrt((f.tol + offset) / (smooth + offset));
      const double limit = f.tol - calibration;  // on the estimate
      if (!(limit > 0)) return kNaN;
      // the steps' tests, a batch at a time as the scan comes to them
      std::array<double, kScanBatch> batch_s{};
      std::array<bool, kScanBatch> batch_over{};
      std::size_t batch_first = 0, batch_end = 0;  // the steps tested: [batch_first, batch_end)
      double batch_rel = 1 + kAbove;                // the rel of step batch_end, as the scan steps it
      bool batches = true;
      auto over_limit = [&](std::size_t i, double h) {
        if (batches && i >= batch_end) {
          for (; batch_end < i; ++batch_end) batch_rel -= kStep;
          batch_first = batch_end;
          for (std::size_t j = 0; j < kScanBatch; ++j, ++batch_end, batch_rel -= kStep)
            batch_s[j] = std::min(h_tol * batch_rel, t_end - ta) / h0;  // as the scan's h (past its end too)
          batches = (in_xy ? scan_batch_xy : scan_batch)(q, offset_vector, a.at, f.grid, hump.at, limit * limit,
                                                         batch_s.data(), batch_over.data());
        }
        if (batches) return batch_over[i - batch_first];
        double length2 = 0;
        return across(h, true, length2) > limit * limit * length2;
      };
      int trials = 0;
      double h_before = 0;
      std::size_t i = 0;
      for (double rel = 1 + kAbove; rel >= 1 - kBelow && trials < kTrials; rel -= kStep, ++i) {
        const double h = std::min(h_tol * rel, t_end - ta);
        if (!first_tried && h <= h0) {
          first_tried = true;
          if (tried_with(t0, first, first_model).e <= f.tol) return b_t;
        }
        if (ta + h <= b_t) return b_t;  // the first trial was longer
        if (h == h_before || over_limit(i, h)) continue;
        h_before = h;
        ++trials;
        if (tried_on_model(ta + h).e <= f.tol) return b_t;
      }
      if (!first_tried) tried_with(t0, first, first_model);
      return b_t > ta ? b_t : kNaN;
    };
    const bool on_model = f.model_steps && !radial;
    double tb = on_model ? scanned() : std::numeric_limits<double>::quiet_NaN();
    if (std::isnan(tb)) tb = longest(on_model);
    if (on_model) {
      const Segment ab(a.at, b.at);
      auto on_curve = [&](const Maximum& m) { return confirmed(f.curve, f.place, ab, ta, tb - ta, m, trust); };
      double e = confirmed(on_curve, b_model, trust).value;
      if (e <= f.tol) b_error = e;
      else tb = longest(false);  // the quintic misleads here: every trial on the curve
    }
    if (tb < t_end) learned = std::clamp((tb - ta) / predicted, 0.25, 4.0);
    path.max_deviation = std::max(path.max_deviation, b_error);
    if (f.budget) f.budget->add();
    path.pieces.push_back(Piece{false, a.at, b.at, {}, false, ta, tb});
    if (errors) errors->push_back(b_error);
    ta = tb;
    a = b;
  }
  return path;
}

// The segments predicted from the curvature (a sag of the tolerance, with the band) from the
// start of the curve up to each of kSamples equal steps in its parameter.
struct Prediction {
  static constexpr std::size_t kSamples = Survey::kSteps;
  std::vector<double> ts, segments;
  double total() const { return segments.back(); }
  // where `count` segments are predicted (0 < count < total())
  double where(double count) const {
    std::size_t i = 1;
    while (segments[i] < count) ++i;
    const double f_in = (count - segments[i - 1]) / (segments[i] - segments[i - 1]);
    return ts[i - 1] + f_in * (ts[i] - ts[i - 1]);
  }
};
// 1 / step_guess at n points from their first and second derivatives (d[0..2][i], d[3..5][i]),
// on vectors: the same operations as outward() and step_guess().
NCURVE_VECTOR_CLONES void step_densities(std::size_t n, const double* const* d, double h, double range, double* out) {
  for (std::size_t i = 0; i < n; ++i) {
    const double ax = d[0][i], ay = d[1][i], az = d[2][i], bx = d[3][i], by = d[4][i], bz = d[5][i];
    const double s2 = ax * ax + ay * ay + az * az;
    const double along = (bx * ax + by * ay + bz * az) / s2;
    const double px = bx - ax * along, py = by - ay * along, pz = bz - az * along;
    const double k = std::sqrt(px * px + py * py + pz * pz) / s2;
    const double speed = std::sqrt(s2);
    const double guess = std::sqrt(8 * h / k) / speed;  // in every lane, then chosen: no branch
    out[i] = 1 / ((k > 1e-12) & (speed > 0) & (guess < range) ? guess : range);
  }
}

Prediction predicted_segments(const Fit& f, bool band) {
  constexpr std::size_t kPoints = Prediction::kSamples + 1;
  const double t0 = f.curve.t0(), t1 = f.curve.t1(), h = f.tol + band_offset(f, band);
  Prediction p;
  p.ts.resize(kPoints);
  p.segments.assign(kPoints, 0.0);
  for (std::size_t i = 0; i < kPoints; ++i) p.ts[i] = t0 + (t1 - t0) * static_cast<double>(i) / Prediction::kSamples;
  std::optional<Survey> own;
  const Survey& survey = f.survey ? *f.survey : own.emplace(f.curve.survey());
  // placed (Placement::component)
  const std::vector<double> none(kPoints, 0.0);
  const double* d[6];
  for (std::size_t a = 0; a < 3; ++a) {
    d[a] = f.place.component(a, survey.d1(0), Survey::kPoints, none.data());
    d[3 + a] = f.place.component(a, survey.d2(0), Survey::kPoints, none.data());
  }
  std::vector<double> density(kPoints);
  step_densities(kPoints, d, h, t1 - t0, density.data());
  for (std::size_t i = 1; i < kPoints; ++i)
    p.segments[i] = p.segments[i - 1] + 0.5 * (density[i] + density[i - 1]) * (p.ts[i] - p.ts[i - 1]);
  return p;
}

// Where a long curve is cut to be fit on several threads at once: about every
// Fit::chunk_segments predicted segments.
struct Chunks {
  std::vector<double> cuts;
  double segments = 0;  // predicted in each
};
Chunks chunk_cuts(const Fit& f, const Prediction& p) {
  const double t0 = f.curve.t0(), t1 = f.curve.t1(), total = p.total();
  if (!(f.chunk_segments > 0) || !std::isfinite(total)) return {{t0, t1}, total};
  const int chunks = std::max(1, static_cast<int>(std::min(total / f.chunk_segments, 64.0)));
  std::vector<double> cuts{t0};
  for (int k = 1; k < chunks; ++k) cuts.push_back(p.where(total * k / chunks));
  cuts.push_back(t1);
  return {cuts, total / chunks};
}

// Fewer predicted segments than this are fit from the start alone.
constexpr double kBothWaysSegments = 16;

// A join is not searched on the curve where its deviation on the quintic through its ends is over
// this many tolerances. On a segment within the tolerance the quintic is off by about a thousandth
// of one, and by the sixth power of the length on a longer one: a join twice as long, 0.07.
constexpr double kJoinHopeless = 1.5;

// The greedy fit from both ends at once (on two cores where there are two), each going to its
// first vertex past `middle`: forwards F0 = t0 .. FK, backwards B0 = t1 .. BJ. Where the longest
// step from a point reaches no less from a later point, k plus the fewest backward steps that reach
// back to Fk is the fewest segments for every k; so F0 .. F(K-1), one segment to the first Bj at or
// before FK, then on to B0, is the fewest. Neither greedy fit is exact (the rounding of vertices
// breaks the rule, steps are searched to a fraction of a per cent), so the joins of one segment
// fewer are tried first; a join is taken where it is within the tolerance, else the forward fit
// goes on to the end. The result depends on the curve alone, not on the threads.
Path lines_both_ways(const Fit& f, bool band, bool radial, double middle, std::size_t expected) {
  const Curve back_curve = f.curve.reversed();
  const Fit back{back_curve, f.place, f.grid,      f.plane,        f.tol,          f.centre,
                 f.arcs_with_r, f.r_step, f.arc_radius_limit, f.model_steps, f.chunk_segments, f.both_ways,
                 nullptr,     f.budget};
  const double t0 = f.curve.t0(), t1 = f.curve.t1();
  Path ahead, behind;
  std::vector<double> ahead_errors, behind_errors;
  bool behind_failed = false;  // its error would name t traced backwards: the forward fit names it
  base::for_each_on_cores(2, [&](std::size_t k) {
    if (k == 0) {
      ahead = lines_greedy(f, band, radial, t0, t1, expected, middle, &ahead_errors);
      return;
    }
    try {
      behind = lines_greedy(back, band, radial, -t1, -t0, expected, -middle, &behind_errors);
    } catch (const std::runtime_error&) {
      behind_failed = true;
    }
  });
  const std::size_t K = ahead.pieces.size();
  const double reached = ahead.pieces.back().t1;
  auto ahead_to_the_end = [&] {
    if (reached < t1) {
      Path rest = lines_greedy(f, band, radial, reached, t1);
      ahead.max_deviation = std::max(ahead.max_deviation, rest.max_deviation);
      ahead.pieces.insert(ahead.pieces.end(), rest.pieces.begin(), rest.pieces.end());
    }
    return ahead;
  };
  if (behind_failed || reached >= t1) return ahead_to_the_end();
  // the vertices: F[k] = ahead's k-th, B[j] = behind's j-th (B[0] = t1), each with its point
  std::vector<double> F{t0}, B{t1};
  for (const Piece& p : ahead.pieces) F.push_back(p.t1);
  for (const Piece& p : behind.pieces) B.push_back(-p.t1);
  auto forward_point = [&](std::size_t k) { return k == 0 ? ahead.pieces[0].start : ahead.pieces[k - 1].end; };
  auto backward_point = [&](std::size_t j) { return j == 0 ? behind.pieces[0].start : behind.pieces[j - 1].end; };
  // the first backward vertex at or before FK, and the last forward vertex before that
  std::size_t j = 1;
  while (B[j] > reached) ++j;
  std::size_t k = K - 1;
  while (k > 0 && F[k] >= B[j]) --k;
  // the joins of one segment fewer, shortest first, then the join the rule gives
  struct Join {
    std::size_t k, j;
  };
  std::vector<Join> joins;
  for (std::size_t dk = 0; dk <= 2; ++dk)  // (k - 1, j), (k, j - 1), (k + 1, j - 2)
    if (k + dk >= 1 && k + dk <= K + 1 && j >= dk && F[k + dk - 1] < B[j - dk]) joins.push_back({k + dk - 1, j - dk});
  std::sort(joins.begin(), joins.end(), [&](const Join& a, const Join& b) { return B[a.j] - F[a.k] < B[b.j] - F[b.k]; });
  if (F[k] < B[j]) joins.push_back({k, j});
  const double offset = band_offset(f, band);
  for (const Join& join : joins) {
    const double ta = F[join.k], tb = B[join.j];
    const Vertex a = vertex(f, ta, offset), b = vertex(f, tb, offset);
    double error;
    if (radial) {
      error = segment_error(f, ta, tb, a, b, true);
    } else {
      const Segment segment(a.at, b.at);
      const ModelMaxima model = on_quintic(a.curve, b.curve, tb - ta, segment, kLineSamples);
      if (model.best.value > kJoinHopeless * f.tol) continue;
      error = segment_maximum(f.curve, f.place, ta, tb, a.curve, segment, trust_of(f), [&](double) { return model; })
                  .distance;
    }
    if (!(error <= f.tol)) continue;
    Path path;
    path.pieces.reserve(join.k + 1 + join.j);
    path.pieces.assign(ahead.pieces.begin(), ahead.pieces.begin() + static_cast<std::ptrdiff_t>(join.k));
    path.pieces.push_back(Piece{false, forward_point(join.k), backward_point(join.j), {}, false, ta, tb});
    for (std::size_t i = join.j; i-- > 0;) {
      const Piece& p = behind.pieces[i];
      path.pieces.push_back(Piece{false, p.end, p.start, {}, false, -p.t1, -p.t0});
    }
    path.max_deviation = error;
    for (std::size_t i = 0; i < join.k; ++i) path.max_deviation = std::max(path.max_deviation, ahead_errors[i]);
    for (std::size_t i = 0; i < join.j; ++i) path.max_deviation = std::max(path.max_deviation, behind_errors[i]);
    return path;
  }
  return ahead_to_the_end();
}

Path lines_in_chunks(const Fit& f, bool band, bool radial = false) {
  const Prediction prediction = predicted_segments(f, band);
  const Chunks c = chunk_cuts(f, prediction);
  const std::vector<double>& cuts = c.cuts;
  const std::size_t chunks = cuts.size() - 1;
  // room for twice the prediction: pages never written cost nothing
  const auto expected = std::isfinite(c.segments) ? static_cast<std::size_t>(2 * c.segments) + 16 : 0;
  if (chunks == 1) {
    if (f.both_ways && prediction.total() >= kBothWaysSegments && std::isfinite(prediction.total()))
      return lines_both_ways(f, band, radial, prediction.where(prediction.total() / 2), expected / 2 + 8);
    return lines_greedy(f, band, radial, cuts[0], cuts[1]);
  }
  std::vector<Path> parts(chunks);
  base::for_each_on_cores(chunks, [&](std::size_t k) {
    parts[k] = lines_greedy(f, band, radial, cuts[k], cuts[k + 1], expected);
  });
  Path path;
  std::size_t pieces = 0;
  for (const Path& part : parts) pieces += part.pieces.size();
  base::reserve_large(path.pieces, pieces);
  for (std::size_t k = 0; k < chunks; ++k) {
    path.max_deviation = std::max(path.max_deviation, parts[k].max_deviation);
    path.pieces.insert(path.pieces.end(), parts[k].pieces.begin(), parts[k].pieces.end());
  }
  return path;
}

// All chords for the given parameters (vertices on the curve); the largest error.
double chords_error(const Fit& f, const std::vector<double>& ts, Path* out) {
  double worst = 0;
  Vertex a = vertex(f, ts[0], 0);
  for (std::size_t i = 1; i < ts.size(); ++i) {
    Vertex b = vertex(f, ts[i], 0);
    double e = segment_error(f, ts[i - 1], ts[i], a, b);
    worst = std::max(worst, e);
    if (out && f.budget) f.budget->add();
    if (out) out->pieces.push_back(Piece{false, a.at, b.at, {}, false, ts[i - 1], ts[i]});
    a = b;
  }
  return worst;
}

std::vector<double> equal_steps(const Fit& f, long n) {
  std::vector<double> ts;
  for (long i = 0; i <= n; ++i) ts.push_back(f.curve.t0() + (f.curve.t1() - f.curve.t0()) * i / n);
  return ts;
}

std::vector<double> equal_chords(const Fit& f, double length) {
  std::vector<double> ts{f.curve.t0()};
  const double t_end = f.curve.t1(), span = t_end - f.curve.t0();
  while (ts.back() < t_end) {
    double ta = ts.back();
    Vec3 pa = f.place(f.curve.point(ta));
    auto shorter = [&](double t) { return norm(sub(f.place(f.curve.point(t)), pa)) <= length; };
    if (shorter(t_end)) {
      ts.push_back(t_end);
      break;
    }
    double speed = norm(local(f, ta).d1);
    double hi = std::min(t_end, ta + 1.5 * length / std::max(speed, 1e-12));
    while (shorter(hi) && hi < t_end) hi = std::min(t_end, ta + 2 * (hi - ta));
    ts.push_back(largest_ok(ta, hi, shorter, span));
    if (ts.size() > 50'000'000) throw std::runtime_error("too many segments");
    if (f.budget && ts.size() > f.budget->most + 1) throw PieceBudget::TooManyPieces(f.budget->most);
  }
  return ts;
}

template <class Make>
long smallest_passing(long lo_fail, long hi, Make passes) {  // passes(hi) is true, passes(lo_fail) false
  while (hi - lo_fail > 1) {
    long mid = lo_fail + (hi - lo_fail) / 2;
    if (passes(mid)) hi = mid; else lo_fail = mid;
  }
  return hi;
}

}  // namespace

Path fit_lines(const Fit& f, LineMethod method) {
  if (f.tol <= f.grid.worst_error())
    throw std::runtime_error(fmt::format("tolerance {} mm is not above the coordinate rounding ({:.6f} mm)", f.tol,
                                         f.grid.worst_error()));
  switch (method) {
    case LineMethod::equal_error: return lines_in_chunks(f, true);
    case LineMethod::equal_error_on_curve: return lines_in_chunks(f, false);
    case LineMethod::radial_error: return lines_in_chunks(f, false, true);
    case LineMethod::equal_step: {
      auto passes = [&](long n) { return chords_error(f, equal_steps(f, n), nullptr) <= f.tol; };
      long n = 1;
      while (!passes(n)) {
        n *= 2;
        if (n > (1L << 24)) throw std::runtime_error("no equal step meets the tolerance");
        if (f.budget && n / 2 >= static_cast<long>(f.budget->most)) throw PieceBudget::TooManyPieces(f.budget->most);
      }
      n = smallest_passing(n / 2, n, passes);
      Path p;
      p.max_deviation = chords_error(f, equal_steps(f, n), &p);
      return p;
    }
    case LineMethod::equal_chord: {
      // the longest chord length for which every chord is within the tolerance (bisection on length)
      Vec3 a = f.place(f.curve.point(f.curve.t0()));
      double total = 0;
      constexpr int kRough = 256;
      for (int i = 1; i <= kRough; ++i) {
        double t = f.curve.t0() + (f.curve.t1() - f.curve.t0()) * i / kRough;
        Vec3 q = f.place(f.curve.point(t));
        total += norm(sub(q, a));
        a = q;
      }
      auto passes = [&](double len) { return chords_error(f, equal_chords(f, len), nullptr) <= f.tol; };
      double lo = 0, hi = total;
      double len = total;
      while (!passes(len)) {
        hi = len;
        len /= 2;
        if (len < 1e-9) throw std::runtime_error("no chord length meets the tolerance");
      }
      lo = len;
      for (int i = 0; i < 30 && hi - lo > 1e-6 * lo; ++i) {
        double mid = 0.5 * (lo + hi);
        if (passes(mid)) lo = mid; else hi = mid;
      }
      Path p;
      p.max_deviation = chords_error(f, equal_chords(f, lo), &p);
      return p;
    }
  }
  return {};
}

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

namespace {

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
