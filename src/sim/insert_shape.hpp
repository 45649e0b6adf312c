// A lathe tool's cutting shape in the half-section's plane (Z along the spindle, X a radius): the
// convex polygon that the lathe section (lathe_section.hpp) sweeps along each move. docs/verify.md,
// "Lathe: the half-section".
#pragma once
#include <vector>

#include "geom/plane.hpp"
#include "sim/tool_library.hpp"

namespace ncurve::sim {

// The chord error of every circle made a polygon for the lathe section, mm: a nose radius, the end
// of a drill or ball end mill, and (lathe_section.hpp) the chords of an arc move. The polygon's
// vertices lie on the circle, so a polygonised nose cuts at most this much less than the round one.
inline constexpr double kChordError = 0.5e-3;
// At most this many chords make one circular arc; beyond a radius of some 400 mm for a half circle
// the chord error then grows past kChordError.
inline constexpr int kMaxArcChords = 1024;

// The insert's size, which a tool library does not give.
struct InsertSize {
  double inscribed_circle = 12.7;  // mm: a pointed insert is a rhombus of this inscribed circle
  double blade_length = 20;        // mm: a grooving blade's depth from its cutting edge
};

// A tool's cutting shape: a convex polygon, counter-clockwise, its points as geom::V2{z, x} (x is
// Z, y is X as a radius), mm from the programmed point.
struct ToolOutline {
  std::vector<geom::V2> points;
  bool empty() const { return points.size() < 3; }
};

// A turning insert or grooving blade, the programmed point being its imaginary tip
// (machine::tip_direction: the nose centre is the programmed point less the tip's vector of one
// nose radius along X and Z; tips 0 and 9 are the nose centre itself):
// - pointed (width 0): a rhombus of `insert_angle` at its cutting corner, rounded by the nose radius,
//   its edges tangent to the nose. Tips 1..4 point on a diagonal: the edge across the spindle axis
//   leans back from the perpendicular by `clearance_angle` (a 95-degree holder's 5 degrees) and the
//   other edge follows at the insert angle (an 80-degree insert's trailing edge rises 5 degrees from
//   the Z axis behind the tool). Tips 5..8 point along an axis: the insert is symmetric about it.
//   Tips 0 and 9 are oriented as tip 3 (an outside turning tool);
// - a blade (width above 0): a rectangle of the width and `size.blade_length`, its two cutting
//   corners rounded by the nose radius (at most half the width), its cutting edge facing the tip's X
//   direction (tips 5 and 7: its Z direction, a face groove). The programmed point is the imaginary
//   tip of the corner the tip names, the blade extending to the other side (tip 3: the -Z corner,
//   the blade towards +Z); tips 6 and 8 (5 and 7) name the middle of the cutting edge, tips 0 and 9
//   the nose centre of the -Z corner of a blade oriented as tip 3.
// Out-of-range numbers are made safe rather than refused: a negative or non-finite nose radius or
// width is 0, a tip outside 0..9 is 0, an insert angle outside [1, 179] degrees is clamped (80
// when not finite), a clearance angle to [-89, 89] (5 when not finite).
ToolOutline insert_outline(const LatheInsert& insert, const InsertSize& size = {});

// A mill tool on a lathe (a drill, a centre drill, an end mill held in the tailstock or turret
// along the spindle axis): its section through its axis, the axis along Z, the tip at the programmed
// point pointing to -Z, its flutes (at least its end) along +Z. Exact for a tool on the spindle axis
// or off it, the part turning about the axis. An empty outline for a diameter that is not positive
// and finite.
ToolOutline axial_tool_outline(const MillTool& tool);

// The outline of either kind.
ToolOutline tool_outline(const Tool& tool, const InsertSize& size = {});

// The number of chords of at most `error` sagitta (rounded up) that make an arc of radius r and the
// given angle (radians), from 1 to kMaxArcChords.
int arc_chords(double r, double angle, double error = kChordError);

}  // namespace ncurve::sim
