#include "motion/servo.hpp"

#include <algorithm>
#include <cmath>

namespace ncurve::motion {

using machine::MoveKind;

namespace {

double norm(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

Point xyz(const machine::AxisVector& v) { return {v[0], v[1], v[2]}; }
}  // namespace

std::complex<double> axis_response(const machine::MachineProfile& profile, int axis, double w) {
  using C = std::complex<double>;
  const C jw(0, w);
  C h = 1;
  const double T = profile.motion.time_constant[axis];
  if (profile.motion.acc_dec == machine::AccDec::after && T > 0 && w > 0) {
    if (profile.motion.filter == machine::Filter::linear) h = (1.0 - std::exp(-jw * T)) / (jw * T);
    else h = 1.0 / (1.0 + jw * T);
  }
  const double kv = profile.servo.kv[axis], ff = profile.servo.feed_forward;
  return h * (kv + ff * jw) / (jw + kv);
}

ServoSim::ServoSim(const machine::MachineProfile& profile, Callback on_tick)
    : profile_(profile), on_tick_(std::move(on_tick)) {
  const double dt = profile_.servo.period;
  for (int a = 0; a < 3; ++a) {
    double T = profile_.motion.acc_dec == machine::AccDec::after ? profile_.motion.time_constant[a] : 0;
    taps_[a] = profile_.motion.filter == machine::Filter::linear ? std::max(1, static_cast<int>(std::lround(T / dt))) : 1;
  }
}

Point ServoSim::path_point(const Segment& seg, double s) const {
  const machine::Move& m = seg.block.move;
  const double L = seg.block.length;
  const double f = L > 0 ? std::clamp(s / L, 0.0, 1.0) : 1.0;
  if (m.kind != MoveKind::arc) {
    Point p;
    for (int a = 0; a < 3; ++a) p[a] = m.start[a] + f * (m.end[a] - m.start[a]);
    return p;
  }
  const auto [pa, qa, na, ip, iq] = machine::plane_axes(m.plane);
  double rp = m.start[pa] - m.center[pa], rq = m.start[qa] - m.center[qa];
  double R = std::hypot(rp, rq), a0 = std::atan2(rq, rp), ang = a0 + m.sweep * f;
  Point p;
  p[pa] = m.center[pa] + R * std::cos(ang);
  p[qa] = m.center[qa] + R * std::sin(ang);
  p[na] = m.start[na] + f * (m.end[na] - m.start[na]);
  return p;
}

double ServoSim::distance_to(const Segment& seg, const Point& p) const {
  const machine::Move& m = seg.block.move;
  if (m.kind != MoveKind::arc) {
    Point a = xyz(m.start), b = xyz(m.end);
    double d[3], w[3], dd = 0, t = 0;
    for (int i = 0; i < 3; ++i) {
      d[i] = b[i] - a[i];
      w[i] = p[i] - a[i];
      dd += d[i] * d[i];
      t += d[i] * w[i];
    }
    t = dd > 0 ? std::clamp(t / dd, 0.0, 1.0) : 0;
    return norm(p, {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]});
  }
  const auto [pa, qa, na, ip, iq] = machine::plane_axes(m.plane);
  double rp = m.start[pa] - m.center[pa], rq = m.start[qa] - m.center[qa];
  double a0 = std::atan2(rq, rp);
  double pp = p[pa] - m.center[pa], pq = p[qa] - m.center[qa];
  double rel = std::atan2(pq, pp) - a0;  // angle from the start, in the sweep's direction
  const double two_pi = 2 * std::acos(-1.0);
  if (m.sweep >= 0) rel = std::fmod(std::fmod(rel, two_pi) + two_pi, two_pi);
  else rel = -std::fmod(std::fmod(-rel, two_pi) + two_pi, two_pi);
  double f = m.sweep != 0 ? rel / m.sweep : 0;
  if (f < 0 || f > 1) return std::min(norm(p, xyz(m.start)), norm(p, xyz(m.end)));
  return norm(p, path_point(seg, f * seg.block.length));
}

void ServoSim::step_to(double t_end, const Segment* seg) {
  const double dt = profile_.servo.period;
  const bool exponential = profile_.motion.acc_dec == machine::AccDec::after &&
                           profile_.motion.filter == machine::Filter::exponential;
  while ((k_ + 1) * dt <= t_end + 1e-12) {
    ++k_;
    t_ = k_ * dt;
    Point cmd = held_;
    double s_cmd = path_length_;
    if (seg && t_ >= seg->block.start) {
      double s = seg->block.profile.distance(t_ - seg->block.start);
      cmd = path_point(*seg, s);
      s_cmd = seg->s0 + std::min(s, seg->block.length);
    }
    Tick tick;
    tick.t = t_;
    tick.command = cmd;
    tick.block = seg ? &seg->block : nullptr;
    for (int a = 0; a < 3; ++a) {
      double c;
      if (exponential) {
        double T = profile_.motion.time_constant[a];
        c = T > 0 ? filtered_[a] + (cmd[a] - filtered_[a]) * (1 - std::exp(-dt / T)) : cmd[a];
      } else {
        fir_[a].push_back(cmd[a]);
        fir_sum_[a] += cmd[a];
        if (static_cast<int>(fir_[a].size()) > taps_[a]) {
          fir_sum_[a] -= fir_[a].front();
          fir_[a].pop_front();
        }
        c = fir_sum_[a] / fir_[a].size();
      }
      filtered_[a] = c;
      const double kv = profile_.servo.kv[a];
      const double rate = (c - previous_[a]) / dt;
      const double steady = (1 - profile_.servo.feed_forward) * rate / kv;
      error_[a] = steady + (error_[a] - steady) * std::exp(-kv * dt);
      previous_[a] = c;
      tick.actual[a] = c - error_[a];
    }
    // contour error: the nearest point of the path behind the command, within the lag
    double lag = norm(tick.actual, cmd);
    double best = lag;
    for (auto it = window_.rbegin(); it != window_.rend(); ++it) {
      if (it->s0 > s_cmd + 1e-9) continue;
      if (it->s0 + it->block.length < s_cmd - lag - 1e-9) break;
      best = std::min(best, distance_to(*it, tick.actual));
    }
    tick.contour_error = best;
    const BlockTime* owner = seg ? &seg->block : last_ ? &*last_ : nullptr;
    if (owner) {
      stats_.add(tick, owner);
      (owner->move.kind == MoveKind::rapid ? rapids_ : cutting_).add(tick, owner);
    }
    if (on_tick_) on_tick_(tick);
  }
}

void ServoSim::on_block(const BlockTime& b) {
  if (!started_) {
    held_ = xyz(b.move.start);
    for (int a = 0; a < 3; ++a) {
      filtered_[a] = previous_[a] = held_[a];
      for (int k = 0; k < taps_[a]; ++k) fir_[a].push_back(held_[a]);
      fir_sum_[a] = held_[a] * taps_[a];
    }
    started_ = true;
  }
  step_to(b.start, nullptr);
  window_.push_back({b, path_length_});
  step_to(b.start + b.seconds, &window_.back());
  last_ = b;
  held_ = xyz(b.move.end);
  path_length_ += b.length;
  // keep what the actual position may still be near: a few following-error lengths back
  double keep = 1.0;
  for (int a = 0; a < 3; ++a) keep = std::max(keep, 4 * std::fabs(error_[a]) + 4 * std::fabs(filtered_[a] - held_[a]));
  while (window_.size() > 2 && window_.front().s0 + window_.front().block.length < path_length_ - keep)
    window_.pop_front();
}

void ServoSim::finish(double settle_seconds) {
  step_to(t_ + settle_seconds, nullptr);
  for (ContourStats* s : {&stats_, &cutting_, &rapids_}) s->close();
}

void ContourStats::add(const Tick& t, const BlockTime* block) {
  ++ticks;
  sum_sq += t.contour_error * t.contour_error;
  if (t.contour_error > max_error || ticks == 1) {
    max_error = t.contour_error;
    max_t = t.t;
    max_actual = t.actual;
    max_line = block ? block->move.line : 0;
    max_file = block ? block->move.file : nullptr;
  }
}

}  // namespace ncurve::motion
