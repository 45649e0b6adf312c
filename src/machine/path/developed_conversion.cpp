#include "machine/path/developed_conversion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "machine/path/developed_path.hpp"

namespace ncurve::machine {

namespace {
constexpr double kDeg = 180 / std::numbers::pi;
const char* const kAxisLetters = "XYZABC";
}  // namespace

void DevelopedConversion::start(const DevelopedMode& mode, const AxisVector& machine) {
  on_ = true;
  mode_ = mode;
  machine_ = machine;
  sign_ = mode.polar && machine[mode.linear] < 0 ? -1 : 1;
  angle_ = 0;
  warned_line_ = 0;
}

// A move of the programmed plane as the machine makes it: the linear and rotary axes moving together
// by pieces, each within the path tolerance of the contour.
void DevelopedConversion::convert(const Move& m) {
  const DevelopedMode& d = mode_;
  if (!m.is_motion()) {
    Move at = m;
    at.start = at.end = machine_;
    return next_->on_move(at);
  }
  const PlanePath path = PlanePath::of(m, d.p, d.q);
  auto along = [&](double t) {  // every axis but the plane's, linearly; the plane's on the contour
    AxisVector v{};
    for (int a = 0; a < kAxes; ++a) v[a] = t >= 1 ? m.end[a] : m.start[a] + t * (m.end[a] - m.start[a]);
    const V2 at = path.at(t);
    v[d.p] = at.x;
    v[d.q] = at.y;
    return v;
  };
  std::vector<double> ts;
  std::vector<AxisVector> points;
  if (d.polar) {
    for (const PolarPoint& pp : polar_points(path, tolerance_, sign_, angle_)) {
      AxisVector v = along(pp.t);
      v[d.linear] = pp.linear;
      v[d.rotary] = d.angle0 + pp.angle * kDeg;
      v[d.slot] = d.held;
      ts.push_back(pp.t);
      points.push_back(v);
    }
  } else {
    for (double t : chord_steps(path, tolerance_)) {
      AxisVector v = along(t);
      v[d.rotary] = v[d.slot] / d.radius * kDeg;
      v[d.slot] = d.spare >= 0 ? v[d.spare] : d.held;
      if (d.spare >= 0) v[d.spare] = 0;
      ts.push_back(t);
      points.push_back(v);
    }
  }
  AxisVector programmed_end = m.programmed_end;
  if (m.compensated) {  // the programmed end as the machine's axes, on the side the tool is
    const V2 at{m.programmed_end[d.p], m.programmed_end[d.q]};
    programmed_end = m.programmed_end;
    if (d.polar) {
      const double r = std::hypot(at.x, at.y);
      double a = r > 0 ? std::atan2(at.y, at.x) + (sign_ < 0 ? std::numbers::pi : 0.0) : angle_;
      a = angle_ + std::remainder(a - angle_, 2 * std::numbers::pi);
      programmed_end[d.linear] = sign_ * r;
      programmed_end[d.rotary] = d.angle0 + a * kDeg;
      programmed_end[d.slot] = d.held;
    } else {
      programmed_end[d.rotary] = programmed_end[d.slot] / d.radius * kDeg;
      programmed_end[d.slot] = d.spare >= 0 ? programmed_end[d.spare] : d.held;
      if (d.spare >= 0) programmed_end[d.spare] = 0;
    }
  }
  for (std::size_t i = 1; i < points.size(); ++i) {
    Move piece = m;
    if (piece.kind == MoveKind::arc) piece.kind = MoveKind::line;
    piece.start = machine_;
    piece.end = points[i];
    piece.center = {};
    piece.sweep = 0;
    piece.clockwise = false;
    const double share = ts[i] - ts[i - 1];
    piece.length = m.length * share;
    piece.seconds = m.seconds * share;
    piece.programmed_end = programmed_end;
    if (i > 1) piece.macro_statements = piece.nc_blocks = 0;
    if (i + 1 < points.size()) piece.exact_stop = false;
    if (d.polar) warn_polar_speed(piece, piece.end[d.rotary] - piece.start[d.rotary], piece.length,
                                  std::min(std::fabs(piece.start[d.linear]), std::fabs(piece.end[d.linear])));
    machine_ = piece.end;
    next_->on_move(piece);
  }
}

// The rotary axis turns faster the nearer the path runs to the centre: the manual's limit is
// F < L * R * pi / 180 (L: the nearest distance to the centre, R: the rotary axis's maximum cutting
// feedrate in deg/min). Warned once a block.
void DevelopedConversion::warn_polar_speed(const Move& m, double degrees, double length, double radius) {
  if (m.feed_per_rev || m.feed <= 0 || length <= 0 || warned_line_ == m.line) return;
  const double rate = std::fabs(degrees) / length * m.feed;  // deg/min
  if (rate <= max_rotary_feed_) return;
  warned_line_ = m.line;
  warn_(m, "NC2060",
        fmt::format("polar coordinate interpolation: the path passes {:.4f} mm from the centre, where {} turns at "
                    "{:.0f} deg/min at F{:g}, above the maximum cutting feedrate {:g}; the manual asks for F < L x R "
                    "x pi / 180",
                    radius, kAxisLetters[mode_.rotary], rate, m.feed, max_rotary_feed_));
}

}  // namespace ncurve::machine
