// The drilling canned cycles as expanders, free of the interpreter: one hole's data in, its moves out
// through a CycleOutput. A mill's G73, G74, G76, G81..G89 and a lathe's G83..G85, G87..G89, as the
// FANUC 0i-MF/0i-TF and 30i-B operator's manuals describe them ("Canned cycle for drilling").
// The interpreter keeps the modal cycle data, works out the levels and raises the block's alarms.
#pragma once
#include "machine/cycles/cycle_output.hpp"
#include "machine/profile.hpp"

namespace ncurve::machine::drill {

// The parameters the cycles read.
struct Parameters {
  double peck_retract = 0;    // No.5114: d of G73 (and of a lathe's high-speed peck)
  double peck_clearance = 0;  // No.5115: d of G83 (and of a lathe's peck out to R)
  DrillingSettings drilling;  // No.5101, No.5200, No.5213, No.5110, No.5111
};

struct Hole {
  int code = 81;        // 73, 74, 76, 81..89 (a lathe: 83..85, 87..89)
  AxisVector at{};      // the hole position (its coordinate along the drilling axis is not used)
  int axis = 2;         // the drilling axis: 0 X, 1 Y, 2 Z
  double initial = 0, r = 0, z = 0;  // levels along the drilling axis: initial level, point R, point Z
  bool return_initial = true;  // G98: the hole ends at the initial level; G99: at point R
  double q = 0;         // depth of each cut (G73, G83, rigid G84/G74), shift (G76, G87); 0: none
  double p = 0;         // dwell, s
  bool rigid = false;   // G84/G74 as rigid tapping
  int clamp_m = 0;      // a lathe: the C-axis clamp M code given at each hole (its unclamp: + 1); 0: none

  double back() const { return return_initial ? initial : r; }
  double into() const { return z < r ? -1.0 : 1.0; }  // from R towards Z
};

// One hole of a mill: position at the current level, the block's M codes (CycleOutput::positioned),
// rapid to R, the cycle's motions, back to the initial level or R. A code the mill has no cycle for
// is std::invalid_argument; G73/G83 need q > 0.
void mill_hole(const Hole& h, const Parameters& p, CycleOutput& out);
// `count` holes (K): the first at h.at, each next one `step` away (G91: the block's increments;
// G90: zero, the same hole) from where the last one ended, along all axes but the drilling axis.
void mill_holes(const Hole& h, int count, const AxisVector& step, const Parameters& p, CycleOutput& out);

// One hole of a lathe: position, clamp C (clamp_m), rapid to R, the cycle's motions, back, unclamp C
// and dwell No.5111. q = 0: G83/G87 drill in one cut.
void lathe_hole(const Hole& h, const Parameters& p, CycleOutput& out);
void lathe_holes(const Hole& h, int count, const AxisVector& step, const Parameters& p, CycleOutput& out);
// hole_driller.hpp has each of these as a template on the output type (mill_holes_to ...).

}  // namespace ncurve::machine::drill
