// A segment's deviation from the curve on the quintic through the jets at its ends, and its
// maxima confirmed on the curve: what the deviation measure and the line fit share (private
// to src/geom).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "geom/approx.hpp"
#include "geom/fit_internal.hpp"
#include "geom/quintic.hpp"
#include "geom/search.hpp"

namespace ncurve::geom::fit {

// On the quintic the place of a maximum matters less: the curve's confirms it.
inline constexpr double kModelResolution = 1e-4;
// A segment's deviation has its humps at the ends (off the curve) and in the middle: four samples.
inline constexpr int kLineSamples = 4;
// Newton's method squares the error at each step: after a step this short the hump is placed
// within kModelResolution (unless the distance's third derivative is 16 times its second).
inline constexpr double kNewtonSettled = 2.5e-3;

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

// A segment's deviation on the quintic (as on_quintic in deviation.cpp), in the segment's frame:
// the quintic's part along the segment (x, from its start) and across it (y, z) are scalar
// quintics, and the distance is the part across plus any part along beyond an end. The humps
// across are where g = y y' + z z' = 0 (z = 0 for a curve in a plane through the segment), found
// by Newton's method from each highest sample, kept between the samples either side; else a
// search of the distance itself. Squared distances are compared, one square root per maximum.
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

inline ModelMaxima on_quintic(const PlacedJet& a, const PlacedJet& b, double h, const Segment& ab, int samples) {
  return SegmentQuintic(a, b, h, ab).maxima(samples);
}

// A hump is confirmed on the curve this fraction of the step to either side of it (see confirmed).
inline constexpr double kConfirmStep = 1e-3;

// Where a segment's hump on the model is confirmed by the curve's jet: true and its parameter t;
// false where no jet is needed (the model's value stands at an end; too near one to bracket: NaN,
// confirmed_without_jet).
inline bool hump_on_curve(double ta, double h, const Maximum& model, double& t) {
  t = ta + h * model.at;
  return !(model.at == 0 || model.at == 1) && !(t - kConfirmStep * h < ta || t + kConfirmStep * h > ta + h);
}
inline double confirmed_without_jet(const Maximum& model) {
  return model.at == 0 || model.at == 1 ? model.value : std::numeric_limits<double>::quiet_NaN();
}

// A segment's hump confirmed (as confirmed in deviation.cpp) from the curve's jet j there: the
// distance across the segment, its slope and bend; the maximum where the slope's tangent line
// crosses zero, which must lie within a thousandth of the step h; its value by the parabola. NaN
// if not (or where the segment's nearest point is an end).
inline double confirmed(const PlacedJet& j, const Segment& segment, double h, const Maximum& model, double trust) {
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

inline double confirmed(const Curve& curve, const Placement& place, const Segment& segment, double ta, double h,
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

}  // namespace ncurve::geom::fit
