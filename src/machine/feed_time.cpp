// The time a move takes at its programmed feed: per minute, or per revolution of a spindle at S
// rev/min or, under G96, at the speed constant surface speed gives along the move, clamped by G50 S
// and by the machine's limit (No.3772, No.3741..3744), which NC2090 warns of.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "machine/executor.hpp"

namespace ncurve::machine {

// The highest speed the spindle turns at under G96: G50 S (G92 S on systems B/C) and the machine's
// limit (No.3772, the top gear's maximum), the lower of those set; 0 if neither is.
double Executor::css_top_speed() const {
  const double machine = profile_.spindle_limit();
  if (max_spindle_ > 0 && machine > 0) return std::min(max_spindle_, machine);
  return max_spindle_ > 0 ? max_spindle_ : machine;
}

// The mean of 1 / spindle speed (min/rev) along a move whose X radius runs linearly from r0 to r1:
// S rev/min, at most the machine's limit, or under G96 the speed n(r) = 1000 S / (2 pi |r|) that
// gives S m/min at radius r (taken at 0.5 mm nearer the centre), at most css_top_speed(). Then
// 1/n(r) = k max(|r|, rho) with k = 2 pi / (1000 S) and rho the radius below which the clamp holds:
// its mean in closed form.
double Executor::minutes_per_rev(double r0, double r1) const {
  if (!modal_.css || speed_ <= 0) {
    double rpm = speed_ > 0 ? speed_ : profile_.spindle_speed_for_time;
    if (const double limit = profile_.spindle_limit(); limit > 0) rpm = std::min(rpm, limit);
    return rpm > 0 ? 1.0 / rpm : 0.0;
  }
  const double k = 2 * std::numbers::pi / (1000.0 * speed_);
  const double top = css_top_speed();
  const double rho = std::max(0.5, top > 0 ? 1.0 / (k * top) : 0.0);
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
  if (!modal_.feed_per_rev || !modal_.css || speed_ <= 0) return feed_seconds(planar, m.start[0], m.end[0]);
  const PlaneAxes pa = plane_axes(m.plane);
  if (pa.p != 0 && pa.q != 0) return feed_seconds(planar, m.start[0], m.end[0]);
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

// The part of an S over what the machine turns (NC2090): the control clamps the spindle at its limit
// without an alarm. `rpm` is the speed the program asks: S in G97, or under G96 the speed at the
// move's radius nearest the centre, already at most G50 S.
void Executor::warn_spindle_limit(double rpm, std::uint16_t column) {
  int parameter = 0;
  const double limit = profile_.spindle_limit(&parameter);
  const std::string asked = modal_.css ? fmt::format("G96 S{} asks {:.0f} rev/min here,", speed_, rpm)
                                       : fmt::format("S{} rev/min is", speed_);
  const std::string which = parameter == 3772
                                ? "No.3772, the upper limit of spindle speed"
                                : fmt::format("No.{}, the maximum speed of gear {}", parameter, parameter - 3740);
  warn_once("NC2090", fmt::format("{} over the machine's limit: the control clamps the spindle at {:.0f} rev/min ({}) "
                                  "without an alarm: the cut runs slower than programmed, its feed per tooth higher",
                                  asked, limit, which),
            column);
}

// A cutting move under G96 whose radius comes near enough to the centre for the speed to pass the
// machine's limit, with no G50 S at or below that limit to hold it (NC2090).
void Executor::check_css_spindle_limit(const Move& m) {
  const double limit = profile_.spindle_limit();
  if (limit <= 0 || (max_spindle_ > 0 && max_spindle_ <= limit)) return;
  double r = std::min(std::fabs(m.start[0]), std::fabs(m.end[0]));
  if (m.kind == MoveKind::line && m.start[0] * m.end[0] <= 0) r = 0;
  if (m.kind == MoveKind::arc) {
    const PlaneAxes pa = plane_axes(m.plane);
    if (pa.p == 0 || pa.q == 0) {  // X in the plane: its nearest point on 64 pieces of the arc
      const double a0 = std::atan2(m.start[pa.q] - m.center[pa.q], m.start[pa.p] - m.center[pa.p]);
      const double rs = std::hypot(m.start[pa.p] - m.center[pa.p], m.start[pa.q] - m.center[pa.q]);
      const double re = std::hypot(m.end[pa.p] - m.center[pa.p], m.end[pa.q] - m.center[pa.q]);
      for (int i = 1; i < 64; ++i) {
        const double t = i / 64.0, rr = rs + (re - rs) * t, a = a0 + m.sweep * t;
        r = std::min(r, std::fabs(pa.p == 0 ? m.center[0] + rr * std::cos(a) : m.center[0] + rr * std::sin(a)));
      }
    }
  }
  double rpm = 1000.0 * speed_ / (2 * std::numbers::pi * std::max(r, 0.5));
  if (max_spindle_ > 0) rpm = std::min(rpm, max_spindle_);
  if (rpm > limit * (1 + 1e-9)) warn_spindle_limit(rpm, 0);
}

}  // namespace ncurve::machine
