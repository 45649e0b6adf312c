#include "motion/circle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "motion/planner.hpp"
#include "motion/servo.hpp"

namespace ncurve::motion {

namespace {
constexpr double kPi = std::numbers::pi;

double deg(double rad) {
  double d = rad * 180 / kPi;
  return d < 0 ? d + 360 : d;
}
}  // namespace

double axis_delay(const machine::MachineProfile& profile, int axis) {
  double d = (1 - profile.servo.feed_forward) / profile.servo.kv[axis];
  if (profile.motion.acc_dec == machine::AccDec::after) {
    double T = profile.motion.time_constant[axis];
    d += profile.motion.filter == machine::Filter::linear ? T / 2 : T;
  }
  return d;
}

CirclePlane circle_plane(const machine::MachineProfile& profile) {
  if (profile.lathe()) return {2, 0, 'Z', 'X'};
  return {};
}

bool axes_alike(const machine::MachineProfile& profile, int p, int q) {
  if (profile.servo.kv[p] != profile.servo.kv[q]) return false;
  return profile.motion.acc_dec == machine::AccDec::before ||
         profile.motion.time_constant[p] == profile.motion.time_constant[q];
}

CircleResult circle_test(const machine::MachineProfile& profile, const CircleTest& test) {
  CircleResult r;
  const CirclePlane plane = circle_plane(profile);
  const int P = plane.p, Q = plane.q;
  const double R = test.radius;
  const double sign = test.clockwise ? -1 : 1;

  // the circle as the interpreter would give it: full turns from R along +p
  std::vector<machine::Move> moves;
  for (int k = 0; k < test.turns; ++k) {
    machine::Move m;
    m.kind = machine::MoveKind::arc;
    m.plane = profile.lathe() ? 18 : 17;
    m.clockwise = test.clockwise;
    m.start[P] = m.end[P] = R;
    m.sweep = sign * 2 * kPi;
    m.length = 2 * kPi * R;
    m.feed = test.feed;
    m.seconds = m.length / (test.feed / 60);
    m.nc_blocks = 1;
    m.line = static_cast<std::uint32_t>(k + 1);
    moves.push_back(m);
  }
  // the feed the control allows on the arc, and how long the run takes, before simulating it
  double end = 0;
  {
    Planner plan(profile, [&](const BlockTime& b) {
      r.feed_reached = b.cap;
      end = b.start + b.seconds + b.settle;
    });
    for (const auto& m : moves) plan.on_move(m);
    plan.finish();
  }
  if (!(end <= test.most_seconds) || !(end / profile.servo.period <= test.most_ticks))
    throw std::runtime_error(fmt::format("{} turns of R {:g} mm at {:g} mm/min take {:.3g} s, more than the {:.4g} s "
                                         "simulated at most: raise the feed or lower the radius (the bound: {:g} s, "
                                         "or {:.3g} servo periods of {:g} ms)",
                                         test.turns, R, r.feed_reached, end,
                                         std::min(test.most_seconds, test.most_ticks * profile.servo.period),
                                         test.most_seconds, test.most_ticks, profile.servo.period * 1000));
  if (r.feed_reached >= test.feed * (1 - 1e-9)) r.feed_reached = test.feed;  // length / time rounds
  const double V = r.feed_reached / 60, w = V / R;

  const int measured = test.turns / 2;
  double min_dev = 1e300, max_dev = -1e300, sum = 0;
  std::size_t n = 0;
  ServoSim sim(profile, [&](const Tick& t) {
    if (!t.block || t.block->move.line != static_cast<std::uint32_t>(measured + 1)) return;
    double rad = std::hypot(t.actual[P], t.actual[Q]) - R;
    double ang = deg(std::atan2(t.actual[Q], t.actual[P]));
    r.polar.emplace_back(ang, rad);
    sum += rad;
    ++n;
    max_dev = std::max(max_dev, rad);
    if (rad < min_dev) {
      min_dev = rad;
      r.max_deviation_angle = ang;
    }
  });
  Planner planner(profile, [&](const BlockTime& b) { sim.on_block(b); });
  for (const auto& m : moves) planner.on_move(m);
  planner.finish();
  sim.finish(1.0);
  if (n > 0) {
    r.radius_reduction = -sum / n;
    r.roundness = max_dev - min_dev;
  }
  r.max_contour_error = sim.stats().max_error;
  r.angle_meaningful = !axes_alike(profile, P, Q);

  // closed forms
  double terms = 0;
  for (int a : {P, Q}) {
    double t = (1 - profile.servo.feed_forward * profile.servo.feed_forward) / (profile.servo.kv[a] * profile.servo.kv[a]);
    if (profile.motion.acc_dec == machine::AccDec::after) {
      double T = profile.motion.time_constant[a];
      t += profile.motion.filter == machine::Filter::linear ? T * T / 12 : T * T;
    }
    terms += t / 2;
  }
  r.fanuc_radius_reduction = V * V / (2 * R) * terms;
  r.first_order_roundness = V * std::fabs(axis_delay(profile, P) - axis_delay(profile, Q));

  const auto gp = axis_response(profile, P, w), gq = axis_response(profile, Q, w);
  double hmin = 1e300, hmax = -1e300, hsum = 0;
  const int samples = 7200;
  for (int i = 0; i < samples; ++i) {
    double th = 2 * kPi * i / samples;
    std::complex<double> e = std::polar(1.0, th);
    double x = R * (gp * e).real(), y = R * sign * (gq * std::complex<double>(0, -1) * e).real();
    double dev = std::hypot(x, y) - R;
    hsum += dev;
    hmax = std::max(hmax, dev);
    if (dev < hmin) {
      hmin = dev;
      r.harmonic_angle = deg(std::atan2(y, x));
    }
  }
  r.harmonic_radius_reduction = -hsum / samples;
  r.harmonic_roundness = hmax - hmin;

  const double ap = profile.motion.acceleration[P], aq = profile.motion.acceleration[Q];
  for (int i = 0; i <= 9000; ++i) {
    double a = i * kPi / 2 / 9000;
    double e = V * V / 2 * std::cos(a) * std::sin(a) * (std::cos(a) / aq + std::sin(a) / ap);
    if (e > r.seed002_error) {
      r.seed002_error = e;
      r.seed002_angle = a * 180 / kPi;
    }
  }
  return r;
}

}  // namespace ncurve::motion
