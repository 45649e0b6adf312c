// The parts of a lathe tool that must not touch the part: an insert's holder shank, a drill's shank
// and holder, as polygons in the half-section's plane about the programmed point. docs/setup.md.
#pragma once
#include <vector>

#include "sim/insert_shape.hpp"
#include "sim/tool_library.hpp"

namespace ncurve::sim {

struct LatheBody {
  ToolOutline outline;      // convex, counter-clockwise, geom::V2{z, x} from the programmed point
  const char* what = "";    // "holder", "shank"
};

// The bodies behind a tool whose cutting outline is `cutting` (insert_shape.hpp):
// - an insert with holder_width and holder_length above 0: its shank, a rectangle of that width and
//   length starting where the insert ends along it. An outside tool (its tip towards -X: tips 3, 4,
//   8, and 0 and 9 taken as 3) has its shank along +X, an inside one (tips 1, 2, 6: a boring bar) along
//   +Z, a face tool along the axis away from its tip (tip 7: +Z, tip 5: -Z). Across, the shank runs
//   from the insert's leading side (the tip's side, the cutting point's Z for tips 3 and 4, its radius
//   for tips 1 and 2) into the insert's side; for tips 5..8 it is centred on the insert.
// - a mill tool along the spindle axis: its shank where wider than the cut (from the flutes' end to
//   the stick-out) and each piece of its holder stack from the stick-out on, about the axis.
// None otherwise; a size that is not finite is none.
std::vector<LatheBody> lathe_bodies(const Tool& tool, const ToolOutline& cutting);

}  // namespace ncurve::sim
