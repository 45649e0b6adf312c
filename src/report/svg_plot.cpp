#include "report/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/svg_text.hpp"

namespace ncurve::report::plot {

namespace {
constexpr double kTickFont = 11, kLabelFont = 12, kTitleFont = 13;
}

double nice_step(double span, int n) {
  if (!(span > 0) || !std::isfinite(span)) return 1;
  const double raw = span / std::max(n, 1), p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw * (1 - 1e-9)) return m * p;
  return 10 * p;
}

std::vector<double> nice_ticks(double lo, double hi, int n) {
  std::vector<double> out;
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo) return out;
  const double step = nice_step(hi - lo, n), eps = step * 1e-9;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps && out.size() < 100; ++k) {
    const double v = k * step;
    out.push_back(std::fabs(v) < eps ? 0.0 : v);
  }
  return out;
}

std::string tick_label(double value, double step) {
  const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 9);
  std::string s = fmt::format("{:.{}f}", value, decimals);
  if (s.find_first_not_of("-0.") == std::string::npos) s = decimals ? fmt::format("{:.{}f}", 0.0, decimals) : "0";
  return s;
}

double text_width(std::string_view text, double font_size) {
  std::size_t chars = 0;
  for (unsigned char c : text) chars += (c & 0xC0) != 0x80;  // code points of UTF-8
  return static_cast<double>(chars) * font_size * 0.62;
}

Page::Page(double width, double height) : width_(width), height_(height) {}

void Page::text(double x, double y, std::string_view t, std::string_view anchor, double size, std::string_view extra) {
  body_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\"{}{}{}{}>{}</text>\n", x, y,
                       anchor == "start" ? "" : fmt::format(" text-anchor=\"{}\"", anchor),
                       size == 12 ? "" : fmt::format(" font-size=\"{:g}\"", size), extra.empty() ? "" : " ", extra,
                       xml_escape(t));
}

namespace {

// The byte offset after the first n code points of text (its size if it has fewer).
std::size_t after_chars(std::string_view text, std::size_t n) {
  std::size_t at = 0;
  for (; at < text.size(); ++at)
    if ((static_cast<unsigned char>(text[at]) & 0xC0) != 0x80 && n-- == 0) break;
  return at;
}

// How many characters of this size fit in width (at least one).
std::size_t chars_in(double width, double size) {
  return static_cast<std::size_t>(std::max(1.0, std::floor(width / (size * 0.62) + 1e-9)));
}

// A word wider than width in pieces that fit: each ends after a separator of a path or name when
// one lets it take at least half the width, else after as many characters as fit.
std::vector<std::string> split_word(std::string_view word, double width, double size) {
  std::vector<std::string> out;
  const std::size_t n = chars_in(width, size);
  while (text_width(word, size) > width) {
    std::size_t cut = after_chars(word, n);
    for (std::size_t k = n; k > n / 2; --k) {
      const std::size_t end = after_chars(word, k);
      if (std::string_view("/\\_-.,;:").find(word[end - 1]) != std::string_view::npos) {
        cut = end;
        break;
      }
    }
    out.emplace_back(word.substr(0, cut));
    word.remove_prefix(cut);
  }
  out.emplace_back(word);
  return out;
}

}  // namespace

std::vector<std::string> wrap(std::string_view text, double width, double size) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t end = text.find(' ', at);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(at, end - at);
    if (!line.empty() && text_width(line, size) + text_width(word, size) + size * 0.3 > width) {
      lines.push_back(line);
      line.clear();
    }
    if (line.empty() && text_width(word, size) > width) {  // a word of lines of its own
      auto pieces = split_word(word, width, size);
      lines.insert(lines.end(), pieces.begin(), pieces.end() - 1);
      line = pieces.back();
    } else {
      if (!line.empty()) line += ' ';
      line += word;
    }
    at = end + 1;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

std::string fit(std::string_view text, double width, double size) {
  if (text_width(text, size) <= width) return std::string(text);
  const std::size_t n = chars_in(width, size);
  if (n < 2) return "…";
  // the first and last characters kept about the ellipsis: a path keeps its file name
  std::size_t chars = 0;
  for (unsigned char c : text) chars += (c & 0xC0) != 0x80;
  const std::size_t head = (n - 1) / 2, tail = n - 1 - head;
  return std::string(text.substr(0, after_chars(text, head))) + "…" + std::string(text.substr(after_chars(text, chars - tail)));
}

double Page::heading(std::string_view title, std::string_view subtitle) {
  double y = 22;
  for (const auto& line : wrap(title, width_ - 32, 15)) {
    text(16, y, line, "start", 15);
    y += 19;
  }
  if (subtitle.empty()) return y + 10 - 19;
  y += 1;
  for (const auto& line : wrap(subtitle, width_ - 32, 12)) {
    text(16, y, line, "start", 12, "fill=\"#444\"");
    y += 16;
  }
  return y + 10 - 16;
}

