// The circular test of ISO 230-4 on the model: a full circle at a feed, the radial deviation of
// the path the machine follows, and the closed forms beside it.
#pragma once
#include <utility>
#include <vector>

#include "machine/profile.hpp"

namespace ncurve::motion {

struct CircleTest {
  double radius = 50;  // mm
  double feed = 1000;  // mm/min
  bool clockwise = false;
  int turns = 3;       // the middle turn is measured (steady state)
};

struct CircleResult {
  // simulation, over the measured turn
  double radius_reduction = 0;     // mm: R minus the mean radius
  double roundness = 0;            // mm: largest minus smallest radial deviation
  double max_deviation_angle = 0;  // degrees (0..360, from +X counter-clockwise) where the radius is smallest
  double max_contour_error = 0;    // mm: the whole run, start and stop included
  std::vector<std::pair<double, double>> polar;  // (angle degrees, radial deviation mm) of the measured turn
  // closed forms
  double fanuc_radius_reduction = 0;    // V^2/(2R) (T^2 terms + (1 - a^2)/Kv^2), mean of the two axes
  double first_order_roundness = 0;     // V |tau_x - tau_y|: the ellipse of unequal axis delays
  double harmonic_radius_reduction = 0; // exact steady state of the linear model (filters and loops)
  double harmonic_roundness = 0;
  double harmonic_angle = 0;
  double seed002_error = 0;  // mm: largest of e = V^2/2 cos a sin a (cos a / a_y + sin a / a_x)
  double seed002_angle = 0;  // degrees, in the first quadrant
};

CircleResult circle_test(const machine::MachineProfile& profile, const CircleTest& test);

// Axis delay for slow motion (s): the servo lag (1 - feed forward)/Kv plus the filter's delay.
double axis_delay(const machine::MachineProfile& profile, int axis);

}  // namespace ncurve::motion
