#include "motion/planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncurve::motion {

using machine::Move;
using machine::MoveKind;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();


// Time of a ramp phase, its speed and distance, for the S-curve: jerk up, constant acceleration, jerk down.
struct Phases {
  double t1 = 0, t2 = 0, a_peak = 0;  // jerk phase, constant phase, acceleration reached
};
Phases phases(double dv, double a, double j) {
  Phases p;
  if (j <= 0) {
    p.t2 = dv / a;
    p.a_peak = a;
  } else if (dv >= a * a / j) {
    p.t1 = a / j;
    p.t2 = dv / a - a / j;
    p.a_peak = a;
  } else {
    p.t1 = std::sqrt(dv / j);
    p.a_peak = j * p.t1;
  }
  return p;
}
}  // namespace

const char* to_string(Limit l) {
  switch (l) {
    case Limit::programmed: return "programmed";
    case Limit::max_cutting: return "max_cutting";
    case Limit::rapid: return "rapid";
    case Limit::arc: return "arc";
    case Limit::block_time: return "block_time";
  }
  return "?";
}

double change_time(double dv, double a, double j) {
  if (dv <= 0) return 0;
  if (!(a > 0) || std::isinf(a)) return 0;
  Phases p = phases(dv, a, j);
  return 2 * p.t1 + p.t2;
}

double change_distance(double v0, double v1, double a, double j) {
  return 0.5 * (v0 + v1) * change_time(std::fabs(v1 - v0), a, j);
}

double reachable(double v, double L, double a, double j) {
  if (!(a > 0) || std::isinf(a)) return kInf;
  double hi = std::sqrt(v * v + 2 * a * L);  // without jerk; jerk only lowers it
  if (j <= 0) return hi;
  double lo = v;
  for (int i = 0; i < 60 && hi - lo > 1e-9 * (1 + hi); ++i) {
    double mid = 0.5 * (lo + hi);
    (change_distance(v, mid, a, j) <= L ? lo : hi) = mid;
  }
  return lo;
}

double Ramp::speed(double tau) const {
  double dv = std::fabs(v1 - v0);
  if (dv == 0 || std::isinf(a)) return v1;
  double s = v1 > v0 ? 1 : -1;
  Phases p = phases(dv, a, j);
  double T = 2 * p.t1 + p.t2;
  tau = std::clamp(tau, 0.0, T);
  double gained;
  if (p.t1 == 0) gained = a * tau;
  else if (tau < p.t1) gained = 0.5 * j * tau * tau;
  else if (tau < p.t1 + p.t2) gained = 0.5 * j * p.t1 * p.t1 + p.a_peak * (tau - p.t1);
  else {
    double r = T - tau;
    gained = dv - 0.5 * j * r * r;
  }
  return v0 + s * gained;
}

double Ramp::distance(double tau) const {
  double dv = std::fabs(v1 - v0);
  if (dv == 0 || std::isinf(a)) return v1 * tau;
  double s = v1 > v0 ? 1 : -1;
  Phases p = phases(dv, a, j);
  double T = 2 * p.t1 + p.t2;
  tau = std::clamp(tau, 0.0, T);
  // distance gained over v0 * tau by the speed change
  double g;
  if (p.t1 == 0) g = 0.5 * a * tau * tau;
  else if (tau < p.t1) g = j * tau * tau * tau / 6;
  else {
    double g1 = j * p.t1 * p.t1 * p.t1 / 6, v1g = 0.5 * j * p.t1 * p.t1;
    double t2 = std::min(tau - p.t1, p.t2);
    g = g1 + v1g * t2 + 0.5 * p.a_peak * t2 * t2;
    if (tau > p.t1 + p.t2) {
      double r = tau - p.t1 - p.t2, vb = v1g + p.a_peak * p.t2;
      g += vb * r + 0.5 * p.a_peak * r * r - j * r * r * r / 6;
    }
  }
  return v0 * tau + s * g;
}

double Profile::distance(double tau) const {
  double tu = up.duration();
  if (tau <= tu) return up.distance(tau);
  double d = up.distance(tu);
  tau -= tu;
  if (tau <= cruise) return d + v_peak * tau;
  d += v_peak * cruise;
  return d + down.distance(tau - cruise);
}

