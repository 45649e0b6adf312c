#include "report/motion_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "report/svg_text.hpp"

namespace ncurve::report {

namespace {
constexpr double kW = 900, kH = 420, kM = 60;

std::string header(double w, double h) {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n",
      w, h);
}

// A round step for about n ticks over span.
double nice_step(double span, int n) {
  double raw = span / n, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}
}  // namespace

std::string feed_svg(const std::vector<FeedSample>& samples, const std::string& title) {
  std::string s = header(kW, kH);
  s += fmt::format("<text x=\"{}\" y=\"24\" font-size=\"15\">{}</text>\n", kM, xml_escape(title));
  double len = samples.empty() ? 1 : std::max(samples.back().path, 1e-9);
  double vmax = 1;
  for (const auto& p : samples) vmax = std::max({vmax, p.programmed, p.reached});
  vmax *= 1.08;
  auto X = [&](double path) { return kM + (kW - 2 * kM) * path / len; };
  auto Y = [&](double v) { return kH - kM - (kH - 2 * kM) * v / vmax; };
  double xs = nice_step(len, 8), vs = nice_step(vmax, 6);
  for (double x = 0; x <= len + 1e-9; x += xs)
    s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/><text x=\"{0:.1f}\" "
                     "y=\"{3}\" text-anchor=\"middle\">{4:g}</text>\n",
                     X(x), kM, kH - kM, kH - kM + 16, x);
  for (double v = 0; v <= vmax; v += vs)
    s += fmt::format("<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"#ddd\"/><text x=\"{3}\" "
                     "y=\"{1:.1f}\" text-anchor=\"end\" dy=\"4\">{4:g}</text>\n",
                     kM, Y(v), kW - kM, kM - 6, v);
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">path length, mm</text>\n", kW / 2, kH - 18);
  s += fmt::format("<text x=\"16\" y=\"{}\" transform=\"rotate(-90 16 {})\" text-anchor=\"middle\">feed, mm/min</text>\n",
                   kH / 2, kH / 2);
  auto line = [&](auto value, const char* style) {
    std::string pts;
    for (const auto& p : samples) pts += fmt::format("{:.1f},{:.1f} ", X(p.path), Y(value(p)));
    return fmt::format("<polyline fill=\"none\" style=\"{}\" points=\"{}\"/>\n", style, pts);
  };
  s += line([](const FeedSample& p) { return p.programmed; }, "stroke:#999;stroke-dasharray:4 3");
  s += line([](const FeedSample& p) { return p.reached; }, "stroke:#1565c0;stroke-width:1.2");
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i].starved)
      s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#d32f2f\" stroke-width=\"2\"/>\n",
                       X(samples[i - 1].path), Y(samples[i - 1].reached), X(samples[i].path), Y(samples[i].reached));
  s += fmt::format("<text x=\"{}\" y=\"44\" fill=\"#999\">- - programmed feed</text><text x=\"{}\" y=\"44\" "
                   "fill=\"#1565c0\">— feed reached</text><text x=\"{}\" y=\"44\" fill=\"#d32f2f\">— starved (block "
                   "processing time)</text>\n",
                   kM, kM + 150, kM + 270);
  return s + "</svg>\n";
}

namespace {
// Blue (0) through green and yellow to red (1).
std::string heat(double f) {
  static constexpr double stops[5][3] = {{33, 102, 172}, {67, 170, 139}, {171, 221, 94}, {253, 174, 97}, {215, 48, 39}};
  f = std::clamp(f, 0.0, 1.0) * 4;
  int i = std::min(3, static_cast<int>(f));
  double g = f - i;
  auto c = [&](int k) { return static_cast<int>(std::lround(stops[i][k] + (stops[i + 1][k] - stops[i][k]) * g)); };
  return fmt::format("rgb({},{},{})", c(0), c(1), c(2));
}
}  // namespace

