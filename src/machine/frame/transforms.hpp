// Coordinate transforms of a FANUC mill, as pure maths: polar coordinate command (G16), programmable
// mirror image (G51.1), scaling (G51) and coordinate system rotation (G68). The control applies them
// to a programmed point in that order (FANUC 0i-MF / 30i-B operator's manuals), before cutter
// compensation: work = rotate(scale(mirror(program))).
#pragma once
#include <array>
#include <optional>

#include "geom/plane.hpp"
#include "machine/profile.hpp"

namespace ncurve::machine {

using geom::V2;

// G16: the point a polar command names, in the plane's two axes (p = first axis, q = second).
// `current` is the programmed position, measured from the work (or G52 local) origin. Absolute
// (G90): radius and angle about the origin. Incremental (G91) with a radius: the radius is the
// distance from the current position, the angle the current position's angle about the origin
// plus the increment. A radius left out keeps the origin as the centre and the current distance
// from it; an angle left out keeps the current position's angle. Angles in degrees, anticlockwise
// from the first axis.
V2 polar_point(V2 current, std::optional<double> radius, std::optional<double> angle_deg, bool incremental);

struct Transforms {
  // G51.1: axes mirrored about a position (program coordinates)
  std::array<bool, kAxes> mirrored{};
  AxisVector mirror_at{};
  // G51: factor per axis about a centre (coordinates after the mirror)
  bool scaling = false;
  AxisVector factor{1, 1, 1, 1, 1, 1};
  AxisVector scale_centre{};
  // G68: rotation in the plane of axes (p, q) about a centre (coordinates after mirror and scaling)
  bool rotating = false;
  int p = 0, q = 1;
  double angle_deg = 0;  // as applied (a mirror in the plane has already reversed the programmed angle)
  V2 centre{};

  bool mirroring() const;
  bool active() const { return rotating || scaling || mirroring(); }
  AxisVector apply(const AxisVector& program) const;  // program -> work coordinates
  AxisVector invert(const AxisVector& work) const;    // work -> program coordinates
  AxisVector apply_vector(const AxisVector& v) const;  // a direction or offset (I J K): no centres
  // Whether a path in the plane of axes (p, q) comes out reversed (an odd number of flips: mirror
  // or a negative factor): G02 and G03 swap, and so do G41 and G42.
  bool reverses(int p_axis, int q_axis) const;
  // R of an arc in the plane of axes (p, q): scaled by the larger factor of the two (magnitudes).
  double radius_factor(int p_axis, int q_axis) const;
  // The mirror and scaling stages only: where a centre given for a later stage goes.
  AxisVector mirror_and_scale(const AxisVector& program) const;
};

}  // namespace ncurve::machine
