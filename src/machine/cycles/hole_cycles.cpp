// The drilling cycles' expanders through a CycleOutput (hole_cycles.hpp); their motions are
// hole_driller.hpp's.
#include "machine/cycles/hole_driller.hpp"

namespace ncurve::machine::drill {

void mill_hole(const Hole& h, const Parameters& p, CycleOutput& out) { mill_hole_to(h, p, out); }

void mill_holes(const Hole& h, int count, const AxisVector& step, const Parameters& p, CycleOutput& out) {
  mill_holes_to(h, count, step, p, out);
}

void lathe_hole(const Hole& h, const Parameters& p, CycleOutput& out) { lathe_hole_to(h, p, out); }

void lathe_holes(const Hole& h, int count, const AxisVector& step, const Parameters& p, CycleOutput& out) {
  lathe_holes_to(h, count, step, p, out);
}

}  // namespace ncurve::machine::drill
