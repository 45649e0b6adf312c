// The shared plotting layer (round ticks, labels, panels) and run --plot's drawing of known programs.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/path_plot.hpp"
#include "report/svg_plot.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using report::plot::nice_step;
using report::plot::nice_ticks;
using report::plot::tick_label;

namespace {

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// The texts of the elements of this class, in order.
std::vector<std::string> texts(const std::string& svg, const std::string& cls) {
  std::vector<std::string> out;
  std::regex re("class=\"" + cls + "\"[^>]*>([^<]*)<");
  for (std::sregex_iterator it(svg.begin(), svg.end(), re), end; it != end; ++it) out.push_back((*it)[1]);
  return out;
}

// The box of each text of the page, estimated as the layer does (0.62 em a character, 0.8 em above
// the baseline, 0.2 below), with its text; rotated texts are left out.
struct TextBox {
  double x0, y0, x1, y1;
  std::string text;
};
std::vector<TextBox> text_boxes(const std::string& svg) {
  std::vector<TextBox> out;
  std::regex re("<text ([^>]*)>([^<]*)</text>");
  auto attr = [](const std::string& attrs, const std::string& name, const std::string& otherwise) {
    std::smatch m;
    return std::regex_search(attrs, m, std::regex("(^| )" + name + "=\"([^\"]*)\"")) ? m[2].str() : otherwise;
  };
  for (std::sregex_iterator it(svg.begin(), svg.end(), re), end; it != end; ++it) {
    const std::string attrs = (*it)[1], body = (*it)[2];
    if (attrs.find("rotate(") != std::string::npos) continue;
    const double size = std::stod(attr(attrs, "font-size", "12"));
    const double x = std::stod(attr(attrs, "x", "0")), y = std::stod(attr(attrs, "y", "0")) + std::stod(attr(attrs, "dy", "0"));
    const double w = report::plot::text_width(body, size);
    const std::string anchor = attr(attrs, "text-anchor", "start");
    const double x0 = anchor == "middle" ? x - w / 2 : anchor == "end" ? x - w : x;
    out.push_back({x0, y - 0.8 * size, x0 + w, y + 0.2 * size, body});
  }
  return out;
}

// No two texts overlap (by more than a pixel) and each lies within [x0, x1] x [y0, y1].
void expect_apart_and_within(const std::string& svg, double x0, double y0, double x1, double y1) {
  const auto boxes = text_boxes(svg);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const auto& a = boxes[i];
    EXPECT_TRUE(a.x0 >= x0 - 0.5 && a.x1 <= x1 + 0.5 && a.y0 >= y0 - 0.5 && a.y1 <= y1 + 0.5)
        << "'" << a.text << "' at " << a.x0 << "," << a.y0 << ".." << a.x1 << "," << a.y1;
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const auto& b = boxes[j];
      EXPECT_FALSE(std::min(a.x1, b.x1) - std::max(a.x0, b.x0) > 1 && std::min(a.y1, b.y1) - std::max(a.y0, b.y0) > 1)
          << "'" << a.text << "' overlaps '" << b.text << "'";
    }
  }
}

struct Drawn {
  std::string svg;
  bool ok = true;
};

Drawn draw(const std::string& program, const machine::MachineProfile& profile, std::vector<report::PlotView> views,
           std::size_t limit = report::PathPlot::kDefaultLimit) {
  machine::ProgramLibrary lib;
  lib.add_text("p.nc", program, true);
  report::PathPlot plot(profile, limit);
  machine::Interpreter in(profile, lib);
  auto r = in.run(plot);
  if (r.alarm) plot.stopped(*r.alarm);
  report::PathPlotOptions o;
  o.views = std::move(views);
  o.title = "p.nc";
  return {plot.svg(o), r.ok()};
}

}  // namespace