Profile plan_profile(double L, double v_in, double v_cap, double v_out, double a, double j) {
  Profile p;
  if (!(a > 0) || std::isinf(a)) {  // unlimited acceleration: the whole block at the cap
    p.v_peak = v_cap;
    p.up = {v_cap, v_cap, kInf, 0};
    p.down = {v_cap, v_cap, kInf, 0};
    p.cruise = v_cap > 0 ? L / v_cap : 0;
    return p;
  }
  v_in = std::min(v_in, v_cap);
  v_out = std::min(v_out, v_cap);
  double d = change_distance(v_in, v_cap, a, j) + change_distance(v_cap, v_out, a, j);
  double peak = v_cap;
  if (d > L) {  // no cruise: the highest peak whose two ramps fit in L
    double lo = std::max(v_in, v_out), hi = v_cap;
    for (int i = 0; i < 60 && hi - lo > 1e-12 * (1 + hi); ++i) {
      double mid = 0.5 * (lo + hi);
      (change_distance(v_in, mid, a, j) + change_distance(mid, v_out, a, j) <= L ? lo : hi) = mid;
    }
    peak = lo;
    d = change_distance(v_in, peak, a, j) + change_distance(peak, v_out, a, j);
  }
  p.v_peak = peak;
  p.up = {v_in, peak, a, j};
  p.down = {peak, v_out, a, j};
  p.cruise = peak > 0 ? std::max(0.0, L - d) / peak : 0;
  return p;
}

Planner::Planner(const machine::MachineProfile& profile, Callback on_block)
    : profile_(profile), on_block_(std::move(on_block)) {}

void Planner::on_move(const Move& m) {
  carry_compute_ += m.macro_statements * profile_.motion.macro_time + m.nc_blocks * profile_.motion.block_time;
  totals_.macro_statements += m.macro_statements;
  totals_.nc_blocks += m.nc_blocks;
  if (plans(m)) {
    add(m);
  } else if (!m.is_motion()) {
    // Events wait for the motion before them to end (M codes wait for FIN, G04 for in-position).
    double dwell = m.kind == MoveKind::dwell ? m.seconds : 0;
    if (!pending_.empty()) {
      pending_.back().stop_after = true;
      pending_.back().t.dwell += dwell;
    } else {
      clock_ += dwell;
      totals_.dwell_seconds += dwell;
    }
  }
  while (finalize_front()) {
  }
}

bool Planner::plans(const Move& m) {
  if (!m.is_motion()) return false;
  if (m.length > 0) return true;
  bool rotary = false;
  for (int a = 3; a < machine::kAxes; ++a) rotary |= m.end[a] != m.start[a];
  return rotary;
}

