// SVG plots of ncurve analyze: feed along the path, the path coloured by its deviation from the
// nominal curve, and the circular test's polar deviation diagram.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "motion/circle.hpp"

namespace ncurve::report {

struct FeedSample {
  double path = 0;        // mm from the start of the cutting moves
  double programmed = 0;  // mm/min
  double reached = 0;     // mm/min
  bool starved = false;
};

// Feed reached against programmed along the path; starved stretches in red.
std::string feed_svg(const std::vector<FeedSample>& samples, const std::string& title);

// One piece of the commanded path in the plane (arcs come as several), and its block's deviation.
struct DeviationSegment {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double deviation = 0;  // mm
  std::size_t block = 0;  // index of its block: an arc's pieces share it
};

// The path coloured by deviation (a scale in micrometres beside it) over the nominal curve in grey;
// with tolerance > 0, blocks beyond it are drawn thicker and counted. Axis names label the plane.
std::string deviation_svg(const std::vector<DeviationSegment>& path, const std::vector<std::array<double, 2>>& nominal,
                          double tolerance, const std::string& title, const std::string& subtitle,
                          const std::string& u_name, const std::string& v_name);

// Radial deviation against angle, magnified about the nominal circle, with rings in micrometres;
// the smallest radius marked by a ray when its angle means something, else said to mean nothing.
std::string polar_svg(const motion::CircleResult& r, const motion::CircleTest& test, const motion::CirclePlane& plane,
                      const std::string& subtitle);

}  // namespace ncurve::report
