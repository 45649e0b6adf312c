// ncurve gen --plot: the curve, the path and the deviation along it, as one SVG.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "gen/generate.hpp"
#include "report/svg_text.hpp"

namespace ncurve::gen {
namespace {

constexpr double kWidth = 800, kShapeHeight = 560, kDevHeight = 200, kMargin = 50;

struct Box {
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  void add(double u, double v) {
    u0 = std::min(u0, u); u1 = std::max(u1, u);
    v0 = std::min(v0, v); v1 = std::max(v1, v);
  }
};

std::string polyline(const std::vector<std::pair<double, double>>& pts, const char* style) {
  std::string s = fmt::format("<polyline style=\"{}\" points=\"", style);
  for (const auto& [x, y] : pts) s += fmt::format("{:.2f},{:.2f} ", x, y);
  s += "\"/>\n";
  return s;
}

}  // namespace

std::string plot_svg(const geom::Curve& curve, const Options& o, const Stats& s) {
  const AxisMap map = axis_map(curve, o);
  const geom::Plane plane = plane_of(o.profile);
  const int u = plane.u_axis, v = plane.v_axis;
  constexpr int kCurveSamples = 2000;
  std::vector<geom::Vec3> exact;
  Box box;
  for (int i = 0; i <= kCurveSamples; ++i) {
    geom::Vec3 p = map(curve.point(curve.t0() + (curve.t1() - curve.t0()) * i / kCurveSamples));
    exact.push_back(p);
    box.add(p[u], p[v]);
  }
  for (const auto& p : s.path) box.add(p[u], p[v]);
  const double span = std::max({box.u1 - box.u0, box.v1 - box.v0, 1e-9});
  const double scale = std::min((kWidth - 2 * kMargin) / std::max(box.u1 - box.u0, 1e-9 * span),
                                (kShapeHeight - 2 * kMargin) / std::max(box.v1 - box.v0, 1e-9 * span));
  auto at = [&](const geom::Vec3& p) {
    return std::pair<double, double>{kMargin + (p[u] - box.u0) * scale, kShapeHeight - kMargin - (p[v] - box.v0) * scale};
  };
  const char* names = o.profile.lathe() ? "ZX" : "XY";
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      kWidth, kShapeHeight + kDevHeight + kMargin);
  svg += fmt::format(
      "<text x=\"{}\" y=\"20\">{} {}, tolerance {} mm: curve (grey), path (red, {} points), max deviation {:.4f} mm "
      "at t = {:.6g}</text>\n",
      kMargin, report::xml_escape(curve.name()), report::xml_escape(to_string(o.form)), o.tol, s.path.size(),
      s.max_deviation, s.worst_t);
  svg += fmt::format("<text x=\"{}\" y=\"{}\">{} {:.3f} .. {:.3f} mm, {} {:.3f} .. {:.3f} mm{}</text>\n", kMargin,
                     kShapeHeight - 15, names[0], box.u0, box.u1, names[1], box.v0, box.v1,
                     o.profile.lathe() ? " (X as a radius)" : "");
  std::vector<std::pair<double, double>> pts;
  for (const auto& p : exact) pts.push_back(at(p));
  svg += polyline(pts, "fill:none;stroke:#999;stroke-width:3");
  pts.clear();
  for (const auto& p : s.path) pts.push_back(at(p));
  svg += polyline(pts, "fill:none;stroke:#d22;stroke-width:1");
  if (s.path.size() <= 2000)
    for (const auto& [x, y] : pts) svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"1.5\" fill=\"#d22\"/>\n", x, y);
  const geom::Vec3 worst = s.worst_point;
  auto [wx, wy] = at(worst);
  svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"6\" fill=\"none\" stroke=\"#06c\"/>\n", wx, wy);

  // deviation along the curve: each move's largest, against the tolerance
  const double top = kShapeHeight + 10, height = kDevHeight - 30;
  const double dmax = std::max(o.tol, s.max_deviation) * 1.1;
  auto dev_at = [&](double t, double d) {
    return std::pair<double, double>{kMargin + (t - curve.t0()) / (curve.t1() - curve.t0()) * (kWidth - 2 * kMargin),
                                     top + height - d / dmax * height};
  };
  svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#ccc\"/>\n", kMargin,
                     top, kWidth - 2 * kMargin, height);
  auto [tx0, ty] = dev_at(curve.t0(), o.tol);
  svg += fmt::format(
      "<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"#d22\" stroke-dasharray=\"6,4\"/>\n", tx0,
      ty, kWidth - kMargin, ty);
  pts.clear();
  double t_prev = curve.t0();
  for (const auto& [t, d] : s.deviation) {  // a step per move
    pts.push_back(dev_at(t_prev, d));
    pts.push_back(dev_at(t, d));
    t_prev = t;
  }
  svg += polyline(pts, "fill:none;stroke:#06c;stroke-width:1");
  svg += fmt::format(
      "<text x=\"{}\" y=\"{}\">deviation per move (blue) against the tolerance {} mm (dashed), t {:.6g} .. {:.6g}</text>\n",
      kMargin, top + height + 18, o.tol, curve.t0(), curve.t1());
  svg += "</svg>\n";
  return svg;
}

}  // namespace ncurve::gen
