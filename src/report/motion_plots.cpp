#include "report/motion_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncurve::report {

namespace {
constexpr double kW = 900, kH = 420, kM = 60;

std::string header(double w, double h) {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n",
      w, h);
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
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
  s += fmt::format("<text x=\"{}\" y=\"24\" font-size=\"15\">{}</text>\n", kM, escape(title));
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

std::string polar_svg(const motion::CircleResult& r, const motion::CircleTest& test, const std::string& subtitle) {
  const double size = 640, c = size / 2, R0 = 200;
  std::string s = header(size, size + 40);
  s += fmt::format("<text x=\"20\" y=\"24\" font-size=\"15\">Circular test: R {} mm, F {} mm/min, {}</text>\n",
                   test.radius, test.feed, test.clockwise ? "CW" : "CCW");
  s += fmt::format("<text x=\"20\" y=\"44\">{}</text>\n", escape(subtitle));
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
    s += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#eee\"/><text x=\"{:.1f}\" "
                     "y=\"{:.1f}\" text-anchor=\"middle\" font-size=\"10\">{}°</text>\n",
                     c, cy, c + 290 * std::cos(t), cy - 290 * std::sin(t), c + 300 * std::cos(t),
                     cy - 300 * std::sin(t) + 4, a);
  }
  std::string pts;
  std::size_t stride = std::max<std::size_t>(1, r.polar.size() / 3600);
  for (std::size_t i = 0; i < r.polar.size(); i += stride) {
    auto [a, d] = r.polar[i];
    double t = a * std::numbers::pi / 180, rr = R0 + d * scale;
    pts += fmt::format("{:.1f},{:.1f} ", c + rr * std::cos(t), cy - rr * std::sin(t));
  }
  s += fmt::format("<polygon fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.5\" points=\"{}\"/>\n", pts);
  s += fmt::format(
      "<text x=\"20\" y=\"{}\">radius reduction {:.4f} mm · roundness {:.4f} mm · smallest radius at {:.1f}° · grey "
      "circle = nominal R, rings every {:g} µm</text>\n",
      size + 30, r.radius_reduction, r.roundness, r.max_deviation_angle, ring * 1000);
  return s + "</svg>\n";
}

}  // namespace ncurve::report