// Ranges worked by hand: span / n rounded up to 1, 2 or 5 times a power of ten.
TEST(PlotLayer, NiceTicksOnHandWorkedRanges) {
  // 10 / 5 = 2 -> 2: 0, 2, ..., 10
  EXPECT_EQ(nice_ticks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  // 15.9 / 6 = 2.65 -> 5; multiples of 5 in [-3.7, 12.2]
  EXPECT_EQ(nice_ticks(-3.7, 12.2, 6), (std::vector<double>{0, 5, 10}));
  // 0.074 / 4 = 0.0185 -> 0.02
  auto small = nice_ticks(0.013, 0.087, 4);
  ASSERT_EQ(small.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(small[i], 0.02 * (i + 1), 1e-12);
  // 700 / 7 = 100 exactly: the step is 100, not 200
  EXPECT_DOUBLE_EQ(nice_step(700, 7), 100);
  // 94.5 / 8 = 11.8 -> 20; 64.8 / 8 = 8.1 -> 10; 3 / 8 = 0.375 -> 0.5
  EXPECT_DOUBLE_EQ(nice_step(94.5, 8), 20);
  EXPECT_DOUBLE_EQ(nice_step(64.8, 8), 10);
  EXPECT_DOUBLE_EQ(nice_step(3, 8), 0.5);
  EXPECT_EQ(nice_ticks(-1.2, -0.1, 4), (std::vector<double>{-1.0, -0.5}));  // 1.1 / 4 = 0.275 -> 0.5
  EXPECT_TRUE(nice_ticks(5, 1, 4).empty());
}

TEST(PlotLayer, TickLabelsCarryTheStepsDecimals) {
  EXPECT_EQ(tick_label(0.1 + 0.2, 0.1), "0.3");
  EXPECT_EQ(tick_label(1500, 500), "1500");
  EXPECT_EQ(tick_label(-1e-17, 0.5), "0.0");  // no "-0"
  EXPECT_EQ(tick_label(0.025, 0.005), "0.025");
}

TEST(PlotLayer, PanelLabelsAreEscapedAndInsideThePage) {
  report::plot::Page page(400, 300);
  report::plot::Panel p;
  p.x = 0, p.y = 0, p.w = 400, p.h = 300;
  p.u = {0, 1000, "a<b & c", 1, 6};
  p.v = {-123456, 0, "v", 1, 6};
  auto f = report::plot::draw_panel(page, p);
  const std::string svg = page.str();
  EXPECT_NE(svg.find("a&lt;b &amp; c"), std::string::npos);
  // the longest v label, "-120000", fits left of the frame
  EXPECT_GT(f.left, report::plot::text_width("-120000", 11));
  EXPECT_LE(f.left + f.width, 400);
  EXPECT_LE(f.top + f.height, 300 - 11);
}

// Entries of every length in 300 px: rows wrap, a text longer than the width wraps within its
// entry, and the height returned covers every line.
TEST(PlotLayer, LegendEntriesNeverOverlapOrPassTheirWidth) {
  report::plot::Page page(400, 400);
  std::vector<report::plot::LegendEntry> entries;
  for (const char* label : {"rapid", "a somewhat longer entry", "tolerance",
                            "an entry far longer than the legend is wide, so that it has to wrap onto lines of its own",
                            "x", "deviation of each block", "end"}) {
    report::plot::LegendEntry e;
    e.label = label;
    entries.push_back(e);
  }
  const double h = report::plot::draw_legend(page, 50, 20, 300, entries);
  EXPECT_DOUBLE_EQ(h, report::plot::legend_height(300, entries));
  expect_apart_and_within(page.str(), 50, 20, 350, 20 + h);
  EXPECT_EQ(text_boxes(page.str()).size(), 7u + 2);  // the long entry on three lines
}

// A 130-character path without a space: wrapped after its slashes and underscores, each line
// within the width; a word with no separator at all is cut where it has to be; fit keeps both ends.
TEST(PlotLayer, LongWordsWrapAndLongLabelsShorten) {
  using report::plot::text_width;
  const std::string path = "/home/someone/projects/customer_parts_2026/turbine_blade_roughing_operation_"
                           "number_twelve_final_revision_c_checked_by_quality.nc";
  ASSERT_GT(path.size(), 120u);
  auto lines = report::plot::wrap("run of " + path, 300, 15);
  ASSERT_GE(lines.size(), 3u);
  std::string joined;
  for (const auto& l : lines) {
    EXPECT_LE(text_width(l, 15), 300) << l;
    joined += l;
  }
  EXPECT_EQ(joined, "run of" + path);  // nothing lost but the space the first break took
  for (std::size_t i = 1; i + 1 < lines.size(); ++i)  // the path broken after its separators
    EXPECT_NE(std::string("/_").find(lines[i].back()), std::string::npos) << lines[i];
  for (const auto& l : report::plot::wrap(std::string(200, 'x'), 100, 12)) EXPECT_LE(text_width(l, 12), 100);
  const std::string short_ = report::plot::fit(path, 200, 12);
  EXPECT_LE(text_width(short_, 12), 200);
  EXPECT_EQ(short_.substr(0, 5), "/home");
  EXPECT_EQ(short_.substr(short_.size() - 3), ".nc");
  EXPECT_NE(short_.find("…"), std::string::npos);
  EXPECT_EQ(report::plot::fit("fits", 200, 12), "fits");
}

// A file name of 130 characters as the title and a long axis label: every text within the page.
TEST(PlotLayer, LongTitlesStayOnThePage) {
  report::plot::Page page(500, 400);
  const std::string name(130, 'n');
  const double top = page.heading(name + ".nc: feed along the path", "a subtitle " + name);
  report::plot::Panel p;
  p.x = 0, p.y = top, p.w = 500, p.h = 400 - top;
  p.title = "panel " + name;
  p.u = {0, 10, "u " + name, 1, 6};
  p.v = {0, 10, "v", 1, 6};
  report::plot::draw_panel(page, p);
  expect_apart_and_within(page.str(), 0, 0, 500, 400);
}

// A mark at the top of the scale where a tick's label also is: the mark's label is written, the
// tick's left out, and the title wraps to the scale's width above the bar.
TEST(PlotLayer, ColourScaleLabelsDoNotCollide) {
  report::plot::Page page(300, 400);
  report::plot::ColourScale s;
  s.x = 150, s.y = 10, s.width = 120, s.height = 380;
  s.title = "deviation of each block along the path";
  s.colour = [](double) { return std::string("#888"); };
  for (int i = 0; i <= 5; ++i) s.ticks.push_back({i / 5.0, fmt::format("{} µm", i)});
  s.ticks.push_back({0.99, "close"});
  s.mark = {{1.0, "tolerance 5 µm"}};
  report::plot::draw_colour_scale(page, s);
  const std::string svg = page.str();
  expect_apart_and_within(svg, 150, 10, 270, 390);
  EXPECT_NE(svg.find(">tolerance 5 µm<"), std::string::npos);
  EXPECT_EQ(svg.find(">5 µm<"), std::string::npos);
  EXPECT_EQ(svg.find(">close<"), std::string::npos);
  EXPECT_NE(svg.find(">4 µm<"), std::string::npos);
}

// G17 mill program; the moves (from X0 Y0 Z0):
//   rapids: Z5, Z1 (back along the same line: not merged), Z5 at the end          -> 3
//   feeds:  Z-1; X40 and X60 (collinear, merged into one); Y40                   -> 3
//   arcs:   G03 to X80 Y20 about (60,20); G02 to X60 Y60 about (80,60)             -> 2
// In the XY view both arcs face the viewer: SVG arcs ("A"); in XZ they are sampled lines.
// Extents X 0..80, Y 0..60, padded 4 %: the XY panel (about 880 x 600 px) has the scale of
// Y's 64.8 mm over 600 px, so X spans about 95 mm: X step 94.5 / 8 -> 20 (ticks 0..80), Y step
// 64.8 / 8 -> 10 (ticks 0..60).
const char* kMill = R"(G21 G17 G90
G00 X0 Y0 Z5.
G00 Z1.
G01 Z-1. F100.
G01 X40.
G01 X60.
G03 X80. Y20. R20.
G01 Y40.
G02 X60. Y60. R20.
G00 Z5.
M30
)";

TEST(PathPlot, CountsEachKindOfElement) {
  auto d = draw(kMill, test::zero_offset_mill(), {report::PlotView::xy});
  ASSERT_TRUE(d.ok);
  EXPECT_EQ(count(d.svg, "class=\"rapid\""), 3u);
  EXPECT_EQ(count(d.svg, "class=\"feed\""), 3u);
  EXPECT_EQ(count(d.svg, "class=\"arc\""), 2u);
  std::regex arc_path("class=\"arc\" d=\"M[-0-9.,]+A");
  EXPECT_EQ(std::distance(std::sregex_iterator(d.svg.begin(), d.svg.end(), arc_path), std::sregex_iterator()), 2);
  EXPECT_NE(d.svg.find("stroke-dasharray=\"6 4\""), std::string::npos);  // rapids dashed
  EXPECT_EQ(count(d.svg, "class=\"marker\""), 0u);                      // no alarm
}

TEST(PathPlot, AxesOfTheMillPlane) {
  auto d = draw(kMill, test::zero_offset_mill(), {report::PlotView::xy});
  EXPECT_EQ(texts(d.svg, "tick-u"), (std::vector<std::string>{"0", "20", "40", "60", "80"}));
  EXPECT_EQ(texts(d.svg, "tick-v"), (std::vector<std::string>{"0", "10", "20", "30", "40", "50", "60"}));
  EXPECT_EQ(texts(d.svg, "label-u"), (std::vector<std::string>{"X, mm"}));
  EXPECT_EQ(texts(d.svg, "label-v"), (std::vector<std::string>{"Y, mm"}));
}

TEST(PathPlot, ArcsOutOfTheirPlaneAreSampled) {
  auto d = draw(kMill, machine::default_mill(), {report::PlotView::xz});
  EXPECT_EQ(count(d.svg, "class=\"arc\""), 2u);
  std::regex arc_path("class=\"arc\" d=\"M[^\"]*A");
  EXPECT_FALSE(std::regex_search(d.svg, arc_path));
  EXPECT_EQ(texts(d.svg, "label-v"), (std::vector<std::string>{"Z, mm"}));
}

TEST(PathPlot, FourViewsByDefault) {
  auto d = draw(kMill, machine::default_mill(), {});
  EXPECT_EQ(count(d.svg, "class=\"view\""), 4u);
  EXPECT_EQ(count(d.svg, "class=\"arc\""), 8u);
  EXPECT_NE(d.svg.find(">isometric<"), std::string::npos);
  EXPECT_EQ(texts(d.svg, "label-u"), (std::vector<std::string>{"X, mm", "X, mm", "Y, mm"}));
}

TEST(PathPlot, TheAlarmBlockIsMarked) {
  auto d = draw("G00 X10. Y5.\nG01 X20. F100.\n#3000=7 (NO DEPTH)\nG01 X30.\nM30\n", machine::default_mill(),
                {report::PlotView::xy});
  ASSERT_FALSE(d.ok);
  EXPECT_EQ(count(d.svg, "class=\"marker\""), 2u);  // on the path and in the legend
  EXPECT_EQ(texts(d.svg, "alarm"), (std::vector<std::string>{"MC3007 line 3"}));
  auto notes = texts(d.svg, "note");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("MC3007"), std::string::npos);
  EXPECT_NE(notes[0].find("NO DEPTH"), std::string::npos);
  EXPECT_EQ(count(d.svg, "class=\"feed\""), 1u);  // X30 was never reached
}

