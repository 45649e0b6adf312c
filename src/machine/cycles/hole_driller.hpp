// The drilling cycles' motions (hole_cycles.hpp) for any CycleOutput type: the interpreter gives
// its own final one, whose calls are then direct. FANUC 0i-MF / 30i-B operator's manual, "Canned
// cycle for drilling", "Rigid tapping"; 0i-TF / 30i-B lathe, "Canned cycle for drilling".
#pragma once
#include <stdexcept>
#include <string>

#include "machine/cycles/hole_cycles.hpp"

namespace ncurve::machine::drill {

namespace detail {
static_assert(kAxes == 6, "X Y Z A B C: the rotary axes are 3..5");

// The shift of G76 and G87 (away from the tool tip after the oriented stop), by No.5101#4 RD1 and
// #5 RD2 and the drilling axis: in G17 (Z drills) +X, -X, +Y, -Y; G18 (Y) +Z, -Z, +X, -X; G19 (X)
// +Y, -Y, +Z, -Z.
struct Shift {
  int axis;
  double sign;
};
inline Shift shift_direction(int bits, int drilling_axis) {
  static constexpr int first[3] = {1, 2, 0};  // by drilling axis X, Y, Z: the first axis of its plane's column
  static constexpr int second[3] = {2, 0, 1};
  return {bits & 2 ? second[drilling_axis] : first[drilling_axis], bits & 1 ? -1.0 : 1.0};
}

template <class Out>
class Driller {
public:
  Driller(const Hole& h, const Parameters& p, Out& out) : h_(h), p_(p), out_(out) {}

  // to the hole at the current level
  void position() {
    at_ = out_.position();
    AxisVector to = h_.at;
    to[h_.axis] = at_[h_.axis];
    if (to == at_) return;
    out_.rapid(to);
    if (to[3] != at_[3] || to[4] != at_[4] || to[5] != at_[5]) at_ = out_.position();  // A B C may roll over
    else at_ = to;
  }
  // along the drilling axis to `level`, unless the tool is at it
  void rapid(double level) { move(level, false); }
  void feed(double level) { move(level, true); }
  void dwell() { out_.dwell(h_.p); }
  void dwell_if_any() {
    if (h_.p > 0) out_.dwell(h_.p);
  }
  void spindle(int m) { out_.spindle(m); }

  // Cuts of q from R to the bottom, each followed by a rapid back by d (out to R first with
  // out_to_r: G83's peck, down again to d short of the last depth).
  void peck_to_bottom(double q, double d, bool out_to_r) {
    if (!(q > 0)) return feed(h_.z);
    const double dir = h_.into();
    double depth = h_.r;  // reached so far
    for (;;) {
      double next = depth + dir * q;
      if ((next - h_.z) * dir >= 0) next = h_.z;
      feed(next);
      depth = next;
      if (depth == h_.z) return;
      if (out_to_r) rapid(h_.r);
      rapid(depth - dir * d);
    }
  }

  void mill_cycle();
  void boring();
  void tapping();
  void lathe_cycle();

private:
  void move(double level, bool fed) {
    if (at_[h_.axis] == level) return;
    at_[h_.axis] = level;
    if (fed) out_.feed(at_);
    else out_.rapid(at_);
  }

