// Chamfering and corner R between two paths of a plane, as FANUC inserts them (,C ,R; lathe C/I/K R):
// plane geometry only, free of the interpreter.
#pragma once
#include "geom/plane.hpp"

namespace ncurve::machine::corner {

using geom::V2;

// One block's path in the plane: a line from s to e, or an arc about c turning `sweep` radians
// (counter-clockwise positive) from s to e.
struct Path {
  bool arc = false;
  V2 s, e, c;
  double sweep = 0;
};

enum class Kind { chamfer, round };

enum class Fault {
  none,
  first_too_short,   // the chamfer or the arc does not fit on the first path
  second_too_short,  // nor on the second
  no_solution,       // no arc of that radius touches both paths (they reverse, or do not meet)
};

// What is cut off the corner where `a` ends and `b` starts.
struct Cut {
  Fault fault = Fault::none;
  bool none = false;  // the paths meet within 1 degree: nothing is inserted (the manual's travel of 0)
  V2 a_end, b_start;  // the first path now ends, the second starts, here
  double a_part = 1;  // share of the first path kept (of its length or turn), from its start
  double b_part = 0;  // share of the second path cut away, from its start
  V2 centre;          // round: the inserted arc's centre
  bool ccw = false;   // round: the inserted arc turns counter-clockwise (G03)
};

// Chamfer: the points at straight-line distance `amount` from the corner on each path, joined by a
// line. Round: the arc of radius `amount` tangent to both paths on the inner side of the corner.
Cut cut_corner(const Path& a, const Path& b, Kind kind, double amount);

// The direction of travel along p at its point x (unit vector).
V2 tangent(const Path& p, V2 x);

}  // namespace ncurve::machine::corner