// Lathe (X as a diameter): from X0 Z0, rapid to X40 (radius 20) Z5, turn to Z-30, face to X60,
// rapid to X80 Z5. Z -30..5 across, X radius 0..40 up, shown as diameters 0..80: padded 4 %, the
// diameter axis spans 86.4 -> step 20 (0..80); the Z axis widens to the panel's aspect, about
// 63 mm -> step 10 (-40..10).
TEST(PathPlot, LatheDrawsZAcrossAndXUpAsDiameter) {
  auto d = draw("G00 X40. Z5.\nG01 Z-30. F0.2\nG01 X60.\nG00 X80. Z5.\nM30\n", machine::default_lathe(), {});
  ASSERT_TRUE(d.ok);
  EXPECT_EQ(count(d.svg, "class=\"view\""), 1u);
  EXPECT_EQ(texts(d.svg, "label-u"), (std::vector<std::string>{"Z, mm"}));
  EXPECT_EQ(texts(d.svg, "label-v"), (std::vector<std::string>{"X (diameter), mm"}));
  // the lathe's home (X0 Z0 here) is where it stood before the program: not framed. The cuts' X
  // goes from 40 to 60 on the diameter, Z from 5 to -30 with the approach to Z5 (diagonal 36.4 mm
  // on the radius); the retract to X80 (radius 40) is more than a quarter of it (9.1 mm) beyond
  // the cuts' radius 30: cut off at the panel's edge, not framed
  EXPECT_EQ(texts(d.svg, "tick-v"), (std::vector<std::string>{"30", "40", "50", "60", "70"}));
  EXPECT_EQ(texts(d.svg, "tick-u"), (std::vector<std::string>{"-30", "-25", "-20", "-15", "-10", "-5", "0", "5"}));
}