std::string deviation_svg(const std::vector<DeviationSegment>& path, const std::vector<std::array<double, 2>>& nominal,
                          double tolerance, const std::string& title, const std::string& subtitle,
                          const std::string& u_name, const std::string& v_name) {
  const double plot = 640, top = 60, left = 60, bar_x = left + plot + 40;
  std::string s = header(bar_x + 140, top + plot + 60);
  s += fmt::format("<text x=\"{}\" y=\"24\" font-size=\"15\">{}</text>\n", left, xml_escape(title));
  s += fmt::format("<text x=\"{}\" y=\"44\">{}</text>\n", left, xml_escape(subtitle));
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY, worst = 0;
  auto grow = [&](double x, double y) {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  };
  for (const auto& p : path) {
    grow(p.x0, p.y0), grow(p.x1, p.y1);
    worst = std::max(worst, p.deviation);
  }
  for (const auto& p : nominal) grow(p[0], p[1]);
  if (!std::isfinite(x0)) x0 = y0 = 0, x1 = y1 = 1;
  const double span = std::max({x1 - x0, y1 - y0, 1e-9}), k = plot / span;  // one scale on both axes
  auto X = [&](double x) { return left + (x - x0) * k + (plot - (x1 - x0) * k) / 2; };
  auto Y = [&](double y) { return top + plot - (y - y0) * k - (plot - (y1 - y0) * k) / 2; };
  // grid in mm
  const double g = nice_step(span, 6);
  for (double x = std::ceil(x0 / g) * g; x <= x1 + 1e-9; x += g)
    s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#eee\"/><text x=\"{0:.1f}\" "
                     "y=\"{3}\" text-anchor=\"middle\" font-size=\"10\">{4:g}</text>\n",
                     X(x), top, top + plot, top + plot + 14, x);
  for (double y = std::ceil(y0 / g) * g; y <= y1 + 1e-9; y += g)
    s += fmt::format("<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"#eee\"/><text x=\"{3}\" "
                     "y=\"{1:.1f}\" text-anchor=\"end\" dy=\"3\" font-size=\"10\">{4:g}</text>\n",
                     left, Y(y), left + plot, left - 4, y);
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}, mm (grid {:g} mm, equal scales)</text>\n",
                   left + plot / 2, top + plot + 32, xml_escape(u_name), g);
  s += fmt::format("<text x=\"20\" y=\"{0}\" transform=\"rotate(-90 20 {0})\" text-anchor=\"middle\">{1}, mm</text>\n",
                   top + plot / 2, xml_escape(v_name));
  std::string pts;
  for (const auto& p : nominal) pts += fmt::format("{:.2f},{:.2f} ", X(p[0]), Y(p[1]));
  s += fmt::format("<polyline fill=\"none\" stroke=\"#bbb\" stroke-width=\"5\" stroke-linecap=\"round\" points=\"{}\"/>\n", pts);
  const double scale = std::max(worst, tolerance > 0 ? tolerance : 0.0);
  std::size_t over = 0, blocks = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const auto& p = path[i];
    const bool beyond = tolerance > 0 && p.deviation > tolerance;
    const bool first = i == 0 || path[i - 1].block != p.block;
    blocks += first;
    over += beyond && first;
    s += fmt::format("<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"{}\" stroke-width=\"{}\" "
                     "stroke-linecap=\"round\"/>\n",
                     X(p.x0), Y(p.y0), X(p.x1), Y(p.y1), heat(scale > 0 ? p.deviation / scale : 0), beyond ? 4 : 2);
  }
  // colour scale in micrometres
  for (int i = 0; i < 100; ++i)
    s += fmt::format("<rect x=\"{}\" y=\"{:.1f}\" width=\"18\" height=\"{:.2f}\" fill=\"{}\"/>\n", bar_x,
                     top + plot - (i + 1) * plot / 100, plot / 100 + 0.5, heat((i + 0.5) / 100));
  const double um = scale * 1000, step = nice_step(std::max(um, 1e-6), 5);
  for (double v = 0; v <= um + 1e-9; v += step)
    s += fmt::format("<text x=\"{}\" y=\"{:.1f}\" dy=\"4\" font-size=\"10\">{:g} µm</text>\n", bar_x + 24,
                     top + plot - (um > 0 ? v / um : 0) * plot, v);
  if (tolerance > 0)
    s += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"black\" stroke-width=\"2\"/>"
                     "<text x=\"{}\" y=\"{:.1f}\" dy=\"4\" text-anchor=\"end\" font-size=\"10\">tolerance</text>\n",
                     bar_x - 4, top + plot - tolerance / scale * plot, bar_x + 22, top + plot - tolerance / scale * plot,
                     bar_x - 8, top + plot - tolerance / scale * plot);
  s += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"11\">deviation of each block</text>\n", bar_x - 10, top - 8);
  s += fmt::format("<text x=\"{}\" y=\"{}\">largest deviation {:.2f} µm{} · grey: the nominal curve · {} blocks</text>\n",
                   left, top + plot + 52, worst * 1000,
                   tolerance > 0 ? fmt::format(" · tolerance {:g} µm, {} blocks beyond it (thick)", tolerance * 1000, over) : "",
                   blocks);
  return s + "</svg>\n";
}

