#include "report/motion_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "report/svg_plot.hpp"
#include "report/svg_text.hpp"

namespace ncurve::report {

std::string feed_svg(const std::vector<FeedSample>& samples, const std::string& title) {
  plot::Page page(900, 440);
  const double top = page.heading(title);
  double len = samples.empty() ? 1 : std::max(samples.back().path, 1e-9);
  double vmax = 1;
  for (const auto& p : samples) vmax = std::max({vmax, p.programmed, p.reached});
  plot::Panel panel;
  panel.x = 8, panel.y = top, panel.w = 884, panel.h = 440 - top - 30;
  panel.u = {0, len, "path length, mm", 1, 8};
  panel.v = {0, vmax * 1.04, "feed, mm/min", 1, 6};
  const plot::Frame f = plot::draw_panel(page, panel);
  auto line = [&](auto value, const char* style) {
    std::string pts;
    for (const auto& p : samples) pts += fmt::format("{:.1f},{:.1f} ", f.x(p.path), f.y(value(p)));
    return fmt::format("<polyline fill=\"none\" style=\"{}\" points=\"{}\"/>\n", style, pts);
  };
  std::string s = line([](const FeedSample& p) { return p.programmed; }, "stroke:#999;stroke-dasharray:4 3");
  s += line([](const FeedSample& p) { return p.reached; }, "stroke:#1565c0;stroke-width:1.2");
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i].starved)
      s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#d32f2f\" stroke-width=\"2\"/>\n",
                       f.x(samples[i - 1].path), f.y(samples[i - 1].reached), f.x(samples[i].path), f.y(samples[i].reached));
  page.add(s);
  plot::draw_legend(page, 16, 440 - 26, 870,
                    {{"programmed feed", "#999", "4 3", 1.5},
                     {"feed reached", "#1565c0", "", 1.5},
                     {"starved (block processing time)", "#d32f2f", "", 2}});
  return page.str();
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
  const double W = 920, H = 800, bar_w = 150;
  plot::Page page(W, H);
  const double top = page.heading(title, subtitle);
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
  // the summary under the drawing, wrapped to the page
  std::size_t over = 0, blocks = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const bool first = i == 0 || path[i - 1].block != path[i].block;
    blocks += first;
    over += first && tolerance > 0 && path[i].deviation > tolerance;
  }
  const auto notes = plot::wrap(
      fmt::format("largest deviation {:.2f} µm{} · grey: the nominal curve · {} blocks", worst * 1000,
                  tolerance > 0 ? fmt::format(" · tolerance {:g} µm, {} blocks beyond it (thick)", tolerance * 1000, over) : "",
                  blocks),
      W - 32, 12);
  const double notes_h = 16 * static_cast<double>(notes.size());
  plot::Panel panel;  // one scale on both axes
  panel.x = 8, panel.y = top, panel.w = W - bar_w - 16, panel.h = H - top - 14 - notes_h;
  panel.u = {x0, x1, u_name + ", mm", 1, 6};
  panel.v = {y0, y1, v_name + ", mm", 1, 6};
  panel.equal = true;
  const plot::Frame f = plot::draw_panel(page, panel);
  std::string s;
  std::string pts;
  for (const auto& p : nominal) pts += fmt::format("{:.2f},{:.2f} ", f.x(p[0]), f.y(p[1]));
  s += fmt::format("<polyline fill=\"none\" stroke=\"#bbb\" stroke-width=\"5\" stroke-linecap=\"round\" points=\"{}\"/>\n", pts);
  const double scale = std::max(worst, tolerance > 0 ? tolerance : 0.0);
  for (const auto& p : path) {
    const bool beyond = tolerance > 0 && p.deviation > tolerance;
    s += fmt::format("<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"{}\" stroke-width=\"{}\" "
                     "stroke-linecap=\"round\"/>\n",
                     f.x(p.x0), f.y(p.y0), f.x(p.x1), f.y(p.y1), heat(scale > 0 ? p.deviation / scale : 0), beyond ? 4 : 2);
  }
  page.add(s);
  // colour scale in micrometres, beside the panel
  plot::ColourScale bar;
  bar.x = W - bar_w + 4, bar.y = f.top, bar.width = bar_w - 12, bar.height = f.height;
  bar.title = "deviation of each block";
  bar.colour = heat;
  const double um = std::max(scale * 1000, 1e-6), step = plot::nice_step(um, 5);
  for (double v : plot::nice_ticks(0, um, 5)) bar.ticks.push_back({v / um, plot::tick_label(v, step) + " µm"});
  if (tolerance > 0) bar.mark = {{tolerance / scale, fmt::format("tolerance {:g} µm", tolerance * 1000)}};
  plot::draw_colour_scale(page, bar);
  for (std::size_t i = 0; i < notes.size(); ++i) page.text(16, H - 10 - 16 * static_cast<double>(notes.size() - 1 - i), notes[i]);
  return page.str();
}

