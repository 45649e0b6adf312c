// A lathe's canned cycles for drilling (group 10): face drilling, tapping and boring along Z (G83,
// G84, G85) and side drilling, tapping and boring along X (G87, G88, G89), as the FANUC 0i-TF /
// 30i-B lathe operator's manuals describe them ("Canned cycle for drilling"). The codes are the same
// in G-code systems A, B and C. docs/lathe-cycles.md, "Drilling cycles".
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/restore.hpp"
#include "machine/cycles/drilling.hpp"

namespace ncurve::machine {

namespace {
const char* lathe_cycle_name(int g) {
  switch (g) {
    case 83: return "face drilling cycle";
    case 84: return "face tapping cycle";
    case 85: return "face boring cycle";
    case 87: return "side drilling cycle";
    case 88: return "side tapping cycle";
    default: return "side boring cycle";
  }
}
}  // namespace

// A block in a lathe's drilling mode: stores R, the bottom and P; drills when it has axis words.
//   G83 X(U) C(H) Z(W) R Q P F K M   (G87: Z(W) C(H) X(U) ...)
// X C (Z C) position the hole, Z (X) is the bottom (W, U or G91: the distance from R), R the
// distance from the initial level to point R, Q the depth of each peck in least input increments.
bool Executor::lathe_drilling_block() {
  const int g = modal_.cycle;
  const bool face = g <= 85;
  const int ax = face ? 2 : 0;  // the drilling axis
  const bool system_a = profile_.gcode_system == 'A';
  const bool diameter = ax == 0 && profile_.diameter_x;
  const std::uint16_t gcol = [&] {
    for (const Cmd& c : cmds_)
      if (c.letter == 'G') return c.column;
    return std::uint16_t{0};
  }();
  if (system_a && has('H'))
    alarm("NC9001", fmt::format("H (an incremental C position) in a drilling cycle (G{}) is not supported yet", g),
          word('H').column);
  const bool tapping = g == 84 || g == 88;
  const bool m29 = std::ranges::any_of(cmds_, [](const Cmd& c) { return c.letter == 'M' && std::lround(c.value) == 29; });
  if (tapping && (m29 || last_m_ == 29 || profile_.drilling.g84_rigid))
    alarm("NC9001", fmt::format("rigid tapping on a lathe (M29 with G{}, or No.5200#0) is not supported yet", g), gcol);

  if (has('R')) {  // a radius unless No.5102#6 RDI = 1 and the drilling axis is a diameter
    const double r = dimension(word('R'));
    cycle_r_ = diameter && profile_.drilling.lathe_r_by_axis ? r / 2 : r;
  }
  const char absolute = face ? 'Z' : 'X', relative = face ? 'W' : 'U';
  if (has(absolute) || (system_a && has(relative))) {
    const bool inc = system_a ? !has(absolute) : modal_.incremental;
    const double v = dimension(word(has(absolute) ? absolute : relative));
    cycle_z_ = diameter ? v / 2 : v;
    cycle_z_incremental_ = inc;
  }
  // Q is given in each block that pecks (a block without Q drills in one cut); P is modal
  double q = 0;
  if (has('Q') && (g == 83 || g == 87))
    q = std::fabs(increments(word('Q'), "Q of G83/G87 (the depth of each cut, least input increments)"));
  std::optional<double> p;
  if (has('P')) {
    const int ms = integer(word('P'), "P of a canned cycle (dwell, milliseconds)");
    if (ms < 0) alarm("PS0006", fmt::format("P{}: a dwell time takes no minus sign", ms), word('P').column);
    p = ms / 1000.0;
  }
  const int repeat = cycle_repeat_count();

  const AxisVector base = coords_.pos;
  AxisVector hole = coords_.pos;
  const bool positioned = axis_target(hole);
  if ((positioned || repeat == 0) && p) cycle_p_ = *p;
  if (!positioned || repeat == 0) return false;  // data only
  if (rolls_) roll_over(hole);
  hole[ax] = coords_.pos[ax];  // the drilling axis word is the bottom, not a move
  if (!cycle_z_)
    alarm("PS0045", fmt::format("address {} not found (G{}, {}): a hole needs its bottom {}{} (the manual names "
                                "no alarm for it; ncurve stops here)",
                                absolute, g, lathe_cycle_name(g), absolute, system_a ? fmt::format(" or {}", relative) : ""),
          gcol);
  // the C-axis clamp M code (No.5110) in the block is given out at each hole, its unclamp after it
  const int clamp = profile_.drilling.c_clamp_m;
  cycle_clamp_m_ = clamp > 0 && std::ranges::any_of(cmds_, [&](const Cmd& c) {
    return c.letter == 'M' && std::lround(c.value) == clamp;
  }) ? clamp : -1;

  Hole h;
  h.axis = ax;
  h.initial = cycle_initial_[ax];
  const bool r_incremental = system_a ? !profile_.drilling.lathe_r_absolute : modal_.incremental;
  const double r = cycle_r_.value_or(r_incremental ? 0.0 : h.initial);
  h.r = r_incremental ? h.initial + r : r;
  h.z = cycle_z_incremental_ ? h.r + *cycle_z_ : *cycle_z_;
  // G98/G99 choose the return level in systems B and C; system A has no such codes (G98/G99 are
  // feed per minute/revolution there) and returns to the initial level
  h.back = system_a || modal_.cycle_return_initial ? h.initial : h.r;
  // Under tool-nose radius compensation the moves are made at the programmed points, the vector
  // cancelled as for G28, and the next move restores it (as the mill's cycles do).
  const base::RestoreOnExit restore_suspended(comp_suspended_);
  if (compensating()) comp_suspended_ = true;
  AxisVector step{};  // K: each repeat moves again by the incremental positioning words
  for (const Cmd& c : cmds_) {
    int a = axis_index(c.letter);
    bool inc = modal_.incremental;
    if (system_a && (c.letter == 'U' || c.letter == 'V' || c.letter == 'W')) {
      a = c.letter == 'U' ? 0 : c.letter == 'V' ? 1 : 2;
      inc = true;
    }
    if (a >= 0 && a != ax && inc) step[a] = hole[a] - base[a];
  }
  for (int k = 0; k < repeat; ++k) {
    if (k > 0)
      for (int a = 0; a < kAxes; ++a)
        if (a != ax) hole[a] = coords_.pos[a] + step[a];
    Hole at = h;
    at.at = hole;
    lathe_hole(at, q);
  }
  return true;
}

// One hole: position at the current level, clamp C (if asked), rapid to R, the cycle's motions,
// return to the initial level (G98, system A) or to R (G99), unclamp C and dwell No.5111.
void Executor::lathe_hole(const Hole& h, double q) {
  const int g = modal_.cycle;
  AxisVector at = h.at;
  at[h.axis] = coords_.pos[h.axis];
  if (at != coords_.pos) linear(MoveKind::rapid, at);
  if (cycle_clamp_m_ > 0) emit_event(MoveKind::m_code, cycle_clamp_m_);
  cycle_move(h, MoveKind::rapid, h.r);
  auto dwell = [&] {
    if (cycle_p_ > 0) cycle_dwell();
  };
  switch (g) {
    case 83: case 87:
      if (q > 0) {
        // No.5101#2 RTR = 0: high-speed peck, back by d = No.5114 after each cut; 1: peck, out to R
        // and back down to d = No.5115 short of the last depth
        const bool to_r = profile_.drilling.lathe_peck_to_r;
        peck_to_bottom(h, q, to_r ? profile_.peck_clearance : profile_.peck_retract, to_r);
      } else {
        cycle_move(h, MoveKind::line, h.z);
      }
      dwell();
      cycle_move(h, MoveKind::rapid, h.back);
      break;
    case 84: case 88: {
      // at the bottom and back at R: dwell P, then the spindle reverses (M05 first unless No.5101#6 M5T = 1)
      auto reversal = [&](int code) {
        dwell();
        if (!profile_.drilling.tap_without_m05) emit_event(MoveKind::spindle, 5);
        emit_event(MoveKind::spindle, code);
      };
      cycle_move(h, MoveKind::line, h.z);
      reversal(4);
      cycle_move(h, MoveKind::line, h.r);
      reversal(3);
      cycle_move(h, MoveKind::rapid, h.back);
      break;
    }
    default:  // G85, G89: bore to the bottom, dwell, feed back out to R
      cycle_move(h, MoveKind::line, h.z);
      dwell();
      cycle_move(h, MoveKind::line, h.r);
      cycle_move(h, MoveKind::rapid, h.back);
      break;
  }
  if (cycle_clamp_m_ > 0) {
    emit_event(MoveKind::m_code, cycle_clamp_m_ + 1);
    if (profile_.drilling.c_unclamp_dwell > 0) {
      Move m;
      m.kind = MoveKind::dwell;
      m.start = m.end = coords_.pos;
      m.seconds = profile_.drilling.c_unclamp_dwell;
      emit(m);
    }
  }
}

}  // namespace ncurve::machine
