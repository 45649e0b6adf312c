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
  double most_seconds = 3600;  // refused (std::runtime_error) if the run would take longer,
  double most_ticks = 10e6;    // or take more servo periods (the measured turn's polar: 16 bytes a period)
};

// The plane of the test: X Y on a mill (G17); Z X on a lathe (G18: angles from +Z towards +X).
struct CirclePlane {
  int p = 0, q = 1;  // axis indices; angles run from +p towards +q
  char p_name = 'X', q_name = 'Y';
};
CirclePlane circle_plane(const machine::MachineProfile& profile);

struct CircleResult {
  // simulation, over the measured turn
  double radius_reduction = 0;     // mm: R minus the mean radius
  double roundness = 0;            // mm: largest minus smallest radial deviation
  double max_deviation_angle = 0;  // degrees (0..360, from +p towards +q) where the radius is smallest
  // False when the two axes respond alike (equal gains, and equal filters after interpolation):
  // the circle then only shrinks and the angle above is where the rounding noise peaks.
  bool angle_meaningful = true;
  double feed_reached = 0;         // mm/min the control runs the circle at (F, or a limit below it)
  double max_contour_error = 0;    // mm: the whole run, start and stop included
  std::vector<std::pair<double, double>> polar;  // (angle degrees, radial deviation mm) of the measured turn
  // closed forms, at feed_reached
  double fanuc_radius_reduction = 0;    // V^2/(2R) (T^2 terms + (1 - a^2)/Kv^2), mean of the two axes
  double first_order_roundness = 0;     // V |tau_x - tau_y|: the ellipse of unequal axis delays
  double harmonic_radius_reduction = 0; // exact steady state of the linear model (filters and loops)
  double harmonic_roundness = 0;
  double harmonic_angle = 0;
  double seed002_error = 0;  // mm: largest of e = V^2/2 cos a sin a (cos a / a_q + sin a / a_p)
  double seed002_angle = 0;  // degrees, in the first quadrant
};

CircleResult circle_test(const machine::MachineProfile& profile, const CircleTest& test);

// Whether axes p and q respond alike: equal gains, and equal filters after interpolation.
bool axes_alike(const machine::MachineProfile& profile, int p, int q);

// Axis delay for slow motion (s): the servo lag (1 - feed forward)/Kv plus the filter's delay.
double axis_delay(const machine::MachineProfile& profile, int axis);

}  // namespace ncurve::motion
