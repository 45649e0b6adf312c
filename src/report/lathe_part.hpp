// A lathe's cut part as the pages take it: the half-section's contours (Z, X as a radius), thinned
// for drawing, which the page revolves about Z (web/backplot-part.js). docs/html.md.
#pragma once
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sim/lathe_section.hpp"

namespace ncurve::report {

struct LathePart {
  std::vector<std::vector<float>> contours;  // each z0, x0, z1, x1, ... (closed: the last joins the first)
  double radius = 0, bore = 0;               // the stock's outer and inner radius, mm
};

// The section's contours with every point dropped that lies within `tolerance` of the contour kept
// (Douglas-Peucker); `tolerance` 0: the section's extent / 5000, at least 1 um.
LathePart lathe_part(const sim::LatheSection& section, double tolerance = 0);

// {lathe: true, radius, bore, contours: [base64 of float32 z, x pairs]}.
nlohmann::json lathe_part_json(const LathePart& part);

}  // namespace ncurve::report
