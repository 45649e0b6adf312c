// G60 single direction positioning: every axis with an overrun (No.5440) ends its positioning in
// the same direction, through a stop short of the end point (docs/reference-moves.md).
#include <fmt/format.h>

#include "machine/executor.hpp"

namespace ncurve::machine {

// A one-shot G60 block (No.5431#0 MDL = 0).
bool Executor::single_direction_block() {
  AxisVector target = coords_.pos;
  if (!axis_target(target)) return false;
  if (rolls_) roll_over(target);
  single_direction(target);
  return true;
}

// Positioning to the point the overrun puts before the end point (end - No.5440: a positive
// overrun ends moving in +), then to the end point, both at rapid. The tool stops there even when
// it already comes from that side. An axis without an overrun, or that does not move, goes
// straight to its end in the first move.
void Executor::single_direction(const AxisVector& target) {
  if (modal_.cycle != 0)
    alarm("NC9001", "single direction positioning (G60) of a drilling canned cycle's holes is not supported yet");
  AxisVector stop = target;
  bool overrun = false;
  for (int a = 0; a < kAxes; ++a) {
    const double o = profile_.g60_overrun[a];
    if (!has_axis_[a] || o == 0 || target[a] == coords_.pos[a]) continue;
    stop[a] = target[a] - o;
    overrun = true;
  }
  if (overrun) linear(MoveKind::rapid, stop);
  linear(MoveKind::rapid, target);
}

}  // namespace ncurve::machine