std::string Page::str() const {
  return fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:g}\" height=\"{1:g}\" viewBox=\"0 0 {0:g} {1:g}\" "
                     "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"{0:g}\" height=\"{1:g}\" fill=\"white\"/>\n",
                     width_, height_) +
         body_ + "</svg>\n";
}

namespace {

struct Range {
  double lo, hi;
};

// The data range padded a little, never empty.
Range padded(const Axis& a) {
  double lo = a.lo, hi = a.hi;
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo) lo = 0, hi = 1;
  const double span = hi - lo;
  if (span < 1e-12 * std::max(1.0, std::fabs(lo))) {
    const double half = std::max(0.5, std::fabs(lo) * 0.05);
    return {lo - half, hi + half};
  }
  return {lo - span * 0.04, hi + span * 0.04};
}

struct Labels {
  std::vector<double> values;  // shown units
  double step = 1;
  double widest = 0;
  std::string text(double v) const { return tick_label(v, step); }
};

Labels labels(Range r, const Axis& a, int n) {
  Labels l;
  l.values = nice_ticks(r.lo * a.scale, r.hi * a.scale, n);
  if (a.scale < 0) l.values = nice_ticks(r.hi * a.scale, r.lo * a.scale, n);
  l.step = nice_step(std::fabs(r.hi - r.lo) * std::fabs(a.scale), n);
  for (double v : l.values) l.widest = std::max(l.widest, text_width(l.text(v), kTickFont));
  return l;
}

}  // namespace

Frame draw_panel(Page& page, const Panel& p) {
  Range u = padded(p.u), v = padded(p.v);
  const double top_pad = p.title.empty() ? 8 : 24;
  Frame f;
  Labels lu, lv;
  // twice: the equal scales change the ranges, the ranges the labels, the labels the margins
  for (int pass = 0; pass < 2; ++pass) {
    double left = 8, bottom = 8, right = 8;
    if (p.ticks) {
      lu = labels(u, p.u, p.u.ticks);
      lv = labels(v, p.v, p.v.ticks);
      left = lv.widest + 10 + (p.v.label.empty() ? 0 : 20);
      bottom = kTickFont + 10 + (p.u.label.empty() ? 0 : 20);
      right = std::max(8.0, lu.widest / 2 + 4);
    }
    f.left = p.x + left;
    f.top = p.y + top_pad;
    f.width = std::max(10.0, p.w - left - right);
    f.height = std::max(10.0, p.h - top_pad - bottom);
    if (p.equal) {
      Range u0 = padded(p.u), v0 = padded(p.v);
      const double k = std::min(f.width / (u0.hi - u0.lo), f.height / (v0.hi - v0.lo));
      const double cu = (u0.lo + u0.hi) / 2, cv = (v0.lo + v0.hi) / 2;
      u = {cu - f.width / k / 2, cu + f.width / k / 2};
      v = {cv - f.height / k / 2, cv + f.height / k / 2};
    }
    if (!p.ticks) break;
  }
  f.u0 = u.lo, f.u1 = u.hi, f.v0 = v.lo, f.v1 = v.hi;
  if (!p.title.empty()) page.text(f.left, p.y + 15, fit(p.title, p.x + p.w - f.left, kTitleFont), "start", kTitleFont);
  std::string s = fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" stroke=\"#999\"/>\n",
                              f.left, f.top, f.width, f.height);
  if (p.ticks) {
    for (double t : lu.values) {
      const double x = f.x(t / p.u.scale);
      if (p.grid)
        s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#eee\"/>", x, f.top,
                         f.top + f.height);
      s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#999\"/>"
                       "<text class=\"tick-u\" x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\" font-size=\"{4:g}\">{5}</text>\n",
                       x, f.top + f.height, f.top + f.height + 4, f.top + f.height + 4 + kTickFont, kTickFont,
                       lu.text(t));
    }
    for (double t : lv.values) {
      const double y = f.y(t / p.v.scale);
      if (p.grid)
        s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#eee\"/>", f.left, y,
                         f.left + f.width);
      s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#999\"/>"
                       "<text class=\"tick-v\" x=\"{3:.1f}\" y=\"{1:.1f}\" dy=\"4\" text-anchor=\"end\" font-size=\"{4:g}\">{5}</text>\n",
                       f.left - 4, y, f.left, f.left - 6, kTickFont, lv.text(t));
    }
    page.add(s);
    if (!p.u.label.empty())
      page.text(f.left + f.width / 2, f.top + f.height + kTickFont + 24, fit(p.u.label, f.width, kLabelFont), "middle", kLabelFont,
                "class=\"label-u\"");
    if (!p.v.label.empty()) {
      const double x = f.left - lv.widest - 14, y = f.top + f.height / 2;
      page.text(x, y, fit(p.v.label, f.height, kLabelFont), "middle", kLabelFont, fmt::format("class=\"label-v\" transform=\"rotate(-90 {:.1f} {:.1f})\"", x, y));
    }
  } else {
    page.add(s);
  }
  return f;
}

