// ncurve gen --plot: the curve, the path and the deviation along it, as one SVG.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "gen/generate.hpp"
#include "report/svg_plot.hpp"

namespace ncurve::gen {
namespace {

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
  constexpr double W = 860, kShapeHeight = 560, kDevHeight = 230;
  std::vector<geom::Vec3> exact;
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  auto grow = [&](const geom::Vec3& p) {
    u0 = std::min(u0, p[u]), u1 = std::max(u1, p[u]), v0 = std::min(v0, p[v]), v1 = std::max(v1, p[v]);
  };
  for (int i = 0; i <= kCurveSamples; ++i) {
    geom::Vec3 p = map(curve.point(curve.t0() + (curve.t1() - curve.t0()) * i / kCurveSamples));
    exact.push_back(p);
    grow(p);
  }
  for (const auto& p : s.path) grow(p);
  const bool lathe = o.profile.lathe();
  const std::string title = fmt::format(
      "{} {}, tolerance {} mm: curve (grey), path (red, {} points), max deviation {:.4f} mm at t = {:.6g}", curve.name(),
      to_string(o.form), o.tol, s.path.size(), s.max_deviation, s.worst_t);
  // the page grows with the title's lines: a first page measures them
  double top = report::plot::Page(W, 1).heading(title);
  report::plot::Page page(W, top + kShapeHeight + kDevHeight);
  page.heading(title);

  // the curve and the path in the machine plane, equal scales
  report::plot::Panel shape;
  shape.x = 8, shape.y = top, shape.w = W - 16, shape.h = kShapeHeight;
  shape.u = {u0, u1, fmt::format("{}, mm", "XYZ"[u]), 1, 8};
  shape.v = {v0, v1, fmt::format("{}{}, mm", "XYZ"[v], lathe && v == 0 ? " (radius)" : ""), 1, 6};
  shape.equal = true;
  const report::plot::Frame f = report::plot::draw_panel(page, shape);
  auto at = [&](const geom::Vec3& p) { return std::pair<double, double>{f.x(p[u]), f.y(p[v])}; };
  std::vector<std::pair<double, double>> pts;
  for (const auto& p : exact) pts.push_back(at(p));
  std::string svg = polyline(pts, "fill:none;stroke:#999;stroke-width:3");
  pts.clear();
  for (const auto& p : s.path) pts.push_back(at(p));
  svg += polyline(pts, "fill:none;stroke:#d22;stroke-width:1");
  if (s.path.size() <= 2000)
    for (const auto& [x, y] : pts) svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"1.5\" fill=\"#d22\"/>\n", x, y);
  auto [wx, wy] = at(s.worst_point);
  svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"6\" fill=\"none\" stroke=\"#06c\"/>\n", wx, wy);
  page.add(svg);

  // deviation along the curve: each move's largest, against the tolerance
  report::plot::Panel dev;
  dev.x = 8, dev.y = top + kShapeHeight, dev.w = W - 16, dev.h = kDevHeight - 34;
  dev.title = "deviation per move (blue) against the tolerance (dashed red)";
  dev.u = {curve.t0(), curve.t1(), "curve parameter t", 1, 8};
  dev.v = {0, std::max(o.tol, s.max_deviation) * 1.05, "deviation, mm", 1, 4};
  const report::plot::Frame g = report::plot::draw_panel(page, dev);
  svg = fmt::format("<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"#d22\" stroke-dasharray=\"6,4\"/>\n",
                    g.left, g.y(o.tol), g.left + g.width, g.y(o.tol));
  pts.clear();
  double t_prev = curve.t0();
  for (const auto& [t, d] : s.deviation) {  // a step per move
    pts.push_back({g.x(t_prev), g.y(d)});
    pts.push_back({g.x(t), g.y(d)});
    t_prev = t;
  }
  svg += polyline(pts, "fill:none;stroke:#06c;stroke-width:1");
  page.add(svg);
  report::plot::draw_legend(page, 16, top + kShapeHeight + kDevHeight - 30, W - 32,
                            {{"curve", "#999", "", 3},
                             {"path", "#d22", "", 1},
                             {"worst point", "#06c", "", 1.5},
                             {fmt::format("tolerance {} mm", o.tol), "#d22", "6,4", 1}});
  return page.str();
}

}  // namespace ncurve::gen
