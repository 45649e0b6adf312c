// Tapping cycles G84 (right-hand) and G74 (left-hand): with a floating holder, where the control
// reverses the spindle by M codes, and rigid tapping (M29, or No.5200#0), where the spindle turns
// with the drilling axis, with or without pecks (Q). FANUC 0i-MF / 30i-B operator's manuals,
// "Tapping cycle" and "Rigid tapping".
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "machine/cycles/drilling.hpp"

namespace ncurve::machine {

void Executor::tapping_hole(const Hole& h) {
  const int forward = modal_.cycle == 84 ? 3 : 4, reverse = modal_.cycle == 84 ? 4 : 3;
  auto spindle = [&](int code) { emit_event(MoveKind::spindle, code); };
  auto dwell = [&] {
    if (cycle_p_ > 0) cycle_dwell();
  };
  cycle_move(h, MoveKind::rapid, h.r);
  if (!h.rigid) {
    // at Z and back at R: dwell P, then the spindle reverses (M05 first unless No.5101#6 M5T = 1)
    auto reversal = [&](int code) {
      dwell();
      if (!profile_.drilling.tap_without_m05) spindle(5);
      spindle(code);
    };
    cycle_move(h, MoveKind::line, h.z);
    reversal(reverse);
    cycle_move(h, MoveKind::line, h.r);
    reversal(forward);
    cycle_move(h, MoveKind::rapid, h.back);
    return;
  }
  // Rigid: every move in the hole is a feed with the spindle synchronised; the spindle events mark
  // its direction. Pecks (Q): No.5200#5 PCP = 0 backs off by d = No.5213 after each cut, 1 goes
  // out to R and back down to d short of the last depth.
  const double dir = h.into();
  const double d = profile_.drilling.rigid_return;
  auto clamp_to_r = [&](double level) { return (level - h.r) * dir < 0 ? h.r : level; };
  spindle(forward);
  if (cycle_has_q_ && cycle_q_ > 0) {
    double depth = h.r;
    for (;;) {
      double next = depth + dir * cycle_q_;
      if ((next - h.z) * dir >= 0) next = h.z;
      cycle_move(h, MoveKind::line, next);
      depth = next;
      if (depth == h.z) break;
      spindle(reverse);
      if (profile_.drilling.peck_to_r) {
        cycle_move(h, MoveKind::line, h.r);
        spindle(forward);
        cycle_move(h, MoveKind::line, clamp_to_r(depth - dir * d));
      } else {
        cycle_move(h, MoveKind::line, clamp_to_r(depth - dir * d));
        spindle(forward);
      }
    }
  } else {
    cycle_move(h, MoveKind::line, h.z);
  }
  // "the spindle is stopped and a dwell is performed; the spindle is then rotated in the reverse
  // direction, the tool is retracted to point R, then the spindle is stopped"
  spindle(5);
  dwell();
  spindle(reverse);
  cycle_move(h, MoveKind::line, h.r);
  spindle(5);
  dwell();
  cycle_move(h, MoveKind::rapid, h.back);
}

// At a rigid tapping hole: the spindle speed and the feed it needs.
void Executor::rigid_tapping_check(std::uint16_t column) const {
  if (speed_ <= 0)
    alarm("PS0200", fmt::format("rigid tapping (G{}) without a spindle speed: give S with M29 (M29 S_)", modal_.cycle),
          column);
  if (feed_ <= 0)
    alarm("PS0201", fmt::format("rigid tapping (G{}) without a feed: give F (mm/min under G94, the lead under G95)",
                                modal_.cycle),
          column);
}

// M29 selects rigid tapping for the G84/G74 that follows (or stands in its block); between the two
// the manual allows neither an S command nor an axis move, nor M29 inside a tapping cycle.
void Executor::rigid_tapping_words() {
  if (profile_.lathe()) return;
  const Cmd* m29 = nullptr;
  for (const Cmd& c : cmds_)
    if (c.letter == 'M' && std::lround(c.value) == 29) m29 = &c;
  if (!m29 && !rigid_pending_) return;
  const bool tap_word = std::ranges::any_of(g_codes_, [](int g) { return g == 840 || g == 740; });
  const Cmd* axis = nullptr;
  for (const Cmd& c : cmds_) {
    const int a = axis_index(c.letter);
    if (a >= 0 && has_axis_[a] && !axis) axis = &c;
  }
  if (m29 && !tap_word && (modal_.cycle == 84 || modal_.cycle == 74))
    alarm("PS0203", "M29 in a tapping cycle: give M29 before the G84/G74 block or in it", m29->column);
  if (!m29 && has('S') && !tap_word)
    alarm("PS0203", "an S command between M29 and G84/G74: give S with M29 (M29 S_)", word('S').column);
  if (axis && !tap_word)
    alarm("PS0204", fmt::format("an axis move ({}) between M29 and G84/G74: rigid tapping allows none", axis->letter),
          axis->column);
  if (tap_word) {
    rigid_tapping_ = true;
    rigid_pending_ = false;
  } else {
    rigid_pending_ = true;
  }
}

}  // namespace ncurve::machine
