#include "report/lathe_part.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "report/backplot_data.hpp"

namespace ncurve::report {

using geom::V2;

namespace {

double distance_to_segment(V2 p, V2 a, V2 b) {
  const V2 d = b - a;
  const double len2 = geom::dot(d, d);
  const double t = len2 > 0 ? std::clamp(geom::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return geom::norm(p - (a + t * d));
}

// Marks the points of p[i..j] (exclusive ends) to keep, Douglas-Peucker, iteratively.
void simplify(const std::vector<V2>& p, std::size_t i, std::size_t j, double tolerance, std::vector<char>& keep) {
  std::vector<std::pair<std::size_t, std::size_t>> stack{{i, j}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double far = -1;
    std::size_t at = a;
    for (std::size_t k = a + 1; k < b; ++k) {
      const double d = distance_to_segment(p[k], p[a], p[b]);
      if (d > far) far = d, at = k;
    }
    if (far <= tolerance) continue;
    keep[at] = 1;
    stack.push_back({a, at});
    stack.push_back({at, b});
  }
}

}  // namespace

LathePart lathe_part(const sim::LatheSection& section, double tolerance) {
  LathePart part;
  const sim::Cylinder& stock = section.stock();
  part.radius = stock.diameter / 2;
  part.bore = std::max(stock.inner_diameter / 2, 0.0);
  const auto polygons = section.polygons();
  if (!(tolerance > 0)) {
    double lo_z = 0, hi_z = 0, hi_x = 0;
    bool first = true;
    for (const auto& p : polygons)
      for (const V2& v : p) {
        lo_z = first ? v.x : std::min(lo_z, v.x);
        hi_z = first ? v.x : std::max(hi_z, v.x);
        hi_x = std::max(hi_x, v.y);
        first = false;
      }
    tolerance = std::max(std::max(hi_z - lo_z, hi_x) / 5000, 1e-3);
  }
  for (const auto& p : polygons) {
    if (p.size() < 3) continue;
    // split the closed contour at its first point and the point farthest from it
    std::size_t far = 0;
    for (std::size_t k = 1; k < p.size(); ++k)
      if (geom::norm(p[k] - p[0]) > geom::norm(p[far] - p[0])) far = k;
    std::vector<V2> closed(p);
    closed.push_back(p[0]);
    std::vector<char> keep(closed.size(), 0);
    keep[0] = keep[far] = 1;
    simplify(closed, 0, far, tolerance, keep);
    simplify(closed, far, closed.size() - 1, tolerance, keep);
    std::vector<float>& out = part.contours.emplace_back();
    for (std::size_t k = 0; k + 1 < closed.size(); ++k)
      if (keep[k]) {
        out.push_back(static_cast<float>(closed[k].x));
        out.push_back(static_cast<float>(closed[k].y));
      }
    if (out.size() < 6) part.contours.pop_back();
  }
  return part;
}

nlohmann::json lathe_part_json(const LathePart& part) {
  nlohmann::json contours = nlohmann::json::array();
  for (const auto& c : part.contours) contours.push_back(base64(c.data(), c.size() * sizeof(float)));
  return {{"lathe", true}, {"radius", part.radius}, {"bore", part.bore}, {"contours", contours}};
}

}  // namespace ncurve::report
