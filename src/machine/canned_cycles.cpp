// Drilling canned cycles of a FANUC mill (group 09): G73, G74, G81..G86, G89, G80, with G98/G99.
// FANUC 30i-B / 0i-MF operator's manual, "Canned cycle for drilling": the hole position X Y in the G17
// plane, R and Z along Z, data kept while the cycle mode lasts, K repeats.
#include <fmt/format.h>

#include <cmath>

#include "machine/interpreter.hpp"

namespace ncurve::machine {

namespace {
const char* cycle_name(int g) {
  switch (g) {
    case 73: return "high-speed peck drilling cycle";
    case 74: return "left-handed tapping cycle";
    case 76: return "fine boring cycle";
    case 81: return "drilling cycle";
    case 82: return "drilling cycle with dwell";
    case 83: return "peck drilling cycle";
    case 84: return "tapping cycle";
    case 85: return "boring cycle";
    case 86: return "boring cycle";
    case 87: return "back boring cycle";
    case 88: return "boring cycle";
    case 89: return "boring cycle with dwell";
    default: return "canned cycle";
  }
}
}  // namespace

// G73..G89 in a block (x10 codes). G76, G87 and G88 are not simulated.
void Interpreter::select_canned_cycle(int g, std::uint16_t column) {
  const int code = g / 10;
  if (code == 76 || code == 87 || code == 88)
    alarm("NC9001", fmt::format("G{} ({}) is not supported yet", code, cycle_name(code)), column);
  if (cycle_ == 0) cycle_initial_z_ = pos_[2];  // the initial level: Z where the cycle mode starts
  cycle_ = code;
}

// G80 and the group 01 codes: the cycle ends and its data (R, Z, Q, P) are cleared.
void Interpreter::cancel_canned_cycle() {
  cycle_ = 0;
  cycle_r_.reset();
  cycle_z_.reset();
  cycle_q_ = cycle_p_ = 0;
  cycle_has_q_ = false;
  rigid_tapping_ = false;
}

bool Interpreter::canned_cycle_block() {
  const int g = cycle_;
  if (has('R')) cycle_r_ = dimension(word('R'));
  if (has('Z')) cycle_z_ = dimension(word('Z'));
  if (has('Q') && (g == 73 || g == 83)) {
    cycle_q_ = std::fabs(dimension(word('Q')));  // "be sure to specify a positive value": the sign is ignored
    cycle_has_q_ = true;
  }
  if (has('P')) {
    const int ms = integer(word('P'), "P of a canned cycle (dwell, milliseconds)");
    if (ms < 0) alarm("PS0011", "negative dwell time", word('P').column);
    cycle_p_ = ms / 1000.0;
  }
  int repeat = 1;
  if (has('K')) {
    repeat = integer(word('K'), "K of a canned cycle (repeats)");
    if (repeat < 0 || repeat > 9999)
      alarm("PS0045", fmt::format("K{} of a canned cycle: the repeat count is 0 to 9999 (the manual names no "
                                  "alarm for it; ncurve stops here)", repeat),
            word('K').column);
  }
  for (const Cmd& c : cmds_)
    if (c.letter == 'M' && std::lround(c.value) == 29) rigid_tapping_ = true;

  AxisVector base = pos_;
  AxisVector hole = pos_;
  const bool axes = axis_target(hole);
  if (!axes) return false;  // data only: no hole
  hole[2] = pos_[2];        // Z is the hole bottom, not a move
  if (repeat == 0) return false;  // K0: the data are stored, no hole is drilled

  const std::uint16_t gcol = [&] {
    for (const Cmd& c : cmds_)
      if (c.letter == 'G') return c.column;
    return std::uint16_t{0};
  }();
  if (plane_ != 17)
    alarm("NC9001", fmt::format("G{} ({}) in the G{} plane is not supported yet (G17 only: holes along Z)", g,
                                cycle_name(g), plane_),
          gcol);
  if (compensating())
    alarm("NC9001", fmt::format("G{} ({}) under cutter compensation is not supported yet: cancel it with G40 first",
                                g, cycle_name(g)),
          gcol);
  if ((g == 84 || g == 74) && rigid_tapping_)
    alarm("NC9001", fmt::format("rigid tapping (M29 with G{}) is not supported yet", g), gcol);
  if (!cycle_z_)
    alarm("PS0045", fmt::format("address Z not found (G{}): a hole needs its bottom point Z (the manual names no "
                                "alarm for it; ncurve stops here)", g),
          gcol);
  if (!cycle_r_)
    alarm("PS0045", fmt::format("address R not found (G{}): a hole needs its point R (the manual names no alarm "
                                "for it; ncurve stops here)", g),
          gcol);
  if ((g == 73 || g == 83) && (!cycle_has_q_ || cycle_q_ <= 0))
    alarm("PS0045", fmt::format("address Q not found (G73/G83): G{} needs Q, the depth of each cut, not 0", g), gcol);

  AxisVector step{};
  for (int a = 0; a < kAxes; ++a) step[a] = hole[a] - base[a];
  for (int k = 0; k < repeat; ++k) {
    if (k > 0 && incremental_ && xf_on_) {  // G16, G51.1, G51, G68: the incremental command again
      hole = pos_;
      axis_target(hole);
      hole[2] = pos_[2];
    } else if (k > 0 && incremental_) {
      for (int a = 0; a < kAxes; ++a)
        if (a != 2) hole[a] += step[a];
    }
    double r_level = incremental_ ? cycle_initial_z_ + *cycle_r_ : *cycle_r_;
    double z_level = incremental_ ? r_level + *cycle_z_ : *cycle_z_;
    if (xf_on_ && xf_.active()) transformed_cycle_levels(r_level, z_level);
    drill_hole(hole, r_level, z_level);
  }
  return true;
}

// One hole: position at the current level, rapid to R, the cycle's motions, return to the initial
// level (G98) or to R (G99).
void Interpreter::drill_hole(const AxisVector& hole, double r_level, double z_level) {
  const int g = cycle_;
  const double initial = cycle_initial_z_;
  const double back = cycle_return_initial_ ? initial : r_level;
  auto go = [&](MoveKind kind, double z) {
    AxisVector t = pos_;
    t[2] = z;
    if (t[2] != pos_[2]) linear(kind, t);
  };
  auto pause = [&] {
    Move m;
    m.kind = MoveKind::dwell;
    m.start = m.end = pos_;
    m.seconds = cycle_p_;
    emit(m);
  };
  AxisVector at = hole;
  at[2] = pos_[2];
  if (at != pos_) linear(MoveKind::rapid, at);
  go(MoveKind::rapid, r_level);
  const double dir = z_level < r_level ? -1.0 : 1.0;  // into the hole
  switch (g) {
    case 81:
      go(MoveKind::line, z_level);
      go(MoveKind::rapid, back);
      break;
    case 82:
      go(MoveKind::line, z_level);
      pause();
      go(MoveKind::rapid, back);
      break;
    case 73: case 83: {
      const double q = cycle_q_;
      const double d = g == 73 ? profile_.peck_retract : profile_.peck_clearance;
      double depth = r_level;  // reached so far
      for (;;) {
        double next = depth + dir * q;
        if ((next - z_level) * dir >= 0) next = z_level;
        go(MoveKind::line, next);
        depth = next;
        if (depth == z_level) break;
        if (g == 73) {
          go(MoveKind::rapid, depth - dir * d);  // back by d to break the chip
        } else {
          go(MoveKind::rapid, r_level);          // out to R, then down to d short of the last depth
          go(MoveKind::rapid, depth - dir * d);
        }
      }
      go(MoveKind::rapid, back);
      break;
    }
    case 85:
      go(MoveKind::line, z_level);
      go(MoveKind::line, r_level);
      go(MoveKind::rapid, back);
      break;
    case 89:
      go(MoveKind::line, z_level);
      pause();
      go(MoveKind::line, r_level);
      go(MoveKind::rapid, back);
      break;
    case 86:
      go(MoveKind::line, z_level);
      emit_event(MoveKind::spindle, 5);
      go(MoveKind::rapid, back);
      emit_event(MoveKind::spindle, 3);
      break;
    case 84: case 74:  // G84 taps with the spindle clockwise and backs out counter-clockwise; G74 the reverse
      go(MoveKind::line, z_level);
      if (cycle_p_ > 0) pause();
      emit_event(MoveKind::spindle, g == 84 ? 4 : 3);
      go(MoveKind::line, r_level);
      emit_event(MoveKind::spindle, g == 84 ? 3 : 4);
      go(MoveKind::rapid, back);
      break;
    default:
      alarm("NC9001", fmt::format("G{} (canned cycle) is not supported yet", g));
  }
}

}  // namespace ncurve::machine
