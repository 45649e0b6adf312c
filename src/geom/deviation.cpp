// The deviation measure: where coordinates land on the grid, the distance from a point to a
// segment, a ray's chord or an arc, and the largest distance from the curve to a piece (on the
// quintic through its end jets, confirmed on the curve, else searched on the curve).
#include "geom/approx.hpp"
#include "geom/fit_internal.hpp"
#include "geom/search.hpp"
#include "geom/segment_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace ncurve::geom {
using namespace fit;

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

// The curve's maximum near the quintic's: the curve must agree with the quintic there within
// trust and be no higher a thousandth of the step to either side (so its maximum lies between);
// the parabola through the three values places it. NaN if not. At an end of the step the
// quintic's value is the curve's.
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

}  // namespace ncurve::geom
