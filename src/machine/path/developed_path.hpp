// Polar coordinate interpolation (G12.1) and cylindrical interpolation (G07.1) as geometry: a line
// or an arc of the programmed ("developed") plane, and the points at which the machine's own axes
// (the linear axis and the rotary axis) are taken so that moving them linearly between the points
// keeps the tool within a tolerance of the programmed contour (docs/polar-cylindrical.md).
#pragma once
#include <cstdint>
#include <vector>

#include "geom/plane.hpp"
#include "machine/move.hpp"

namespace ncurve::machine {

using geom::V2;

// A line, or an arc about c from s sweeping `sweep` radians (counter-clockwise positive) whose
// radius goes from rs to re, in the plane of slots (p, q); t runs from 0 (s) to 1 (e).
struct PlanePath {
  V2 s, e, c;
  bool arc = false;
  double sweep = 0, rs = 0, re = 0, a0 = 0;

  static PlanePath of(const Move& m, int p, int q);
  V2 at(double t) const;
  double distance(V2 point) const;  // from the contour (the line, or the circle of the nearest radius)
};

// One point of the machine's polar motion: the linear axis (a signed radius: negative past the
// centre) and the angle from the plane's angle 0 (radians, continuous), at parameter t.
struct PolarPoint {
  double t = 0;
  double linear = 0;
  double angle = 0;
};

// The points of the polar motion along `path`, the first at t = 0. `sign` (+1, or -1 with the
// linear axis past the centre) and `angle` are the machine's before the path and are updated:
// where the path runs through the centre the linear axis changes sign and the angle holds.
// Between consecutive points the linear axis and the angle move linearly; that path stays within
// `tol` of the contour, checked at the quarter points of each piece. At most `max_points` points.
std::vector<PolarPoint> polar_points(const PlanePath& path, double tol, int& sign, double& angle,
                                     std::size_t max_points = 1'000'000);

// Cylindrical interpolation: the parameters t (0 first, 1 last) at which an arc of the developed
// surface is divided into chords no farther than `tol` from it; a line is one piece.
std::vector<double> chord_steps(const PlanePath& path, double tol, std::size_t max_points = 100'000);

// The point of the polar plane a machine position stands for: (linear * cos angle, linear * sin angle).
V2 polar_to_plane(double linear, double angle);

}  // namespace ncurve::machine