// A lathe moves in ZX: the views of Y do not fit it (a view asked for anyway draws ZX), unless
// the profile has a Y axis.
TEST(PathPlot, ALatheWithoutYHasTheZXViewOnly) {
  auto lathe = machine::default_lathe();
  for (auto v : {report::PlotView::xy, report::PlotView::yz, report::PlotView::iso})
    EXPECT_FALSE(report::view_fits(lathe, v));
  EXPECT_TRUE(report::view_fits(lathe, report::PlotView::xz));
  EXPECT_TRUE(report::view_fits(machine::default_mill(), report::PlotView::iso));
  auto d = draw("G00 X40. Z5.\nG01 Z-30. F0.2\nM30\n", lathe, {report::PlotView::xy});
  EXPECT_EQ(texts(d.svg, "label-u"), (std::vector<std::string>{"Z, mm"}));
  auto with_y = lathe;
  with_y.axes = "XYZ";
  EXPECT_TRUE(report::view_fits(with_y, report::PlotView::xy));
  d = draw("G00 X40. Z5.\nG01 Z-30. F0.2\nM30\n", with_y, {report::PlotView::xy});
  EXPECT_EQ(texts(d.svg, "label-v"), (std::vector<std::string>{"Y, mm"}));
  EXPECT_EQ(d.svg.find("Z across"), std::string::npos);
}

