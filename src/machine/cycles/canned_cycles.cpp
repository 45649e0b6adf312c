// Drilling canned cycles of a FANUC mill (group 09): a cycle block's data, the drilling axis, the
// hole positions and repeats, and the block's alarms; the holes' motions are hole_cycles.cpp's.
// FANUC 30i-B / 0i-MF operator's manual, "Canned cycle for drilling". Rigid tapping's words and
// checks: tapping_cycles.cpp.
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "base/restore.hpp"
#include "machine/cycles/drilling.hpp"
#include "machine/cycles/hole_driller.hpp"

namespace ncurve::machine {

// G73..G89 in a block (x10 codes).
void Executor::select_canned_cycle(int g, std::uint16_t) {
  const int code = g / 10;
  if (modal_.cycle == 0) {  // the initial level: where the tool is when the cycle mode starts
    cycle_initial_ = coords_.pos;
    cycle_axis_ = -1;
  }
  if (code != 84 && code != 74) rigid_tapping_ = false;  // another cycle ends the rigid mode
  modal_.cycle = code;
  peck_d_checked_ = false;
}

// G80 and the group 01 codes: the cycle ends and its data (R, Z, Q, P) are cleared. Ending rigid
// tapping clears its S as if S0 were given.
void Executor::cancel_canned_cycle() {
  if (rigid_tapping_) speed_ = 0;
  modal_.cycle = 0;
  cycle_axis_ = -1;
  cycle_r_.reset();
  cycle_z_.reset();
  cycle_q_ = cycle_p_ = 0;
  cycle_has_q_ = false;
  rigid_tapping_ = rigid_pending_ = false;
  peck_d_checked_ = false;
}

// NC2076: peck drilling whose d is 0 in the profile, for a hole that takes more than one cut. The
// high-speed peck (a mill's G73; a lathe's G83/G87 with Q and No.5101#2 RTR = 0) backs off d =
// No.5114 after each cut of q: with 0 the drill does not back off at all and the chip is never
// broken. The peck cycle (G83; the lathe's with RTR = 1) goes out to point R after each cut and
// rapids back down to d = No.5115 short of the depth reached, where the cut goes on at feed: with 0
// the rapid ends on the bottom of the hole, onto the chips left there. The control gives no alarm
// for either. Once a cycle mode (the code given again starts another).
void Executor::check_peck_d(int code, double r, double z, double q, std::uint16_t column) {
  const bool high_speed = profile_.lathe() ? !profile_.drilling.lathe_peck_to_r : code == 73;
  const double d = high_speed ? profile_.peck_retract : profile_.peck_clearance;
  if (peck_d_checked_ || d != 0 || !(q > 0)) return;
  if (std::fabs(z - r) <= q + profile_.increment * 0.5) return;  // one cut: nothing to back off from
  peck_d_checked_ = true;
  const int parameter = high_speed ? 5114 : 5115;
  const std::string cycle =
      profile_.lathe() ? fmt::format("G{} with Q ({}, No.5101#2 RTR = {})", code,
                                     high_speed ? "high-speed peck drilling" : "peck drilling", high_speed ? 0 : 1)
                       : fmt::format("G{} ({})", code, high_speed ? "high-speed peck drilling" : "peck drilling");
  const std::string what =
      high_speed ? fmt::format("its retraction d after each cut of Q is 0 (No.{} = 0 in the profile): the drill does "
                               "not back off between the cuts, so the chip is never broken and the hole is fed to the "
                               "bottom as one long cut that only pauses every {:.3f} {}",
                               parameter, program_units(2, q), modal_.inch ? "in" : "mm")
                 : fmt::format("its clearance d is 0 (No.{} = 0 in the profile): after each retraction to point R the "
                               "drill rapids back down to the very depth the last cut reached, not d short of it, so "
                               "it comes down at rapid onto the chips left at the bottom of the hole",
                               parameter);
  const long example = std::lround((high_speed ? 0.5 : 1.0) / profile_.increment);
  for (const Cmd& c : cmds_)  // the cycle's own G word, where the block gives it
    if (c.letter == 'G' && std::lround(c.value * 10) == code * 10) column = c.column;
  warn_once("NC2076", fmt::format("{}: {} (the control gives no alarm); give the machine's d in increments, as "
                                  "\"{}\" in the profile's [parameters] or --param {}={} ({} mm)",
                                  cycle, what, parameter, parameter, example, high_speed ? "0.5" : "1"),
            column);
}

bool Executor::canned_cycle_block() {
  const int g = modal_.cycle;
  // No.5101#0 FXY = 0: Z drills whatever the plane; 1: the normal of G17/G18/G19 (the basic axis:
  // ncurve's mills have no parallel axes U V W that could name another)
  const int ax = profile_.drilling.axis_by_plane ? plane_axes(modal_.plane).n : 2;
  const char axis_letter = "XYZ"[ax];
  if (has('R')) cycle_r_ = dimension(word('R'));
  if (has(axis_letter)) cycle_z_ = dimension(word(axis_letter));
  // Q and P are kept only from a block that drills (or stores its data with K0)
  std::optional<double> q, p;
  if (has('Q') && (g == 73 || g == 83 || g == 76 || g == 87 || g == 84 || g == 74))
    q = std::fabs(dimension(word('Q')));  // "be sure to specify a positive value": the sign is ignored
  if (has('P')) {
    const int ms = integer(word('P'), "P of a canned cycle (dwell, milliseconds)");
    if (ms < 0) alarm("PS0006", fmt::format("P{}: a dwell time takes no minus sign", ms), word('P').column);
    p = ms / 1000.0;
  }
  const char repeat_letter = profile_.drilling.repeat_address;
  const char other = repeat_letter == 'K' ? 'L' : 'K';
  if (has(other))
    alarm("PS0009", fmt::format("address {} in a canned cycle: this control counts repeats with {} (the profile's "
                                "cycle_repeat = \"{}\")", other, repeat_letter, repeat_letter),
          word(other).column);
  const int repeat = cycle_repeat_count();

  const AxisVector base = coords_.pos;
  AxisVector hole = coords_.pos;
  const bool positioned = axis_target(hole);
  if (positioned || repeat == 0) {
    if (q) cycle_q_ = *q, cycle_has_q_ = true;
    if (p) cycle_p_ = *p;
  }
  if (!positioned) return false;  // data only: no hole
  if (rolls_) roll_over(hole);
  hole[ax] = coords_.pos[ax];             // the drilling axis word is the hole bottom, not a move
  if (repeat == 0) return false;  // K0: the data are stored, no hole is drilled

  const std::uint16_t gcol = [&] {
    for (const Cmd& c : cmds_)
      if (c.letter == 'G') return c.column;
    return std::uint16_t{0};
  }();
  if (cycle_axis_ >= 0 && cycle_axis_ != ax)
    alarm("NC9002", fmt::format("the drilling axis changed from {} to {} in cycle mode (G{} with No.5101#0 FXY = 1): "
                                "the manual asks to cancel the canned cycle (G80) before the drilling axis changes "
                                "and names no alarm; ncurve stops here",
                                "XYZ"[cycle_axis_], axis_letter, modal_.plane),
          gcol);
  if (!cycle_r_ || !cycle_z_)  // the manual on G80: "R = 0 and Z = 0 in incremental mode"
    warn_once("NC2017",
              fmt::format("G{} drills without {}: point R and point Z are cleared by G80 (and at power-on), which the "
                          "control takes as R = 0 and Z = 0 in incremental mode: {}",
                          g,
                          !cycle_r_ && !cycle_z_ ? fmt::format("R and {}", axis_letter)
                          : !cycle_r_            ? std::string("R")
                                                 : std::string(1, axis_letter),
                          !cycle_z_ ? "the hole has no depth" : "point R is the initial level"),
              gcol);
  if ((g == 73 || g == 83) && (!cycle_has_q_ || cycle_q_ <= 0))
    alarm("PS0045", fmt::format("address Q not found (G73/G83): G{} needs Q, the depth of each cut, not 0", g), gcol);
  const bool rigid = (g == 84 || g == 74) && (rigid_tapping_ || profile_.drilling.g84_rigid);
  if (rigid) rigid_tapping_check(gcol);

  cycle_axis_ = ax;
  drill::Hole h;
  h.code = g;
  h.at = hole;
  h.axis = ax;
  h.initial = cycle_initial_[ax];
  h.r = !cycle_r_ ? h.initial : modal_.incremental ? h.initial + *cycle_r_ : *cycle_r_;
  h.z = !cycle_z_ ? h.r : modal_.incremental ? h.r + *cycle_z_ : *cycle_z_;
  if (xf_on_ && xf_.active()) transformed_cycle_levels(ax, h.r, h.z);
  h.return_initial = modal_.cycle_return_initial;
  h.q = cycle_q_;
  h.p = cycle_p_;
  h.rigid = rigid;
  if ((g == 73 || g == 83) && !peck_d_checked_) [[unlikely]] check_peck_d(g, h.r, h.z, h.q, gcol);
  // Under cutter compensation the cycle's moves are made at the programmed points, the vector
  // cancelled as for G28, and the next move restores it.
  const base::RestoreOnExit restore_suspended(comp_suspended_);
  if (compensating()) comp_suspended_ = true;
  const drill::Parameters parameters = drill_parameters(profile_);
  HoleOutput out(*this, h);
  if (modal_.incremental && xf_on_) {  // G16, G51.1, G51, G68: each repeat takes the incremental command again
    for (int k = 0; k < repeat; ++k) {
      if (k > 0) {
        h.at = coords_.pos;
        axis_target(h.at);
      }
      drill::mill_hole_to(h, parameters, out);
    }
    return true;
  }
  AxisVector step{};  // G91: each repeat moves by the increment again; G90: the same hole
  if (modal_.incremental)
    for (int a = 0; a < kAxes; ++a) step[a] = hole[a] - base[a];
  drill::mill_holes_to(h, repeat, step, parameters, out);
  return true;
}

// "When the G8x command and an M code are specified in the same block, the M code is executed at
// the time of the first positioning operation": after the move to the first hole, before the rapid
// to R; the repeats (K) make no M code. M02, M30, M98 and M99 act after the block as elsewhere.
void Executor::cycle_m_codes() {
  if (cycle_m_done_) return;
  cycle_m_done_ = true;
  for (const Cmd& c : cmds_) {
    if (c.letter != 'M') continue;
    const int m = integer(c, "M");
    if (m != 2 && m != 30 && m != 98 && m != 99) m_code_event(m);
  }
}

int Executor::cycle_repeat_count() {
  const char letter = profile_.drilling.repeat_address;
  if (!has(letter)) return 1;
  const int repeat = integer(word(letter), "the repeat count of a canned cycle");
  if (repeat < 0)
    alarm("PS0006", fmt::format("{}{} of a canned cycle: the repeat count takes no minus sign", letter, repeat),
          word(letter).column);
  if (repeat > 9999)
    alarm("PS0003", fmt::format("{}{} of a canned cycle: the repeat count has at most four digits (0 to 9999)",
                                letter, repeat),
          word(letter).column);
  return repeat;
}

}  // namespace ncurve::machine
