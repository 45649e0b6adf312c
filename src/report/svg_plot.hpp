// The plotting layer every SVG of ncurve is drawn with: a page, panels with axes whose round tick
// steps and labels size the margins (so nothing is clipped), legends, and text always escaped.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ncurve::report::plot {

// A round step (1, 2 or 5 times a power of ten) giving about n intervals over span.
double nice_step(double span, int n);
// The multiples of a nice step for about n intervals that lie within [lo, hi] (hi >= lo).
std::vector<double> nice_ticks(double lo, double hi, int n);
// A tick value written with as many decimals as the step needs, no "-0".
std::string tick_label(double value, double step);
// Width in pixels of text in the sans-serif font at this size (an upper estimate, so margins hold).
double text_width(std::string_view text, double font_size);

// `text` in lines no wider than `width` at this font size, broken at spaces; a word wider than
// the width (a long file name) is broken after a / _ - . or the like, else where it has to be.
std::vector<std::string> wrap(std::string_view text, double width, double font_size);
// `text` on one line no wider than `width`: as it is when it fits, else its first and last
// characters about an ellipsis ("…").
std::string fit(std::string_view text, double width, double font_size);

// An SVG page: the header, a white background and the elements appended to it.
class Page {
public:
  Page(double width, double height);
  double width() const { return width_; }
  double height() const { return height_; }
  // Raw markup (the caller has escaped its text).
  void add(std::string_view markup) { body_ += markup; }
  // Escaped text at (x, y); anchor "start", "middle" or "end"; extra attributes as markup.
  void text(double x, double y, std::string_view text, std::string_view anchor = "start", double size = 12,
            std::string_view extra = "");
  // A title and an optional subtitle at the top left, wrapped to the page; returns the height they take.
  double heading(std::string_view title, std::string_view subtitle = "");
  std::string str() const;

private:
  double width_, height_;
  std::string body_;
};

// One axis of a panel: its data range and name; shown values are data * scale (a lathe's X as a
// diameter: 2, inches: 1 / 25.4), ticks round in shown units.
struct Axis {
  double lo = 0, hi = 1;
  std::string label;
  double scale = 1;
  int ticks = 6;
};

// Where a panel's data lands on the page.
struct Frame {
  double left = 0, top = 0, width = 1, height = 1;  // plotting area, px
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;           // data at its edges
  double x(double u) const { return left + (u - u0) / (u1 - u0) * width; }
  double y(double v) const { return top + height - (v - v0) / (v1 - v0) * height; }
  double px_per_unit() const { return width / (u1 - u0); }
};

// A panel in the box (x, y, w, h) of the page: an optional title above, axes with ticks, grid and
// labels, margins from the labels' sizes. With equal scales one data unit is as long on both axes
// (the ranges grow to fill the box, centred). Without ticks only the area and title are laid out.
struct Panel {
  double x = 0, y = 0, w = 400, h = 300;
  std::string title;
  Axis u, v;
  bool equal = false;
  bool grid = true;
  bool ticks = true;
};
Frame draw_panel(Page& page, const Panel& panel);

// Legend entries: a line sample (stroke, dash, width) or a marker, and its text.
struct LegendEntry {
  std::string label;
  std::string stroke = "#000";
  std::string dash;      // stroke-dasharray, empty: solid
  double width = 1.5;
  bool cross = false;    // a cross marker instead of a line
  bool dot = false;      // a dot instead of a line
};
// A legend in rows from (x, y) within max_width, a row wrapping when full and a text longer than
// the width wrapping within its entry; returns the height it took.
double draw_legend(Page& page, double x, double y, double max_width, const std::vector<LegendEntry>& entries);
// The height draw_legend takes for these entries in this width (to make room for it first).
double legend_height(double max_width, const std::vector<LegendEntry>& entries);

// A vertical colour scale in the box (x, y, width, height): its title wrapped above, the bar
// (colour(0) at the bottom, colour(1) at the top), tick labels beside it and an optional mark (a
// line across the bar, its label in bold). Labels never overlap: a tick label too near the mark's,
// or another tick's, is left out.
struct ColourScale {
  double x = 0, y = 0, width = 120, height = 300;
  std::string title;
  std::function<std::string(double)> colour;
  std::vector<std::pair<double, std::string>> ticks;  // position 0..1 on the bar, label
  std::optional<std::pair<double, std::string>> mark;
};
void draw_colour_scale(Page& page, const ColourScale& scale);

// A cross of size s at (x, y).
std::string cross(double x, double y, double s, std::string_view colour, double width = 2);

}  // namespace ncurve::report::plot