void Planner::add(const Move& m) {
  const machine::MotionSettings& ms = profile_.motion;
  Pending p;
  p.t.move = m;
  p.compute = carry_compute_;
  carry_compute_ = 0;
  p.exact_stop = m.exact_stop;
  const bool before = ms.acc_dec == machine::AccDec::before;

  double d[machine::kAxes];
  double all = 0;
  for (int a = 0; a < machine::kAxes; ++a) {
    d[a] = m.end[a] - m.start[a];
    all += d[a] * d[a];
  }
  all = std::sqrt(all);
  double L = m.kind == MoveKind::arc || m.length > 0 ? m.length : all;
  p.t.length = L;

  double programmed;
  Limit limit = Limit::programmed;
  double accel = kInf;
  if (m.kind == MoveKind::arc) {
    const auto [pa, qa, na, ip, iq] = machine::plane_axes(m.plane);
    double rp = m.start[pa] - m.center[pa], rq = m.start[qa] - m.center[qa];
    double R = std::hypot(rp, rq);
    double sgn = m.sweep >= 0 ? 1 : -1;
    double arc_len = R * std::fabs(m.sweep);
    double dn = m.end[na] - m.start[na];
    for (int end = 0; end < 2; ++end) {
      const auto& pt = end ? m.end : m.start;
      double ep = pt[pa] - m.center[pa], eq = pt[qa] - m.center[qa];
      double r = std::hypot(ep, eq);
      double* dir = end ? p.end_dir : p.start_dir;
      double tp = r > 0 ? -sgn * eq / r : 0, tq = r > 0 ? sgn * ep / r : 0;
      double len = std::hypot(arc_len, dn);
      dir[pa] = len > 0 ? tp * arc_len / len : 0;
      dir[qa] = len > 0 ? tq * arc_len / len : 0;
      dir[na] = len > 0 ? dn / len : 0;
    }
    accel = std::min(ms.acceleration[pa], ms.acceleration[qa]);
    programmed = m.seconds > 0 ? m.length / m.seconds : m.feed / 60;
    p.cap = programmed;
    double clamp = std::sqrt(accel * R);  // centripetal acceleration within the slower axis's limit
    if (ms.jerk > 0) clamp = std::min(clamp, std::cbrt(ms.jerk * R * R));  // its turning rate v^3/R^2 within the jerk
    if (before && clamp < p.cap) p.cap = clamp, limit = Limit::arc;
  } else {
    for (int a = 0; a < 3; ++a) p.start_dir[a] = p.end_dir[a] = all > 0 ? d[a] / all : 0;
    for (int a = 0; a < machine::kAxes; ++a) {
      double u = all > 0 ? std::fabs(d[a]) / all : 0;
      if (u > 1e-12) accel = std::min(accel, ms.acceleration[a] / u);
    }
    if (m.kind == MoveKind::rapid) {
      programmed = kInf;
      for (int a = 0; a < machine::kAxes; ++a) {
        double u = all > 0 ? std::fabs(d[a]) / all : 0;
        if (u > 1e-12 && profile_.rapid_rate[a] > 0) programmed = std::min(programmed, profile_.rapid_rate[a] / 60 / u);
      }
      if (std::isinf(programmed)) programmed = profile_.rapid_rate[0] / 60;
      limit = Limit::rapid;
      p.stop_after = true;  // rapids end with an in-position check
    } else {
      programmed = m.seconds > 0 && m.length > 0 ? m.length / m.seconds : m.feed / 60;
    }
    p.cap = programmed;
  }
  if (m.kind != MoveKind::rapid && profile_.max_cutting_feed / 60 < p.cap)
    p.cap = profile_.max_cutting_feed / 60, limit = Limit::max_cutting;
  if (ms.block_time > 0 && L / ms.block_time < p.cap) {
    p.cap = L / ms.block_time;
    limit = Limit::block_time;
    p.t.starved = true;
  }
  p.t.programmed = programmed * 60;
  p.t.cap = p.cap * 60;
  p.t.limit = limit;
  p.accel = before ? accel : kInf;

  // The corner with the previous block: each axis may change speed by corner_speed at once.
  p.junction = p.cap;
  if (!pending_.empty() && before) {
    const Pending& prev = pending_.back();
    if (prev.stop_after || prev.exact_stop || m.kind == MoveKind::rapid) {
      p.junction = 0;
    } else {
      for (int a = 0; a < 3; ++a) {
        double du = std::fabs(p.start_dir[a] - prev.end_dir[a]);
        if (du > 1e-9 && ms.corner_speed[a] > 0) p.junction = std::min(p.junction, ms.corner_speed[a] / 60 / du);
      }
      p.junction = std::min(p.junction, prev.cap);
    }
  } else if (before && (v_last_ == 0 || m.kind == MoveKind::rapid)) {
    p.junction = 0;
  }
  if (p.exact_stop) p.stop_after = true;
  // Look-ahead off (G05.1 Q0, G08 P0, G05 P0): the planner cannot see the next block, so the feed
  // comes down to zero at this block's end (no in-position check, unlike G61/G09).
  if (!m.lookahead && before) {
    p.stop_after = true;
    ++totals_.without_lookahead;
  }
  pending_.push_back(std::move(p));
}

double Planner::start_of(std::int64_t index) const {
  if (index < 0) return 0;
  std::int64_t first = next_index_ - static_cast<std::int64_t>(starts_.size());
  if (index < first) return 0;
  return starts_[static_cast<std::size_t>(index - first)];
}

// The block can be read once the block look_ahead places before it has started (the buffer is full
// until then), and only after the statements and blocks before it have been processed. Block k of
// the pending ones is read look_ahead blocks after a final one, or (k = look_ahead) after the front,
// whose start the caller gives. Without a buffer (look_ahead 0) the control reads and computes a
// block only once the one before it has ended.
double Planner::ready_of(std::size_t k, double front_start) {
  Pending& p = pending_[k];
  if (p.ready_known) return p.ready;
  double previous = k == 0 ? last_ready_ : ready_of(k - 1, front_start);
  double buffer = clock_;
  if (profile_.motion.look_ahead > 0) {
    std::int64_t reader = next_index_ + static_cast<std::int64_t>(k) - profile_.motion.look_ahead;
    buffer = reader == next_index_ ? front_start : start_of(reader);
  }
  p.ready = std::max(previous, buffer) + p.compute;
  p.ready_known = true;
  return p.ready;
}