std::string polar_svg(const motion::CircleResult& r, const motion::CircleTest& test, const motion::CirclePlane& plane,
                      const std::string& subtitle) {
  // the nominal circle R0 px, the deviation's rings within R0 +- 100 px, angle labels outside them
  constexpr double R0 = 200, band = 100, label_r = R0 + band + 22;
  const std::string axis_p = fmt::format("+{}", plane.p_name), axis_q = fmt::format("+{}", plane.q_name);
  double span = 0;
  for (const auto& [a, d] : r.polar) span = std::max(span, std::fabs(d));
  span = std::max(span, 1e-6);
  const double ring = plot::nice_step(span * 1000, 3) / 1000;  // mm between rings
  const int rings = std::max(1, static_cast<int>(std::ceil(span / ring - 1e-9)));
  const double scale = band / (rings * ring);  // pixels per mm of deviation
  const std::string title = fmt::format("Circular test: R {} mm, F {} mm/min, {}, {}{} plane", test.radius, test.feed,
                                        test.clockwise ? "CW" : "CCW", plane.p_name, plane.q_name);
  const std::string numbers = fmt::format("radius reduction {:.4f} mm · roundness {:.4f} mm · grey circle = nominal R, "
                                          "rings every {} µm",
                                          r.radius_reduction, r.roundness, plot::tick_label(ring * 1000, ring * 1000));
  const std::string angle =
      r.angle_meaningful
          ? fmt::format("smallest radius at {:.1f}° (red)", r.max_deviation_angle)
          : fmt::format("{} and {} respond alike: the circle only shrinks, its smallest radius has no particular angle",
                        plane.p_name, plane.q_name);
  // wide enough for the rings with their angle labels and for every line of text
  const double side = label_r + plot::text_width("180°", 11) + 12;
  double W = 2 * side + 16;
  for (const auto* t : {&title, &subtitle, &numbers, &angle})
    W = std::max(W, plot::text_width(*t, t == &title ? 15 : 12) + 32);
  const double top = 52, c = W / 2, cy = top + side, H = cy + side + 50;
  plot::Page page(W, H);
  page.heading(title, subtitle);
  std::string s;
  for (int k = -rings; k <= rings; ++k) {
    const double rr = R0 + k * ring * scale;
    s += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" fill=\"none\" stroke=\"{}\"/>\n", c, cy, rr,
                     k == 0 ? "#888" : "#ddd");
    // ring labels up the vertical ray, just inside each ring
    s += fmt::format("<text class=\"ring\" x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#666\">{}{} µm</text>\n",
                     c + 3, cy - rr + 11, k > 0 ? "+" : "", plot::tick_label(k * ring * 1000, ring * 1000));
  }
  for (int a = 0; a < 360; a += 45) {
    const double t = a * std::numbers::pi / 180;
    // the two axes' directions named at 0 and 90 degrees
    const std::string axis = a == 0 ? " " + axis_p : a == 90 ? " " + axis_q : "";
    const double lx = c + label_r * std::cos(t), ly = cy - label_r * std::sin(t) + 4;
    const char* anchor = std::fabs(std::cos(t)) < 0.3 ? "middle" : std::cos(t) > 0 ? "start" : "end";
    s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#eee\"/><text x=\"{:.1f}\" "
                     "y=\"{:.1f}\" text-anchor=\"{}\" font-size=\"11\">{}°{}</text>\n",
                     c, cy, c + (R0 + band + 8) * std::cos(t), cy - (R0 + band + 8) * std::sin(t),
                     lx, ly, anchor,
                     a, xml_escape(axis));
  }
  std::string pts;
  const std::size_t stride = std::max<std::size_t>(1, r.polar.size() / 3600);
  for (std::size_t i = 0; i < r.polar.size(); i += stride) {
    auto [a, d] = r.polar[i];
    const double t = a * std::numbers::pi / 180, rr = R0 + d * scale;
    pts += fmt::format("{:.1f},{:.1f} ", c + rr * std::cos(t), cy - rr * std::sin(t));
  }
  s += fmt::format("<polygon fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.5\" points=\"{}\"/>\n", pts);
  if (r.angle_meaningful) {
    // the smallest radius marked by a ray from the centre
    const double t = r.max_deviation_angle * std::numbers::pi / 180;
    s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#d32f2f\" stroke-dasharray=\"5 3\"/>\n",
                     c, cy, c + (R0 + band) * std::cos(t), cy - (R0 + band) * std::sin(t));
  }
  page.add(s);
  page.text(16, H - 30, numbers);
  page.text(16, H - 12, angle);
  return page.str();
}

}  // namespace ncurve::report