double draw_legend(Page& page, double x, double y, double max_width, const std::vector<LegendEntry>& entries) {
  // entries side by side, a row wrapping to the next when the next entry would pass max_width; a
  // text wider than max_width wraps within its entry, whose row grows with its lines
  constexpr double kSample = 30, kGap = 16, kLine = 15, kRow = 18;
  double cx = x, row_top = y, row_h = 0;
  for (const auto& e : entries) {
    const auto lines = wrap(e.label, std::max(max_width - kSample, 12.0), 12);
    double tw = 0;
    for (const auto& l : lines) tw = std::max(tw, text_width(l, 12));
    const double w = kSample + tw + kGap;
    if (cx > x && cx + w - kGap > x + max_width) cx = x, row_top += row_h, row_h = 0;
    const double cy = row_top + 12;
    if (e.cross)
      page.add(cross(cx + 11, cy - 4, 5, e.stroke));
    else if (e.dot)
      page.add(fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"{}\"/>\n", cx + 11, cy - 4, e.stroke));
    else
      page.add(fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"{:g}\"{}/>\n",
                           cx, cy - 4, cx + 24, cy - 4, e.stroke, e.width,
                           e.dash.empty() ? "" : fmt::format(" stroke-dasharray=\"{}\"", e.dash)));
    for (std::size_t i = 0; i < lines.size(); ++i) page.text(cx + kSample, cy + kLine * static_cast<double>(i), lines[i]);
    cx += w;
    row_h = std::max(row_h, kRow + kLine * static_cast<double>(lines.size() - 1));
  }
  return row_top + row_h - y;
}

double legend_height(double max_width, const std::vector<LegendEntry>& entries) {
  Page scratch(max_width, 1);
  return draw_legend(scratch, 0, 0, max_width, entries);
}

void draw_colour_scale(Page& page, const ColourScale& s) {
  constexpr double kFont = 10, kBar = 18;
  double y = s.y;
  for (const auto& line : wrap(s.title, s.width, 11)) {
    page.text(s.x, y + 11, line, "start", 11);
    y += 14;
  }
  // the bar leaves half a label's height below it, for the label of its bottom
  const double top = y + 10, height = std::max(10.0, s.y + s.height - kFont * 0.6 - top), bar_x = s.x + 6, label_x = bar_x + kBar + 6;
  const double label_w = s.x + s.width - label_x;
  std::string out;
  for (int i = 0; i < 100; ++i)
    out += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:g}\" height=\"{:.2f}\" fill=\"{}\"/>\n", bar_x,
                       top + height - (i + 1) * height / 100, kBar, height / 100 + 0.5, s.colour((i + 0.5) / 100));
  page.add(out);
  // labels centred on their values, the mark's first; a tick label that would touch one already
  // written is left out
  std::vector<double> taken;  // the centres of the labels written
  auto free = [&](double cy) {
    return std::none_of(taken.begin(), taken.end(), [&](double t) { return std::fabs(t - cy) < kFont + 2; });
  };
  auto at = [&](double v) { return top + height - std::clamp(v, 0.0, 1.0) * height; };
  if (s.mark) {
    const double cy = at(s.mark->first);
    page.add(fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"black\" stroke-width=\"2\"/>\n",
                         bar_x - 4, cy, bar_x + kBar + 4, cy));
    page.text(label_x, cy, fit(s.mark->second, label_w, kFont), "start", kFont, "dy=\"4\" font-weight=\"bold\"");
    taken.push_back(cy);
  }
  for (const auto& [v, label] : s.ticks) {
    const double cy = at(v);
    if (!free(cy)) continue;
    page.text(label_x, cy, fit(label, label_w, kFont), "start", kFont, "dy=\"4\"");
    taken.push_back(cy);
  }
}

std::string cross(double x, double y, double s, std::string_view colour, double width) {
  return fmt::format("<path class=\"marker\" d=\"M{:.1f},{:.1f}L{:.1f},{:.1f}M{:.1f},{:.1f}L{:.1f},{:.1f}\" stroke=\"{}\" "
                     "stroke-width=\"{:g}\"/>\n",
                     x - s, y - s, x + s, y + s, x - s, y + s, x + s, y - s, colour, width);
}

}  // namespace ncurve::report::plot