bool Planner::finalize_front() {
  if (pending_.empty()) return false;
  const machine::MotionSettings& ms = profile_.motion;
  const bool before = ms.acc_dec == machine::AccDec::before;
  Pending& b = pending_.front();
  const double ready = ready_of(0, 0);
  const double start = std::max(clock_, ready);
  const double wait = start - clock_ > 1e-12 ? start - clock_ : 0;

  double v_in = wait > 0 ? 0 : v_last_;
  Profile prof;
  if (before) {
    v_in = std::min(v_in, b.cap);
    // The blocks the planner knows at time t: read by then, within the look-ahead. It replans as
    // blocks arrive, so what counts is what it knows when this block must begin to brake.
    bool need_more = false;
    auto horizon = [&](double t) {
      std::size_t h = 0;
      if (b.stop_after) return h;
      for (std::size_t k = 1; k <= static_cast<std::size_t>(ms.look_ahead); ++k) {
        if (k >= pending_.size()) {
          need_more = !ended_;
          break;
        }
        if (ready_of(k, start) > t + 1e-12) break;
        h = k;
        if (pending_[k].stop_after) break;
      }
      return h;
    };
    auto plan_with = [&](std::size_t h) {
      double v = 0;  // the speed at the end of block k, going back from the last known block
      for (std::size_t k = h; k >= 1; --k) {
        const Pending& p = pending_[k];
        v = std::min({p.junction, p.cap, reachable(v, p.t.length, p.accel, ms.jerk)});
      }
      double v_out = h >= 1 ? std::min({v, b.cap, reachable(v_in, b.t.length, b.accel, ms.jerk)}) : 0;
      return plan_profile(b.t.length, v_in, b.cap, v_out, b.accel, ms.jerk);
    };
    std::size_t h = horizon(start);
    if (need_more) return false;
    prof = plan_with(h);
    for (int pass = 0; pass < 8; ++pass) {
      std::size_t later = horizon(start + prof.up.duration() + prof.cruise);
      if (need_more) return false;
      if (later == h) break;
      h = later;
      prof = plan_with(h);
    }
  } else {
    prof = plan_profile(b.t.length, v_in, b.cap, b.cap, b.accel, ms.jerk);
  }
  double seconds = prof.seconds();

  // Settling at a stop: the in-position check after an exact stop or a rapid, or the tail of the
  // acc/dec filter (after interpolation).
  double settle = 0;
  if (b.stop_after && (b.exact_stop || b.t.move.kind == MoveKind::rapid)) {
    double T = 0, kv = kInf;
    for (int a = 0; a < machine::kAxes; ++a)
      if (b.t.move.end[a] != b.t.move.start[a]) {
        T = std::max(T, ms.time_constant[a]);
        kv = std::min(kv, profile_.servo.kv[a]);
      }
    if (!before && T > 0) {
      if (ms.filter == machine::Filter::linear) settle = T;
      else settle = std::max(0.0, T * std::log(prof.v_peak * T / ms.in_position));
    } else if (before && std::isfinite(kv)) {
      double lag = b.accel * (1 - profile_.servo.feed_forward) / (kv * kv);  // following error left at the stop
      if (std::isfinite(lag) && lag > ms.in_position) settle = std::log(lag / ms.in_position) / kv;
    }
  }

  BlockTime& t = b.t;
  t.profile = prof;
  t.v_in = prof.up.v0 * 60;
  t.v_peak = prof.v_peak * 60;
  t.v_out = prof.down.v1 * 60;
  t.start = start;
  t.seconds = seconds;
  t.wait = wait;
  t.settle = settle;

  totals_.motions++;
  totals_.motion_seconds += seconds;
  totals_.wait_seconds += wait;
  totals_.settle_seconds += settle;
  totals_.dwell_seconds += t.dwell;
  if (wait > 0) totals_.waits++;
  if (t.starved) totals_.starved++;
  if (prof.down.v1 == 0) totals_.stops++;
  totals_.programmed_seconds += t.programmed > 0 ? t.length / t.programmed * 60 : 0;
  if (t.move.kind != MoveKind::rapid) {
    totals_.feed_length += t.length;
    totals_.feed_motion_seconds += seconds;
  }

  clock_ = start + seconds + settle + t.dwell;
  last_ready_ = ready;
  v_last_ = b.stop_after ? 0 : prof.down.v1;
  starts_.push_back(start);
  while (starts_.size() > static_cast<std::size_t>(ms.look_ahead)) starts_.pop_front();
  ++next_index_;
  if (on_block_) on_block_(t);
  pending_.pop_front();
  return true;
}

void Planner::finish() {
  ended_ = true;
  while (finalize_front()) {
  }
  const machine::MotionSettings& ms = profile_.motion;
  double tail = 0;  // the acc/dec filter's lag at the very end
  if (ms.acc_dec == machine::AccDec::after && totals_.motions > 0) {
    double T = *std::max_element(ms.time_constant.begin(), ms.time_constant.end());
    if (ms.filter == machine::Filter::linear) tail = T;
    else if (T > 0 && v_last_ > 0) tail = std::max(0.0, T * std::log(v_last_ * T / ms.in_position));
  }
  totals_.settle_seconds += tail;
  totals_.seconds = clock_ + tail;
}

}  // namespace ncurve::motion
