// SVG plots of motion: feed along the path, and the circular test's polar deviation diagram.
#pragma once
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

// Radial deviation against angle, magnified about the nominal circle, with rings in micrometres.
std::string polar_svg(const motion::CircleResult& r, const motion::CircleTest& test, const std::string& subtitle);

}  // namespace ncurve::report