// The views are of X, Y and Z: a rotary A axis the run turned is named under the title with its
// range; one that stayed at 0 (or a machine without one) is not mentioned.
TEST(PathPlot, ARotaryAxisNotDrawnIsSaid) {
  auto profile = machine::default_mill();
  profile.axes = "XYZA";
  profile.rotary[3].rotary = true;
  auto d = draw("G01 X10. A90. F100.\nA360.\nX0 A-45.\nM30\n", profile, {report::PlotView::xy});
  EXPECT_EQ(texts(d.svg, "not-drawn"),
            (std::vector<std::string>{"A axis not drawn: -45 to 360 deg (the views show X, Y and Z)"}));
  expect_apart_and_within(d.svg, 0, 0, 960, 760);
  EXPECT_TRUE(texts(draw("G01 X10. F100.\nM30\n", profile, {}).svg, "not-drawn").empty());
  EXPECT_TRUE(texts(draw(kMill, machine::default_mill(), {}).svg, "not-drawn").empty());
}

TEST(PathPlot, LatheInRadiusSaysSo) {
  auto p = machine::default_lathe();
  p.diameter_x = false;
  auto d = draw("G00 X40. Z5.\nG01 Z-30. F0.2\nM30\n", p, {});
  EXPECT_EQ(texts(d.svg, "label-v"), (std::vector<std::string>{"X (radius), mm"}));
}

