// NC2077: a lathe's feed move beyond the spindle centre line. A turning tool cuts on its own side of
// the centre (X >= 0); a feed that ends at or passes through X < 0 has the tool cutting on the far
// side, which is almost always a wrong sign or a wrong centre. Facing down to X0 is not warned.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {

// Below this much under X0 (a radius: half the least input increment of a diameter) the tool is
// beyond the centre; nearer is X0 written by a computation's rounding.
constexpr double kBeyond = 0.0005;
// A facing cut's overshoot past the centre, as a radius, that is not warned (X-2. on a diameter); a
// larger nose radius allows its own.
constexpr double kFacingOvershoot = 1.0;

// The lowest X a move reaches: a line's lower end, an arc's lowest point when its sweep passes the
// angle where X is least (X one of the plane's axes), else its lower end.
double lowest_x(const Move& m) {
  double low = std::min(m.start[0], m.end[0]);
  if (m.kind != MoveKind::arc) return low;
  const PlaneAxes pa = plane_axes(m.plane);
  if (pa.p != 0 && pa.q != 0) return low;
  const double a0 = std::atan2(m.start[pa.q] - m.center[pa.q], m.start[pa.p] - m.center[pa.p]);
  const double rs = std::hypot(m.start[pa.p] - m.center[pa.p], m.start[pa.q] - m.center[pa.q]);
  const double re = std::hypot(m.end[pa.p] - m.center[pa.p], m.end[pa.q] - m.center[pa.q]);
  const double least = pa.p == 0 ? std::numbers::pi : -std::numbers::pi / 2;  // cos = -1, or sin = -1
  const double turn = 2 * std::numbers::pi;
  double d = std::fmod(m.sweep >= 0 ? least - a0 : a0 - least, turn);
  if (d < 0) d += turn;
  const double sweep = std::fabs(m.sweep);
  if (d > sweep) return low;
  const double t = sweep > 0 ? d / sweep : 0;  // the fraction of the arc there (a spiral's radius runs linearly)
  return std::min(low, m.center[0] - (rs + (re - rs) * t));
}

}  // namespace

// Once each time the path goes beyond the centre: again only after a feed wholly on the tool's side.
void Executor::check_centre_line(const Move& m) {
  const double low = lowest_x(m);
  if (low >= -kBeyond) {
    beyond_centre_ = false;
    return;
  }
  if (low >= -std::max(kFacingOvershoot, nose_radius()) - kBeyond) {
    beyond_centre_ = false;
    return;
  }
  if (beyond_centre_) return;
  beyond_centre_ = true;
  const bool dia = profile_.diameter_x;
  std::uint16_t column = has('X') ? word('X').column : has('U') ? word('U').column : 0;
  const double places = modal_.inch ? 10000 : 1000;  // as a program writes it, in its units
  const double shown = std::round((dia ? 2 * low : low) / (modal_.inch ? 25.4 : 1.0) * places) / places;
  warn("NC2077", fmt::format("the feed goes to X{:g}{}, beyond the spindle centre line (X0): a turning tool cuts on "
                             "its own side of the centre, so the far side is almost always a wrong sign of X or a "
                             "wrong centre of an arc or a curve (the control gives no alarm); a facing cut ends at X0, "
                             "or past it by no more than the nose radius or 1 mm, which is not warned",
                             shown, dia ? " (a diameter)" : ""),
       column);
}

}  // namespace ncurve::machine
