// Whether a program's contour follows the curve it is compared with: the moves that approach the
// curve's start and leave its end are set aside, and a contour whose corners lie far from the
// curve (the wrong curve, or wrong parameters) is named as such instead of being measured into
// absurd figures.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "geom/approx.hpp"
#include "geom/curve.hpp"
#include "machine/move.hpp"

namespace ncurve::report {

// The curve as placed on the machine, sampled, for the nearest point to any point.
class CurveNearest {
public:
  CurveNearest(const geom::Curve& curve, const geom::Placement& map, int samples = 4096)
      : curve_(curve), map_(map) {
    for (int k = 0; k <= samples; ++k) {
      const double t = curve.t0() + (curve.t1() - curve.t0()) * k / samples;
      t_.push_back(t);
      points_.push_back(map(curve.point(t)));
    }
  }

  // The distance from p to the curve: the nearest sample, refined by golden section between its
  // neighbours (a curve point is undefined there: the sample's distance stands).
  double distance(const geom::Vec3& p) const {
    std::size_t best = 0;
    double best_sq = INFINITY;
    for (std::size_t k = 0; k < points_.size(); ++k) {
      const double d = square(p, points_[k]);
      if (d < best_sq) best_sq = d, best = k;
    }
    double a = t_[best > 0 ? best - 1 : 0], b = t_[std::min(best + 1, t_.size() - 1)];
    auto f = [&](double t) {
      const double d = square(p, map_(curve_.point(t)));
      return std::isfinite(d) ? d : INFINITY;
    };
    const double g = (std::sqrt(5.0) - 1) / 2;
    double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
    for (int i = 0; i < 60 && b - a > 1e-12 * (1 + std::fabs(a)); ++i) {
      if (fc < fd) b = d, d = c, fd = fc, c = b - g * (b - a), fc = f(c);
      else a = c, c = d, fc = fd, d = a + g * (b - a), fd = f(d);
    }
    return std::sqrt(std::min({best_sq, fc, fd}));
  }

  // The first sample where the curve is undefined (a coordinate not a finite number), if any.
  std::optional<double> undefined_at() const {
    for (std::size_t k = 0; k < points_.size(); ++k)
      if (!std::isfinite(points_[k][0] + points_[k][1] + points_[k][2])) return t_[k];
    return std::nullopt;
  }

  const geom::Placement& map() const { return map_; }
  const geom::Curve& curve() const { return curve_; }

private:
  static double square(const geom::Vec3& a, const geom::Vec3& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
  }
  const geom::Curve& curve_;
  geom::Placement map_;
  std::vector<double> t_;
  std::vector<geom::Vec3> points_;
};

inline geom::Vec3 xyz(const machine::AxisVector& v) { return {v[0], v[1], v[2]}; }

// A corner of the contour is off the curve when it lies farther from it than half the longer of
// its two moves (a chord's middle strays at most half its length from an arc up to a half turn;
// its ends lie on the curve within the tolerance) and farther than `floor` (the tolerance and the
// coordinates' rounding, for moves shorter than those).
inline bool off_curve(double distance, double longer_move, double floor) {
  return distance > std::max(0.5 * longer_move, floor);
}

// Feed moves set aside at each end: those before the first that starts at the curve's start
// (within `near`), and those after the last that ends at the curve's end, looked for among the
// first and last `most` moves (an approach, a plunge, a departure). None is set aside at an end
// where no move starts (ends) there: the measurement then shows how far off the contour is.
struct ContourSpan {
  std::size_t first = 0, last = 0;  // the contour proper: moves [first, last)
};

inline ContourSpan contour_span(const std::vector<machine::Move>& moves, const geom::Curve& curve,
                                const geom::Placement& map, double near, std::size_t most = 8) {
  auto distance = [](const geom::Vec3& a, const geom::Vec3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); };
  const geom::Vec3 start = map(curve.point(curve.t0())), end = map(curve.point(curve.t1()));
  ContourSpan s;
  s.last = moves.size();
  for (std::size_t i = 0; i < moves.size() && i < most; ++i)
    if (distance(xyz(moves[i].start), start) <= near) {
      s.first = i;
      break;
    }
  for (std::size_t i = moves.size(); i > s.first && moves.size() - i < most; --i)  // one move may be the contour
    if (distance(xyz(moves[i - 1].end), end) <= near) {
      s.last = i;
      break;
    }
  return s;
}

// The contour's corner farthest off the curve, by the curve parameters a measurement found
// nearest to them (the start's, then each move's end).
struct OffCurve {
  double distance = 0;
  std::size_t move = 0;  // the move ending at the corner (the first move for its start)
  double longer = 0;     // the longer of the corner's two moves, mm
  geom::Vec3 at{};       // the corner
};

inline std::optional<OffCurve> farthest_off_curve(const std::vector<machine::Move>& contour, const CurveNearest& curve,
                                                  double start_t, const std::vector<double>& end_t, double floor) {
  std::optional<OffCurve> worst;
  for (std::size_t k = 0; k <= contour.size() && k <= end_t.size(); ++k) {
    // corner k: the start of move 0, or the end of move k - 1
    const geom::Vec3 p = xyz(k == 0 ? contour[0].start : contour[k - 1].end);
    const double t = k == 0 ? start_t : end_t[k - 1];
    geom::Vec3 q = curve.map()(curve.curve().point(t));
    double d = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    if (!std::isfinite(d)) d = INFINITY;
    double longer = 0;
    if (k > 0) longer = contour[k - 1].length;
    if (k < contour.size()) longer = std::max(longer, contour[k].length);
    if (off_curve(d, longer, floor) && (!worst || d > worst->distance))
      worst = OffCurve{d, k == 0 ? 0 : k - 1, longer, p};
  }
  return worst;
}

}  // namespace ncurve::report