TEST(PathPlot, MemoryStaysBounded) {
  std::string program = "G01 F100.\n";
  for (int i = 1; i <= 1000; ++i) program += fmt::format("X{}.\n", i);  // collinear: one element
  // a zigzag of 500 mm: 100 elements, too wide for any simplification (at most 1/250 of the extent)
  for (int i = 1; i <= 100; ++i) program += fmt::format("Y{}.\n", 500 * (i % 2));
  program += "M30\n";
  machine::ProgramLibrary lib;
  lib.add_text("p.nc", program, true);
  auto profile = test::zero_offset_mill();
  report::PathPlot plot(profile, 20);
  machine::Interpreter in(profile, lib);
  ASSERT_TRUE(in.run(plot).ok());
  EXPECT_EQ(plot.elements().size(), 20u);
  EXPECT_DOUBLE_EQ(plot.elements()[0].b[0], 1000);
  report::PathPlotOptions o;
  auto notes = texts(plot.svg(o), "note");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes.back().find("only the first 20 elements are drawn: 81 more moves"), std::string::npos);
}

// 2000 chords of 0.18 degrees on a circle of radius 100 mm (sag 0.12 um), limit 100: simplified,
// the drawing keeps every programmed point within the bound it reports, under twice the largest
// tolerance, 1/250 of the extent's diagonal (2 x 200 sqrt 2 / 250 = 2.26 mm), and the note says so.
TEST(PathPlot, DenseRunsAreSimplifiedWithinTheirTolerance) {
  std::string program = "G00 X100. Y0.\nG01 F100.\n";
  std::vector<std::array<double, 2>> points;
  for (int i = 1; i <= 2000; ++i) {
    const double t = i * 0.18 * 3.14159265358979 / 180;
    points.push_back({std::round(100000 * std::cos(t)) / 1000, std::round(100000 * std::sin(t)) / 1000});
    program += fmt::format("X{:.3f} Y{:.3f}\n", points.back()[0], points.back()[1]);
  }
  program += "M30\n";
  machine::ProgramLibrary lib;
  lib.add_text("p.nc", program, true);
  auto profile = machine::default_mill();
  report::PathPlot plot(profile, 100);
  machine::Interpreter in(profile, lib);
  ASSERT_TRUE(in.run(plot).ok());
  const double tol = plot.simplified_within();
  EXPECT_GT(tol, 0);
  EXPECT_LE(tol, 2 * 200 * std::sqrt(2.0) / 250);
  EXPECT_LE(plot.elements().size(), 100u);
  for (const auto& p : points) {
    double best = INFINITY;
    for (const auto& e : plot.elements()) {
      if (e.kind != machine::MoveKind::line) continue;
      const double dx = e.b[0] - e.a[0], dy = e.b[1] - e.a[1], dd = dx * dx + dy * dy;
      const double t = dd > 0 ? std::clamp(((p[0] - e.a[0]) * dx + (p[1] - e.a[1]) * dy) / dd, 0.0, 1.0) : 0;
      best = std::min(best, std::hypot(p[0] - e.a[0] - t * dx, p[1] - e.a[1] - t * dy));
    }
    ASSERT_LE(best, tol + 1e-9) << p[0] << "," << p[1];
  }
  auto notes = texts(plot.svg({}), "note");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("simplified"), std::string::npos);
}