std::string polar_svg(const motion::CircleResult& r, const motion::CircleTest& test, const motion::CirclePlane& plane,
                      const std::string& subtitle) {
  const double size = 640, c = size / 2, R0 = 200;
  std::string s = header(size, size + 60);
  s += fmt::format("<text x=\"20\" y=\"24\" font-size=\"15\">Circular test: R {} mm, F {} mm/min, {}, {}{} plane</text>\n",
                   test.radius, test.feed, test.clockwise ? "CW" : "CCW", plane.p_name, plane.q_name);
  s += fmt::format("<text x=\"20\" y=\"44\">{}</text>\n", xml_escape(subtitle));
  double span = 0;
  for (const auto& [a, d] : r.polar) span = std::max(span, std::fabs(d));
  span = std::max(span, 1e-6);
  double ring = nice_step(span * 1000, 3) / 1000;  // mm between rings
  double scale = 100 / (std::ceil(span / ring) * ring);  // pixels per mm of deviation
  const double cy = c + 40;
  for (int k = -3; k <= 3; ++k) {
    double rr = R0 + k * ring * scale;
    if (rr <= 0) continue;
    s += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{:.1f}\" fill=\"none\" stroke=\"{}\"/>\n", c, cy, rr,
                     k == 0 ? "#888" : "#ddd");
    s += fmt::format("<text x=\"{:.1f}\" y=\"{}\" font-size=\"10\" fill=\"#666\">{:+g} µm</text>\n", c + rr + 2, cy - 2,
                     k * ring * 1000);
  }
  for (int a = 0; a < 360; a += 45) {
    double t = a * std::numbers::pi / 180;
    // the two axes' directions named at 0 and 90 degrees
    const std::string axis = a == 0 ? fmt::format(" +{}", plane.p_name) : a == 90 ? fmt::format(" +{}", plane.q_name) : "";
    s += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#eee\"/><text x=\"{:.1f}\" "
                     "y=\"{:.1f}\" text-anchor=\"middle\" font-size=\"10\">{}°{}</text>\n",
                     c, cy, c + 290 * std::cos(t), cy - 290 * std::sin(t), c + 300 * std::cos(t),
                     cy - 300 * std::sin(t) + 4, a, axis);
  }
  std::string pts;
  std::size_t stride = std::max<std::size_t>(1, r.polar.size() / 3600);
  for (std::size_t i = 0; i < r.polar.size(); i += stride) {
    auto [a, d] = r.polar[i];
    double t = a * std::numbers::pi / 180, rr = R0 + d * scale;
    pts += fmt::format("{:.1f},{:.1f} ", c + rr * std::cos(t), cy - rr * std::sin(t));
  }
  s += fmt::format("<polygon fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.5\" points=\"{}\"/>\n", pts);
  std::string angle;
  if (r.angle_meaningful) {
    // the smallest radius marked by a ray from the centre
    const double t = r.max_deviation_angle * std::numbers::pi / 180;
    s += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#d32f2f\" stroke-dasharray=\"5 3\"/>\n",
                     c, cy, c + 280 * std::cos(t), cy - 280 * std::sin(t));
    angle = fmt::format("smallest radius at {:.1f}° (red)", r.max_deviation_angle);
  } else {
    angle = fmt::format("{} and {} respond alike: the circle only shrinks, its smallest radius has no particular angle",
                        plane.p_name, plane.q_name);
  }
  s += fmt::format("<text x=\"20\" y=\"{}\">radius reduction {:.4f} mm · roundness {:.4f} mm · grey circle = nominal R, "
                   "rings every {:g} µm</text>\n",
                   size + 30, r.radius_reduction, r.roundness, ring * 1000);
  s += fmt::format("<text x=\"20\" y=\"{}\">{}</text>\n", size + 50, xml_escape(angle));
  return s + "</svg>\n";
}

}  // namespace ncurve::report
