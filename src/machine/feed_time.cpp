// The time a move takes at its programmed feed: per minute, or per revolution of a spindle at S
// rev/min or, under G96, at the speed constant surface speed gives along the move, clamped.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "machine/executor.hpp"

namespace ncurve::machine {

// The mean of 1 / spindle speed (min/rev) along a move whose X radius runs linearly from r0 to r1:
// S rev/min, or under G96 the speed n(r) = 1000 S / (2 pi |r|) that gives S m/min at radius r (taken
// at 0.5 mm nearer the centre), at most G50 S (G92 S on systems B/C). Then 1/n(r) = k max(|r|, rho)
// with k = 2 pi / (1000 S) and rho the radius below which the clamp holds: its mean in closed form.
double Executor::minutes_per_rev(double r0, double r1) const {
  if (!modal_.css || speed_ <= 0) {
    const double rpm = speed_ > 0 ? speed_ : profile_.spindle_speed_for_time;
    return rpm > 0 ? 1.0 / rpm : 0.0;
  }
  const double k = 2 * std::numbers::pi / (1000.0 * speed_);
  const double rho = std::max(0.5, max_spindle_ > 0 ? 1.0 / (k * max_spindle_) : 0.0);
  auto F = [rho](double r) {  // an antiderivative of max(|r|, rho), odd in r
    const double u = std::fabs(r);
    const double g = u <= rho ? rho * u : (u * u + rho * rho) / 2;
    return r < 0 ? -g : g;
  };
  return k * (std::fabs(r1 - r0) < 1e-12 ? std::max(std::fabs(r0), rho) : (F(r1) - F(r0)) / (r1 - r0));
}

// Time at the programmed feed along a move whose X radius runs linearly from r0 to r1.
double Executor::feed_seconds(double length, double r0, double r1) const {
  if (feed_ <= 0) return 0.0;
  return modal_.feed_per_rev ? length / feed_ * 60.0 * minutes_per_rev(r0, r1) : length / feed_ * 60.0;
}

// The same along an arc, whose X radius is not linear in the distance: Simpson's rule on 64 pieces of
// equal angle (the time per mm at one point is feed_seconds at constant radius).
double Executor::arc_feed_seconds(const Move& m, double planar) const {
  const PlaneAxes pa = plane_axes(m.plane);
  if (!modal_.feed_per_rev || !modal_.css || speed_ <= 0 || (pa.p != 0 && pa.q != 0))
    return feed_seconds(planar, m.start[0], m.end[0]);
  const double a0 = std::atan2(m.start[pa.q] - m.center[pa.q], m.start[pa.p] - m.center[pa.p]);
  const double rs = std::hypot(m.start[pa.p] - m.center[pa.p], m.start[pa.q] - m.center[pa.q]);
  const double re = std::hypot(m.end[pa.p] - m.center[pa.p], m.end[pa.q] - m.center[pa.q]);
  auto per_mm = [&](double t) {  // at the fraction t of the arc
    const double r = rs + (re - rs) * t, a = a0 + m.sweep * t;
    const double x = pa.p == 0 ? m.center[0] + r * std::cos(a) : m.center[0] + r * std::sin(a);
    return feed_seconds(1.0, x, x);
  };
  constexpr int kPieces = 64;
  double sum = 0;
  for (int i = 0; i < kPieces; ++i) {
    const double t0 = static_cast<double>(i) / kPieces, t1 = static_cast<double>(i + 1) / kPieces;
    sum += per_mm(t0) + 4 * per_mm((t0 + t1) / 2) + per_mm(t1);
  }
  return planar / kPieces / 6 * sum;
}

// A cutting move faster than the maximum cutting feed (the profile's [feeds] max_cutting, No.1430):
// the control clamps the feed without an alarm, so the move takes the clamped feed's time. `fed` is
// the length the feed is taken along (the arc in the plane for a helix).
void Executor::clamp_to_max_feed(Move& m, double fed) {
  const double max = profile_.max_cutting_feed;
  const double rate = fed / m.seconds * 60.0;
  m.seconds = fed / max * 60.0;
  warn_once("NC2073", fmt::format("F{}{} makes {:.0f} mm/min here, over the maximum cutting feed {:.0f} mm/min (the "
                                  "profile's [feeds] max_cutting, No.1430): the control clamps it without an alarm, "
                                  "and the time is the clamped feed's",
                                  modal_.inch ? feed_ / 25.4 : feed_, modal_.feed_per_rev ? " per revolution" : "",
                                  rate, max));
}

}  // namespace ncurve::machine
