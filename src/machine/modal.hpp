// The control's modal state: what each modal G-code group has in force, as the G-code table
// (g_codes.hpp) groups the codes and #4001..#4022 read them (Executor::modal_code). The groups whose
// codes carry data of their own (scaling, rotation, mirror image: frame/transforms.hpp; polar and
// cylindrical interpolation: the Executor's Developed) keep it in their component.
#pragma once

#include "machine/profile.hpp"

namespace ncurve::machine {

struct ModalState {
  int motion = 0;                        // interpolation: 0..3 (G00..G03), 33, 60, or a lathe cycle's code as written
  int plane = 17;                        // 17, 18, 19
  bool incremental = false;              // G91 (a system A lathe: U, W words, and #4003 reads 90)
  bool stroke2_on = true;                // G22 (stored stroke check 2 on), else G23
  bool feed_per_rev = false;             // G95 (G99 on a system A lathe), else per minute
  bool inch = false;                     // G20 (G70 on system C), else G21
  int comp_side = 0;                     // +1 G41, -1 G42, 0 G40
  int length_comp = 49;                  // 43, 44, 49
  bool speed_fluctuation_check = false;  // G26, else G25
  int cycle = 0;                         // drilling canned cycle: 0 G80, else 73, 74, 76, 81..89
  bool cycle_return_initial = true;      // G98 (initial level), else G99 (point R)
  bool modal_call = false;               // G66 in force, else G67
  int work_index = 1;                    // 1..6 G54..G59, 7 and up G54.1 P(n - 6)
  int exact_stop_code = 64;              // 61, 62, 63, 64; 611 for G61.1
  bool exact_stop = false;               // G61: every move ends in an exact stop
  bool css = false;                      // G96 (constant surface speed), else G97
  bool polar = false;                    // G16 (polar coordinate command), else G15
  bool look_ahead = true;                // G05.1 Q1, G08 P1, G05 P10000 (G61.1: exact_stop_code 611)

  // The codes a run starts in that the profile sets (the others keep their values between runs).
  void power_on(const MachineProfile& p) {
    motion = p.power_on_g01 ? 1 : 0;
    plane = p.power_on_plane;
    incremental = p.power_on_g91;
    feed_per_rev = p.power_on_feed_per_rev;
    look_ahead = p.motion.look_ahead_at_power_on;
  }
};

}  // namespace ncurve::machine