  const Hole& h_;
  const Parameters& p_;
  Out& out_;
  AxisVector at_;  // where the tool is (position() sets it): a move along X, Y, Z ends at its target
};

template <class Out>
void Driller<Out>::mill_cycle() {
  switch (h_.code) {
    case 76: case 87: case 88: return boring();
    case 84: case 74: return tapping();
    default: break;
  }
  rapid(h_.r);
  switch (h_.code) {
    case 81:
      feed(h_.z);
      break;
    case 82:
      feed(h_.z);
      dwell();
      break;
    case 73: case 83:  // G73: back by d to break the chip; G83: out to R, then down to d short of the last depth
      peck_to_bottom(h_.q, h_.code == 73 ? p_.peck_retract : p_.peck_clearance, h_.code == 83);
      break;
    case 85:
      feed(h_.z);
      feed(h_.r);
      break;
    case 89:
      feed(h_.z);
      dwell();
      feed(h_.r);
      break;
    case 86:  // the spindle stops at the bottom and starts again at the return level
      feed(h_.z);
      spindle(5);
      rapid(h_.back());
      spindle(3);
      return;
    default:
      throw std::invalid_argument("no drilling cycle G" + std::to_string(h_.code));
  }
  rapid(h_.back());
}

template <class Out>
void Driller<Out>::boring() {
  const Shift s = shift_direction(p_.drilling.shift_direction, h_.axis);
  auto shift = [&](double away) {  // rapid by Q: +1 away from the tool tip, -1 back
    AxisVector t = at_;
    t[s.axis] += away * s.sign * h_.q;
    if (t == at_) return;
    at_ = t;
    out_.rapid(at_);
  };
  switch (h_.code) {
    case 76:  // bore to Z, stop the spindle oriented, move the tip off the wall, rapid out
      rapid(h_.r);
      feed(h_.z);
      dwell_if_any();
      spindle(19);
      shift(1);
      rapid(h_.back());
      shift(-1);
      spindle(3);
      break;
    case 87:  // oriented and shifted, down through the hole to R (the bottom), bore upwards to Z
      spindle(19);
      shift(1);
      rapid(h_.r);
      shift(-1);
      spindle(3);
      feed(h_.z);
      dwell_if_any();
      spindle(19);
      shift(1);
      rapid(h_.initial);  // always the initial level: R is below the work
      shift(-1);
      spindle(3);
      break;
    case 88: {  // dwell and stop at Z; the operator brings the tool back to R by hand
      rapid(h_.r);
      feed(h_.z);
      dwell_if_any();
      spindle(5);
      out_.program_stop();
      at_[h_.axis] = h_.r;
      out_.manual_return(at_);
      spindle(3);
      rapid(h_.back());
      break;
    }
  }
}

// G84 (right-hand) and G74 (left-hand): with a floating holder the spindle reverses by M codes; rigid,
// the spindle turns with the drilling axis, with or without pecks (q).
template <class Out>
void Driller<Out>::tapping() {
  const int forward = h_.code == 84 ? 3 : 4, reverse = h_.code == 84 ? 4 : 3;
  rapid(h_.r);
  if (!h_.rigid) {
    // at Z and back at R: dwell P, then the spindle reverses (M05 first unless No.5101#6 M5T = 1)
    auto reversal = [&](int code) {
      dwell_if_any();
      if (!p_.drilling.tap_without_m05) spindle(5);
      spindle(code);
    };
    feed(h_.z);
    reversal(reverse);
    feed(h_.r);
    reversal(forward);
    rapid(h_.back());
    return;
  }
  // Rigid: every move in the hole is a feed with the spindle synchronised; the spindle events mark
  // its direction. Pecks (q): No.5200#5 PCP = 0 backs off by d = No.5213 after each cut, 1 goes
  // out to R and back down to d short of the last depth.
  const double dir = h_.into();
  const double d = p_.drilling.rigid_return;
  auto clamp_to_r = [&](double level) { return (level - h_.r) * dir < 0 ? h_.r : level; };
  spindle(forward);
  if (h_.q > 0) {
    double depth = h_.r;
    for (;;) {
      double next = depth + dir * h_.q;
      if ((next - h_.z) * dir >= 0) next = h_.z;
      feed(next);
      depth = next;
      if (depth == h_.z) break;
      spindle(reverse);
      if (p_.drilling.peck_to_r) {
        feed(h_.r);
        spindle(forward);
        feed(clamp_to_r(depth - dir * d));
      } else {
        feed(clamp_to_r(depth - dir * d));
        spindle(forward);
      }
    }
  } else {
    feed(h_.z);
  }
  // "the spindle is stopped and a dwell is performed; the spindle is then rotated in the reverse
  // direction, the tool is retracted to point R, then the spindle is stopped"
  spindle(5);
  dwell_if_any();
  spindle(reverse);
  feed(h_.r);
  spindle(5);
  dwell_if_any();
  rapid(h_.back());
}

template <class Out>
void Driller<Out>::lathe_cycle() {
  switch (h_.code) {
    case 83: case 87:
      if (h_.q > 0) {
        // No.5101#2 RTR = 0: high-speed peck, back by d = No.5114 after each cut; 1: peck, out to R
        // and back down to d = No.5115 short of the last depth
        const bool to_r = p_.drilling.lathe_peck_to_r;
        peck_to_bottom(h_.q, to_r ? p_.peck_clearance : p_.peck_retract, to_r);
      } else {
        feed(h_.z);
      }
      dwell_if_any();
      rapid(h_.back());
      break;
    case 84: case 88: {
      // at the bottom and back at R: dwell P, then the spindle reverses (M05 first unless No.5101#6 M5T = 1)
      auto reversal = [&](int code) {
        dwell_if_any();
        if (!p_.drilling.tap_without_m05) spindle(5);
        spindle(code);
      };
      feed(h_.z);
      reversal(4);
      feed(h_.r);
      reversal(3);
      rapid(h_.back());
      break;
    }
    case 85: case 89:  // bore to the bottom, dwell, feed back out to R
      feed(h_.z);
      dwell_if_any();
      feed(h_.r);
      rapid(h_.back());
      break;
    default:
      throw std::invalid_argument("no lathe drilling cycle G" + std::to_string(h_.code));
  }
}

template <class Out, class One>
void holes(const Hole& h, int count, const AxisVector& step, Out& out, One one) {
  if (count <= 0) return;
  one(h);
  if (count == 1) return;
  Hole at = h;
  for (int k = 1; k < count; ++k) {
    const AxisVector now = out.position();
    for (int a = 0; a < kAxes; ++a)
      if (a != h.axis) at.at[a] = now[a] + step[a];
    one(at);
  }
}

}  // namespace detail

template <class Out>
void mill_hole_to(const Hole& h, const Parameters& p, Out& out) {
  detail::Driller<Out> d(h, p, out);
  d.position();
  out.positioned();
  d.mill_cycle();
}

template <class Out>
void lathe_hole_to(const Hole& h, const Parameters& p, Out& out) {
  detail::Driller<Out> d(h, p, out);
  d.position();
  if (h.clamp_m > 0) out.m_code(h.clamp_m);
  d.rapid(h.r);
  d.lathe_cycle();
  if (h.clamp_m > 0) {
    out.m_code(h.clamp_m + 1);
    if (p.drilling.c_unclamp_dwell > 0) out.dwell(p.drilling.c_unclamp_dwell);
  }
}

// `count` holes, each next one `step` from where the last one ended (hole_cycles.hpp, mill_holes)
template <class Out>
void mill_holes_to(const Hole& h, int count, const AxisVector& step, const Parameters& p, Out& out) {
  detail::holes(h, count, step, out, [&](const Hole& at) { mill_hole_to(at, p, out); });
}
template <class Out>
void lathe_holes_to(const Hole& h, int count, const AxisVector& step, const Parameters& p, Out& out) {
  detail::holes(h, count, step, out, [&](const Hole& at) { lathe_hole_to(at, p, out); });
}

}  // namespace ncurve::machine::drill
