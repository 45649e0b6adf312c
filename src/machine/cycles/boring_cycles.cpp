// Boring cycles with an oriented spindle stop or a manual return: G76 fine boring, G87 back boring
// and G88 boring, as the FANUC 0i-MF / 30i-B operator's manuals describe them.
#include <fmt/format.h>

#include "machine/cycles/drilling.hpp"

namespace ncurve::machine {

namespace {
// The shift of G76 and G87 (away from the tool tip after the oriented stop), by No.5101#4 RD1 and
// #5 RD2 and the drilling axis: in G17 (Z drills) +X, -X, +Y, -Y; G18 (Y) +Z, -Z, +X, -X; G19 (X)
// +Y, -Y, +Z, -Z.
struct Shift {
  int axis;
  double sign;
};
Shift shift_direction(int bits, int drilling_axis) {
  static constexpr int first[3] = {1, 2, 0};   // by drilling axis X, Y, Z: the first axis of its plane's column
  static constexpr int second[3] = {2, 0, 1};
  return {bits & 2 ? second[drilling_axis] : first[drilling_axis], bits & 1 ? -1.0 : 1.0};
}
}  // namespace

void Executor::boring_hole(const Hole& h) {
  const Shift s = shift_direction(profile_.drilling.shift_direction, h.axis);
  auto shift = [&](double away) {  // rapid by Q: +1 away from the tool tip, -1 back
    AxisVector t = coords_.pos;
    t[s.axis] += away * s.sign * cycle_q_;
    if (t != coords_.pos) linear(MoveKind::rapid, t);
  };
  auto oriented_stop = [&] { emit_event(MoveKind::spindle, 19); };
  switch (modal_.cycle) {
    case 76:  // bore to Z, stop the spindle oriented, move the tip off the wall, rapid out
      cycle_move(h, MoveKind::rapid, h.r);
      cycle_move(h, MoveKind::line, h.z);
      if (cycle_p_ > 0) cycle_dwell();
      oriented_stop();
      shift(1);
      cycle_move(h, MoveKind::rapid, h.back);
      shift(-1);
      emit_event(MoveKind::spindle, 3);
      break;
    case 87:  // oriented and shifted, down through the hole to R (the bottom), bore upwards to Z
      oriented_stop();
      shift(1);
      cycle_move(h, MoveKind::rapid, h.r);
      shift(-1);
      emit_event(MoveKind::spindle, 3);
      cycle_move(h, MoveKind::line, h.z);
      if (cycle_p_ > 0) cycle_dwell();
      oriented_stop();
      shift(1);
      cycle_move(h, MoveKind::rapid, h.initial);  // always the initial level: R is below the work
      shift(-1);
      emit_event(MoveKind::spindle, 3);
      break;
    case 88:  // dwell and stop at Z; the operator brings the tool back to R by hand
      cycle_move(h, MoveKind::rapid, h.r);
      cycle_move(h, MoveKind::line, h.z);
      if (cycle_p_ > 0) cycle_dwell();
      emit_event(MoveKind::spindle, 5);
      emit_event(MoveKind::program_stop, 0);
      warn("NC2005", fmt::format("G88 stops at the bottom of the hole ({} {:.3f}) for the operator to bring the tool "
                                 "back to point R by hand (JOG or handle) and press cycle start; ncurve takes that "
                                 "as a straight rapid to R",
                                 "XYZ"[h.axis], h.z));
      cycle_move(h, MoveKind::rapid, h.r);
      emit_event(MoveKind::spindle, 3);
      cycle_move(h, MoveKind::rapid, h.back);
      break;
  }
}

}  // namespace ncurve::machine
