#include "report/path_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine/rapid_path.hpp"
#include "report/part_svg.hpp"
#include "report/svg_plot.hpp"
#include "report/writers.hpp"

namespace ncurve::report {

using machine::MoveKind;
using Vec = std::array<double, 3>;

std::optional<PlotView> plot_view(const std::string& name) {
  if (name == "xy") return PlotView::xy;
  if (name == "xz" || name == "zx") return PlotView::xz;
  if (name == "yz") return PlotView::yz;
  if (name == "iso") return PlotView::iso;
  return std::nullopt;
}

bool view_fits(const machine::MachineProfile& profile, PlotView view) {
  return !profile.lathe() || view == PlotView::xz || profile.axes.find('Y') != std::string::npos;
}

PathPlot::PathPlot(const machine::MachineProfile& profile, std::size_t max_elements)
    : lathe_(profile.lathe()), x_diameter_(profile.lathe() && profile.diameter_x),
      lathe_y_(profile.lathe() && profile.axes.find('Y') != std::string::npos),
      rapid_rate_(profile.rapid_rate), linear_rapid_(profile.linear_rapid),
      machine_plane_(profile.lathe() ? 18 : profile.power_on_plane), limit_(std::max<std::size_t>(max_elements, 1)),
      other_(profile) {}

namespace {

// What a drawing of X, Y and Z leaves out: "A axis not drawn: 0 to 360 deg" for each of the
// profile's A, B and C axes that moved (inch: a linear one in inches); empty when there is none.
std::string axes_not_drawn(const OtherAxes& other, bool inch) {
  auto number = [](double v) {
    std::string s = fmt::format("{:.3f}", v);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? std::string("0") : s;
  };
  std::string out;
  for (int k = 0; k < 3; ++k) {
    if (!other.moved(k)) continue;
    const bool rotary = other.rotary[k];
    const double lo = other.lo[k], hi = other.hi[k], scale = rotary || !inch ? 1 : 1 / 25.4;
    const char* unit = rotary ? "deg" : inch ? "in" : "mm";
    if (!out.empty()) out += " · ";
    out += lo == hi ? fmt::format("{} axis not drawn: at {} {}", "ABC"[k], number(lo * scale), unit)
                    : fmt::format("{} axis not drawn: {} to {} {}", "ABC"[k], number(lo * scale), number(hi * scale),
                                  unit);
  }
  return out;
}

Vec xyz(const machine::AxisVector& v) { return {v[0], v[1], v[2]}; }

// b - a and c - b point the same way: the second line continues the first.
bool continues(const Vec& a, const Vec& b, const Vec& c) {
  const Vec d1{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, d2{c[0] - b[0], c[1] - b[1], c[2] - b[2]};
  const Vec x{d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  const double n1 = std::hypot(d1[0], d1[1], d1[2]), n2 = std::hypot(d2[0], d2[1], d2[2]);
  const double dot = d1[0] * d2[0] + d1[1] * d2[1] + d1[2] * d2[2];
  return dot > 0 && std::hypot(x[0], x[1], x[2]) <= 1e-9 * n1 * n2;
}

}  // namespace

void PathPlot::on_move(const machine::Move& m) {
  if (!m.is_motion()) return;
  ++moves_by_kind_[m.kind == MoveKind::rapid ? 0 : m.kind == MoveKind::line ? 1 : 2];
  {  // the frame, of whole moves (a dog-leg's corners are the machine's, not the program's points)
    const Vec a = xyz(m.start), b = xyz(m.end);
    const bool cut = m.kind != MoveKind::rapid;
    for (int k = 0; k < 3; ++k) {
      if (cut) cut_lo_[k] = std::min({cut_lo_[k], a[k], b[k]}), cut_hi_[k] = std::max({cut_hi_[k], a[k], b[k]});
      if (axis_moved_[k] || cut) frame_lo_[k] = std::min(frame_lo_[k], a[k]), frame_hi_[k] = std::max(frame_hi_[k], a[k]);
      axis_moved_[k] = axis_moved_[k] || a[k] != b[k] || m.kind == MoveKind::arc;
      if (axis_moved_[k]) frame_lo_[k] = std::min(frame_lo_[k], b[k]), frame_hi_[k] = std::max(frame_hi_[k], b[k]);
    }
  }
  if (m.kind == MoveKind::rapid && !linear_rapid_) {  // a dog-leg: a straight piece between corners
    const auto path = machine::rapid_path(m.start, m.end, rapid_rate_, false);
    if (path.size() > 2) {
      machine::Move piece = m;
      for (std::size_t k = 1; k < path.size(); ++k) {
        piece.start = path[k - 1];
        piece.end = path[k];
        add(piece);
      }
      ++motions_;
      other_.add(m);
      return;
    }
  }
  ++motions_;
  other_.add(m);
  add(m);
}

void PathPlot::add(const machine::Move& m) {
  const Vec a = xyz(m.start), b = xyz(m.end);
  for (int k = 0; k < 3; ++k) lo_[k] = std::min({lo_[k], a[k], b[k]}), hi_[k] = std::max({hi_[k], a[k], b[k]});
  last_ = b;
  moved_ = true;
  if (m.kind != MoveKind::arc && !elements_.empty()) {  // a straight continuation of the same kind
    Element& p = elements_.back();
    if (p.kind == m.kind && p.b == a && continues(p.a, p.b, b)) {
      p.b = b;
      return;
    }
  }
  if (a == b && m.kind != MoveKind::arc) return;  // a move of rotary axes only: nothing to draw
  if (elements_.size() >= limit_ && !given_up_) compact();
  if (elements_.size() >= limit_) {
    ++left_out_;
    return;
  }
  Element e{m.kind, m.plane, a, b, m.center, m.sweep};
  elements_.push_back(e);
}

namespace {

double distance_to_segment(const Vec& p, const Vec& a, const Vec& b) {
  const Vec d{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{p[0] - a[0], p[1] - a[1], p[2] - a[2]};
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double t = dd > 0 ? std::clamp((w[0] * d[0] + w[1] * d[1] + w[2] * d[2]) / dd, 0.0, 1.0) : 0.0;
  return std::hypot(w[0] - t * d[0], w[1] - t * d[1], w[2] - t * d[2]);
}

}  // namespace

// The drawing is at most about 1,300 px across the path's extent: a 4000th of its diagonal is
// under half a pixel. The moves added since the last pass are simplified at the current level (a
// power of two in mm); if that does not halve the elements, everything is, at the next level up,
// until a 250th of the diagonal. Each pass keeps only programmed points, each dropped one within
// the level of the lines before: a point is off by at most the sum of the levels used, which is
// under twice the last.
void PathPlot::compact() {
  const double diag = std::hypot(hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2]);
  auto use = [&](double level, std::size_t from) {
    const std::size_t before = elements_.size();
    simplify(level, from);
    if (elements_.size() < before && level > last_tol_) tol_ += level, last_tol_ = level;
  };
  double level = std::max(last_tol_, std::exp2(std::ceil(std::log2(std::max(diag, 1e-9) / 4000))));
  use(level, fresh_);
  while (elements_.size() > limit_ / 2) {
    level *= 2;
    if (level > diag / 250) break;
    use(level, 0);
  }
  fresh_ = elements_.size();
  given_up_ = elements_.size() >= limit_;
}

// From element `from` on, runs of connected straight moves of one kind become fewer lines, every
// dropped corner within tol of the line that replaces it; arcs shorter than tol become lines. Each
// line reaches as far as a doubling then halving search finds (at most 512 corners), so the work
// is about n log n.
void PathPlot::simplify(double tol, std::size_t from) {
  constexpr std::size_t kWindow = 512;
  std::vector<Element> out(elements_.begin(), elements_.begin() + static_cast<std::ptrdiff_t>(from));
  out.reserve(elements_.size());
  std::vector<Vec> run;
  for (std::size_t i = from; i < elements_.size();) {
    Element e = elements_[i];
    if (e.kind == MoveKind::arc) {
      const auto pq = machine::plane_axes(e.plane);
      const double r = std::hypot(e.a[pq.p] - e.c[pq.p], e.a[pq.q] - e.c[pq.q]);
      if (r * std::fabs(e.sweep) < tol) e.kind = MoveKind::line;
    }
    if (e.kind == MoveKind::arc) {
      out.push_back(e);
      ++i;
      continue;
    }
    // the run: e and the straight elements of its kind joined to it
    run.assign({e.a, e.b});
    std::size_t j = i + 1;
    for (; j < elements_.size(); ++j) {
      const Element& n = elements_[j];
      bool straight = n.kind == e.kind;
      if (n.kind == MoveKind::arc && e.kind == MoveKind::line) {
        const auto pq = machine::plane_axes(n.plane);
        straight = std::hypot(n.a[pq.p] - n.c[pq.p], n.a[pq.q] - n.c[pq.q]) * std::fabs(n.sweep) < tol;
      }
      if (!straight || n.a != run.back()) break;
      run.push_back(n.b);
    }
    std::size_t anchor = 0;
    while (anchor + 1 < run.size()) {
      auto fits = [&](std::size_t end) {
        for (std::size_t k = anchor + 1; k < end; ++k)
          if (distance_to_segment(run[k], run[anchor], run[end]) > tol) return false;
        return true;
      };
      const std::size_t last = std::min(run.size() - 1, anchor + kWindow);
      std::size_t end = anchor + 1, bad = last + 1;
      for (std::size_t step = 1; end < last; step *= 2) {
        const std::size_t c = std::min(last, end + step);
        if (!fits(c)) {
          bad = c;
          break;
        }
        end = c;
      }
      while (bad - end > 1) {
        const std::size_t mid = (end + bad) / 2;
        (fits(mid) ? end : bad) = mid;
      }
      Element s = e;
      s.a = run[anchor], s.b = run[end];
      out.push_back(s);
      anchor = end;
    }
    i = j;
  }
  elements_ = std::move(out);
}

void PathPlot::stopped(const nc::Diagnostic& alarm) {
  alarm_ = alarm;
  alarm_at_ = last_;
}

namespace {

constexpr double kCos30 = 0.8660254037844386;

struct ViewMap {
  PlotView view;
  bool lathe;
  std::array<double, 2> operator()(const Vec& p) const {
    switch (view) {
      case PlotView::xy: return {p[0], p[1]};
      case PlotView::xz: return lathe ? std::array<double, 2>{p[2], p[0]} : std::array<double, 2>{p[0], p[2]};
      case PlotView::yz: return {p[1], p[2]};
      case PlotView::iso: return {(p[0] + p[1]) * kCos30, p[2] + (p[1] - p[0]) * 0.5};
    }
    return {0, 0};
  }
};

// Whether an arc of `plane` shows as a circle in the view (the plane faces the viewer), and the
// sign that turns its counter-clockwise into the view's.
int arc_facing(int plane, PlotView view, bool lathe) {
  if (plane == 17 && view == PlotView::xy) return 1;
  if (plane == 19 && view == PlotView::yz) return 1;
  if (plane == 18 && view == PlotView::xz) return lathe ? 1 : -1;  // G18: Z to X counter-clockwise
  return 0;
}

struct Box {
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  void add(const std::array<double, 2>& p) {
    u0 = std::min(u0, p[0]), u1 = std::max(u1, p[0]), v0 = std::min(v0, p[1]), v1 = std::max(v1, p[1]);
  }
  bool empty() const { return !(u0 <= u1); }
};

// The points of an arc element (start excluded), its chord error within tol.
template <class F>
void arc_pieces(const PathPlot::Element& e, double tol, F&& f) {
  machine::Move m;
  m.kind = MoveKind::arc;
  m.plane = e.plane;
  for (int k = 0; k < 3; ++k) m.start[k] = e.a[k], m.end[k] = e.b[k];
  m.center = e.c;
  m.sweep = e.sweep;
  machine::arc_points(m, tol, [&](const machine::AxisVector& p) { f(Vec{p[0], p[1], p[2]}); });
}

const char* css_class(MoveKind k) { return k == MoveKind::rapid ? "rapid" : k == MoveKind::arc ? "arc" : "feed"; }

constexpr const char* kRapid = "#ef6c00", *kFeed = "#1565c0", *kArc = "#2e7d32", *kAlarm = "#d50000";

std::string style(MoveKind k) {
  if (k == MoveKind::rapid) return fmt::format("stroke=\"{}\" stroke-dasharray=\"6 4\"", kRapid);
  return fmt::format("stroke=\"{}\"", k == MoveKind::arc ? kArc : kFeed);
}

}  // namespace

std::string PathPlot::svg(const PathPlotOptions& o) const {
  std::vector<PlotView> views;
  for (PlotView v : o.views)
    if (!lathe_ || lathe_y_ || v == PlotView::xz) views.push_back(v);
  if (views.empty()) {
    if (lathe_) views = {PlotView::xz};
    else if (machine_plane_ == 18) views = {PlotView::xz, PlotView::iso, PlotView::xy, PlotView::yz};
    else if (machine_plane_ == 19) views = {PlotView::yz, PlotView::iso, PlotView::xy, PlotView::xz};
    else views = {PlotView::xy, PlotView::iso, PlotView::xz, PlotView::yz};
  }
  const bool single = views.size() == 1;
  const double W = single ? 960 : 1280, H = single ? 760 : 1100;
  plot::Page page(W, H);
  // the moves as the run's summary counts them (a dog-leg rapid one move, collinear moves apart)
  const auto* by_kind = moves_by_kind_.data();
  double top = page.heading(o.title, fmt::format("{} motions: {} rapid, {} line and {} arc moves{}",
                                                       motions_, by_kind[0], by_kind[1], by_kind[2],
                                                       lathe_ && views.front() == PlotView::xz && views.size() == 1
                                                           ? "; lathe: Z across, X up"
                                                           : ""));
  // the axes the views leave out, under the heading
  if (const std::string other = axes_not_drawn(other_, o.inch); !other.empty()) {
    for (const auto& line : plot::wrap(other + " (the views show X, Y and Z)", W - 32, 12)) {
      page.text(16, top + 6, line, "start", 12, "class=\"not-drawn\" fill=\"#bf360c\"");
      top += 16;
    }
    top += 2;
  }
  // the legend and notes at the bottom
  std::vector<std::string> notes;  // lines, the alarm's last
  auto note = [&](const std::string& text) {
    for (auto& line : plot::wrap(text, W - 32, 12)) notes.push_back(std::move(line));
  };
  if (tol_ > 0)
    note(fmt::format("short moves drawn simplified, within {:.3g} {} of the path, to keep the drawing small",
                     o.inch ? tol_ / 25.4 : tol_, o.inch ? "in" : "mm"));
  if (left_out_)
    note(fmt::format("only the first {} elements are drawn: {} more moves were left out (limit of the plot)", limit_,
                     left_out_));
  std::size_t alarm_lines = 0;
  if (alarm_) {
    auto lines = plot::wrap(fmt::format("the run stopped on alarm {} at {}line {}: {}", alarm_->code,
                                        alarm_->span.file ? alarm_->span.file->name() + " " : std::string(),
                                        alarm_->span.line, alarm_->message),
                            W - 32, 12);
    alarm_lines = lines.size();
    notes.insert(notes.end(), lines.begin(), lines.end());
  }
  const double bottom = 36 + 18 * static_cast<double>(notes.size());
  const double cols = single ? 1 : 2, rows = single ? 1 : 2;
  const double cw = (W - 16) / cols, ch = (H - top - bottom) / rows;
  const double unit = o.inch ? 1 / 25.4 : 1;
  const char* units = o.inch ? "in" : "mm";

  // The program's box: the cuts (lines and arcs) and the rapids' ends near them, within a quarter of
  // the cuts' diagonal (clearance planes, approaches), so that rapids to and from a home far off
  // are cut off at the panel's edge. Without cuts: every move, an axis counted from its first move
  // on (a cut from where it starts), which leaves out where the machine stood before the program.
  Vec lo = frame_lo_, hi = frame_hi_, cut_lo = cut_lo_, cut_hi = cut_hi_;
  {
    auto count = [&](Vec& l, Vec& h, const Vec& p) {
      for (int k = 0; k < 3; ++k) l[k] = std::min(l[k], p[k]), h[k] = std::max(h[k], p[k]);
    };
    for (const auto& e : elements_) {
      if (e.kind == MoveKind::arc) {  // its extremes, as the panels' box takes them below
        const double r = std::hypot(e.a[0] - e.c[0], e.a[1] - e.c[1], e.a[2] - e.c[2]);
        arc_pieces(e, std::max(r * 1e-3, 1e-9), [&](const Vec& p) { count(lo, hi, p), count(cut_lo, cut_hi, p); });
      }
    }
    const Vec& here = elements_.empty() ? last_ : elements_.front().a;
    for (int k = 0; k < 3; ++k)
      if (!(lo[k] <= hi[k])) lo[k] = hi[k] = here[k];  // an axis nothing counted: where it stands
    const double all_diag = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    const double cut_diag = std::hypot(cut_hi[0] - cut_lo[0], cut_hi[1] - cut_lo[1], cut_hi[2] - cut_lo[2]);
    if (cut_lo[0] <= cut_hi[0] && cut_diag >= all_diag * 1e-3) {
      const double m = cut_diag / 4;
      const Vec cuts_lo = cut_lo, cuts_hi = cut_hi;
      for (const auto& e : elements_) {
        if (e.kind != MoveKind::rapid) continue;
        for (const Vec& p : {e.a, e.b}) {
          bool in = true;
          for (int k = 0; k < 3; ++k) in = in && p[k] >= cuts_lo[k] - m && p[k] <= cuts_hi[k] + m;
          if (in) count(cut_lo, cut_hi, p);
        }
      }
      lo = cut_lo, hi = cut_hi;
    }
  }
  auto inside = [&](const Vec& p) {
    Vec q;
    for (int k = 0; k < 3; ++k) q[k] = std::clamp(p[k], lo[k], hi[k]);
    return q;
  };

  for (std::size_t i = 0; i < views.size() && i < 4; ++i) {
    const PlotView view = views[i];
    const ViewMap map{view, lathe_};
    Box box;
    for (const auto& e : elements_) {
      box.add(map(inside(e.a))), box.add(map(inside(e.b)));
      if (e.kind == MoveKind::arc) {  // its extremes: a coarse sampling is within the padding
        double r = std::hypot(e.a[0] - e.c[0], e.a[1] - e.c[1], e.a[2] - e.c[2]);
        arc_pieces(e, std::max(r * 1e-3, 1e-9), [&](const Vec& p) { box.add(map(inside(p))); });
      }
    }
    if (alarm_) box.add(map(alarm_at_));
    const bool part = part_ && !lathe_ && view != PlotView::iso;
    const bool section = !section_.empty() && lathe_ && view == PlotView::xz;
    if (section)  // the section's box: Z across, the radius up
      for (const auto& poly : section_)
        for (const geom::V2& q : poly) box.add({q.x, q.y});
    if (part)  // the stock's box
      for (double x : {part_->x0 - part_->dx / 2, part_->x0 + (part_->nx - 0.5) * part_->dx})
        for (double y : {part_->y0 - part_->dy / 2, part_->y0 + (part_->ny - 0.5) * part_->dy})
          for (double z : {part_->bottom, part_->top}) box.add(map({x, y, z}));
    if (box.empty()) box.add({0, 0});
    plot::Panel panel;
    panel.x = 8 + (single ? 0 : (i % 2) * cw);
    panel.y = top + (single ? 0 : static_cast<double>(i / 2) * ch);
    panel.w = cw - 8, panel.h = ch - 4;
    panel.equal = true;
    panel.u = {box.u0, box.u1, "", unit, 8};
    panel.v = {box.v0, box.v1, "", unit, 8};
    const std::string x_name = lathe_ ? fmt::format("X ({})", x_diameter_ ? "diameter" : "radius") : "X";
    const double x_scale = x_diameter_ ? 2 * unit : unit;
    switch (view) {
      case PlotView::xy:
        panel.title = "XY (top)", panel.u.label = x_name, panel.v.label = "Y", panel.u.scale = x_scale;
        break;
      case PlotView::yz: panel.title = "YZ (side)", panel.u.label = "Y", panel.v.label = "Z"; break;
      case PlotView::xz:
        if (lathe_) {
          panel.title = "ZX plane", panel.u.label = "Z", panel.v.label = x_name, panel.v.scale = x_scale;
        } else {
          panel.title = "XZ (front)", panel.u.label = "X", panel.v.label = "Z";
        }
        break;
      case PlotView::iso:
        panel.title = "isometric", panel.ticks = false;
        break;
    }
    if (panel.ticks) panel.u.label += fmt::format(", {}", units), panel.v.label += fmt::format(", {}", units);
    const plot::Frame f = plot::draw_panel(page, panel);
    if (part) page.add(view == PlotView::xy ? part_top_svg(*part_, f) : part_side_svg(*part_, f, view == PlotView::xz ? 0 : 1));
    if (section) page.add(section_svg(section_, f));
    const double res = 0.25 / f.px_per_unit();  // a quarter pixel, in mm
    std::string s = fmt::format("<g class=\"view\" fill=\"none\" stroke-width=\"1.3\" stroke-linejoin=\"round\">\n");
    // a line's part inside the panel (Liang-Barsky), false when none is: the approach from where the
    // machine stood before the program, which the box leaves out
    auto clipped = [&](std::array<double, 2>& p0, std::array<double, 2>& p1) {
      double t0 = 0, t1 = 1;
      const double dx = p1[0] - p0[0], dy = p1[1] - p0[1];
      const double x0 = f.left - 0.5, x1 = f.left + f.width + 0.5, y0 = f.top - 0.5, y1 = f.top + f.height + 0.5;
      for (const auto& [p, q] : {std::pair{-dx, p0[0] - x0}, std::pair{dx, x1 - p0[0]}, std::pair{-dy, p0[1] - y0},
                                 std::pair{dy, y1 - p0[1]}}) {
        if (p == 0) {
          if (q < 0) return false;
          continue;
        }
        const double t = q / p;
        if (p < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
      }
      if (t1 < 1) p1 = {p0[0] + t1 * dx, p0[1] + t1 * dy};
      if (t0 > 0) p0 = {p0[0] + t0 * dx, p0[1] + t0 * dy};
      return true;
    };
    auto pt = [&](const Vec& p) {
      auto q = map(p);
      return fmt::format("{:.2f},{:.2f}", f.x(q[0]), f.y(q[1]));
    };
    auto to = [&](std::string& d, char command, const Vec& p) {
      auto q = map(p);
      fmt::format_to(std::back_inserter(d), "{}{:.2f},{:.2f}", command, f.x(q[0]), f.y(q[1]));
    };
    for (const auto& e : elements_) {
      std::string d;
      if (e.kind != MoveKind::arc) {
        const auto qa = map(e.a), qb = map(e.b);
        std::array<double, 2> p0{f.x(qa[0]), f.y(qa[1])}, p1{f.x(qb[0]), f.y(qb[1])};
        if (!clipped(p0, p1)) continue;
        s += fmt::format("<path class=\"{}\" d=\"M{:.2f},{:.2f}L{:.2f},{:.2f}\" {}/>\n", css_class(e.kind), p0[0], p0[1],
                         p1[0], p1[1], style(e.kind));
        continue;
      }
      to(d, 'M', e.a);
      const int facing = e.kind == MoveKind::arc ? arc_facing(e.plane, view, lathe_) : 0;
      const auto pq = machine::plane_axes(e.plane);
      const double rs = std::hypot(e.a[pq.p] - e.c[pq.p], e.a[pq.q] - e.c[pq.q]);
      const double re = std::hypot(e.b[pq.p] - e.c[pq.p], e.b[pq.q] - e.c[pq.q]);
      if (e.kind != MoveKind::arc) {
        to(d, 'L', e.b);
      } else if (facing != 0 && std::fabs(rs - re) <= res) {
        // an SVG arc per half at most, so a full circle draws too
        const double r = rs * f.px_per_unit();
        const int pieces = std::fabs(e.sweep) > std::numbers::pi ? 2 : 1;
        const int flag = e.sweep * facing > 0 ? 0 : 1;  // counter-clockwise on the page: flag 0 (y points down)
        for (int k = 1; k <= pieces; ++k) {
          Vec p = e.b;
          if (k < pieces) {
            const double t = std::atan2(e.a[pq.q] - e.c[pq.q], e.a[pq.p] - e.c[pq.p]) + e.sweep / pieces * k;
            for (int j = 0; j < 3; ++j) p[j] = e.a[j] + (e.b[j] - e.a[j]) * k / pieces;
            p[pq.p] = e.c[pq.p] + rs * std::cos(t);
            p[pq.q] = e.c[pq.q] + rs * std::sin(t);
          }
          d += fmt::format("A{:.2f},{:.2f} 0 0 {} {}", r, r, flag, pt(p));
        }
      } else {
        arc_pieces(e, res, [&](const Vec& p) { to(d, 'L', p); });
      }
      s += fmt::format("<path class=\"{}\" d=\"{}\" {}/>\n", css_class(e.kind), d, style(e.kind));
    }
    if (moved_ || !elements_.empty()) {
      const Vec start = elements_.empty() ? last_ : elements_.front().a;
      auto q = map(start);
      if (f.x(q[0]) >= f.left && f.x(q[0]) <= f.left + f.width && f.y(q[1]) >= f.top && f.y(q[1]) <= f.top + f.height)
        s += fmt::format("<circle class=\"start\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3.5\" fill=\"#000\"/>\n", f.x(q[0]), f.y(q[1]));
    }
    s += "</g>\n";
    page.add(s);
    if (alarm_) {
      auto q = map(alarm_at_);
      page.add(plot::cross(f.x(q[0]), f.y(q[1]), 7, kAlarm, 2.5));
      const bool right = f.x(q[0]) > f.left + f.width * 0.7;  // the label stays inside the panel
      const double room = right ? f.x(q[0]) - 10 - f.left : f.left + f.width - f.x(q[0]) - 10;
      page.text(f.x(q[0]) + (right ? -10 : 10), f.y(q[1]) - 8,
                plot::fit(fmt::format("{} line {}", alarm_->code, alarm_->span.line), room, 12), right ? "end" : "start",
                12, fmt::format("class=\"alarm\" fill=\"{}\"", kAlarm));
    }
    if (view == PlotView::iso) {  // the axes' directions and a scale bar instead of ticks
      const double ox = f.left + 40, oy = f.top + f.height - 40;
      for (int k = 0; k < 3; ++k) {
        Vec p{0, 0, 0};
        p[k] = 30 / f.px_per_unit();
        auto q = map(p);
        const double dx = q[0] * f.px_per_unit(), dy = -q[1] * f.px_per_unit();
        page.add(fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#555\"/>", ox, oy,
                             ox + dx, oy + dy));
        page.text(ox + dx * 1.3, oy + dy * 1.3 + 4, std::string(1, "XYZ"[k]), "middle", 11);
      }
      const double bar = plot::nice_step((f.u1 - f.u0) * unit, 4);
      const double px = bar / unit * f.px_per_unit(), bx = f.left + f.width - px - 12, by = f.top + f.height - 14;
      page.add(fmt::format("<path d=\"M{0:.1f},{1:.1f}v4h{2:.1f}v-4\" fill=\"none\" stroke=\"#555\"/>", bx, by - 4, px));
      page.text(bx + px / 2, by - 8, fmt::format("{:g} {}", bar, units), "middle", 11, "class=\"scale-bar\"");
    }
  }
  double y = H - bottom + 4;
  std::vector<plot::LegendEntry> legend = {
      {"rapid (G00)", kRapid, "6 4", 1.5}, {"feed (G01)", kFeed, "", 1.5}, {"arc (G02/G03)", kArc, "", 1.5}, {"start", "#000", "", 1.5, false, true}};
  if (alarm_) legend.push_back({"alarm", kAlarm, "", 2.5, true});
  if (part_ && !lathe_) legend.push_back({"part (cut stock; isometric: not drawn)", "#a0a6ae", "", 6});
  if (!section_.empty() && lathe_) legend.push_back({"part (the bar's half-section as cut)", "#a0a6ae", "", 6});
  y += plot::draw_legend(page, 16, y, W - 32, legend);
  for (std::size_t i = 0; i < notes.size(); ++i) {
    const bool alarm = i + alarm_lines >= notes.size();
    page.text(16, y + 12, notes[i], "start", 12, fmt::format("class=\"note\" fill=\"{}\"", alarm ? kAlarm : "#444"));
    y += 18;
  }
  return page.str();
}

}  // namespace ncurve::report
