// A lathe's canned cycles for drilling (group 10): face drilling, tapping and boring along Z (G83,
// G84, G85) and side drilling, tapping and boring along X (G87, G88, G89), as the FANUC 0i-TF /
// 30i-B lathe operator's manuals describe them ("Canned cycle for drilling"). The codes are the same
// in G-code systems A, B and C. docs/lathe-cycles.md, "Drilling cycles". The block's data and
// alarms; the holes' motions are hole_cycles.cpp's.
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

  drill::Hole h;
  h.code = g;
  h.at = hole;
  h.axis = ax;
  h.initial = cycle_initial_[ax];
  const bool r_incremental = system_a ? !profile_.drilling.lathe_r_absolute : modal_.incremental;
  const double r = cycle_r_.value_or(r_incremental ? 0.0 : h.initial);
  h.r = r_incremental ? h.initial + r : r;
  h.z = cycle_z_incremental_ ? h.r + *cycle_z_ : *cycle_z_;
  // G98/G99 choose the return level in systems B and C; system A has no such codes (G98/G99 are
  // feed per minute/revolution there) and returns to the initial level
  h.return_initial = system_a || modal_.cycle_return_initial;
  h.q = q;
  h.p = cycle_p_;
  h.clamp_m = std::max(cycle_clamp_m_, 0);
  if ((g == 83 || g == 87) && q > 0 && !peck_d_checked_) [[unlikely]] check_peck_d(g, h.r, h.z, q, gcol);
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
  HoleOutput out(*this, h);
  drill::lathe_holes(h, repeat, step, drill_parameters(profile_), out);
  return true;
}

}  // namespace ncurve::machine
