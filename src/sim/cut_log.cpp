#include "sim/cut_log.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/bounds.hpp"
#include "geom/approx.hpp"

namespace ncurve::sim {

void CutLog::add(const ToolShape& tool, const Point3& a, const Point3& b, const std::optional<Arc>& arc,
                 const machine::Move& from) {
  if (cuts_.size() >= most_)
    throw base::BoundExceeded(fmt::format("the curve's check keeps every cut to measure the walls: more than {}, at "
                                          "line {}: raise --max-moves",
                                          most_, from.line));
  std::uint32_t k = 0;
  while (k < shapes_.size() && !(shapes_[k].kind() == tool.kind() && shapes_[k].radius() == tool.radius() &&
                                  shapes_[k].corner() == tool.corner() &&
                                  shapes_[k].point_angle_deg() == tool.point_angle_deg()))
    ++k;
  if (k == shapes_.size()) shapes_.push_back(tool);
  largest_radius_ = std::max(largest_radius_, tool.radius());
  Cut c;
  c.tool = k;
  c.a = a;
  c.b = b;
  c.is_arc = arc.has_value();
  if (arc) c.arc = *arc;
  c.file = from.file;
  c.line = from.line;
  c.compensated = from.compensated && !from.corner;
  any_compensated_ = any_compensated_ || c.compensated;
  cuts_.push_back(c);
  indexed_ = false;
}

double CutLog::lowest_of(const Cut& c, double x, double y) const {
  return c.is_arc ? lowest_over(shapes_[c.tool], c.arc, x, y) : lowest_over(shapes_[c.tool], c.a, c.b, x, y);
}

double CutLog::distance_of(const Cut& c, double x, double y) const {
  if (!c.is_arc) return geom::point_segment_distance({x, y, 0}, {c.a[0], c.a[1], 0}, {c.b[0], c.b[1], 0});
  const Arc& arc = c.arc;
  const double dx = x - arc.cx, dy = y - arc.cy, d = std::hypot(dx, dy);
  // the point's angle from the start along the move, in [0, 2 pi)
  const double dir = arc.sweep < 0 ? -1.0 : 1.0;
  double s = std::fmod(dir * (std::atan2(dy, dx) - arc.start_angle), 2 * std::numbers::pi);
  if (s < 0) s += 2 * std::numbers::pi;
  if (d > 0 && s <= std::abs(arc.sweep)) return std::abs(d - arc.radius);
  const double e = arc.start_angle + arc.sweep;
  return std::min(std::hypot(x - arc.cx - arc.radius * std::cos(arc.start_angle),
                             y - arc.cy - arc.radius * std::sin(arc.start_angle)),
                  std::hypot(x - arc.cx - arc.radius * std::cos(e), y - arc.cy - arc.radius * std::sin(e)));
}

void CutLog::index() const {
  indexed_ = true;
  first_.assign(1, 0);
  items_.clear();
  gnx_ = gny_ = 0;
  if (cuts_.empty()) return;
  // each cut's reach: its tip path's box widened by its tool
  std::vector<XYBox> reach(cuts_.size());
  XYBox all{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (std::size_t k = 0; k < cuts_.size(); ++k) {
    const Cut& c = cuts_[k];
    const double r = shapes_[c.tool].radius();
    XYBox b = c.is_arc ? arc_box(c.arc)
                        : XYBox{std::min(c.a[0], c.b[0]), std::max(c.a[0], c.b[0]), std::min(c.a[1], c.b[1]),
                               std::max(c.a[1], c.b[1])};
    b = {b.x0 - r, b.x1 + r, b.y0 - r, b.y1 + r};
    reach[k] = b;
    all = {std::min(all.x0, b.x0), std::max(all.x1, b.x1), std::min(all.y0, b.y0), std::max(all.y1, b.y1)};
  }
  const double w = all.x1 - all.x0, h = all.y1 - all.y0;
  gcell_ = std::max({largest_radius_ / 2, std::sqrt(w * h / 4e6), 1e-6 * (1 + w + h)});
  // a bucket's margin all round: a point on the reach's edge falls inside
  gx0_ = all.x0 - gcell_;
  gy0_ = all.y0 - gcell_;
  gnx_ = static_cast<int>(std::ceil(w / gcell_)) + 2;
  gny_ = static_cast<int>(std::ceil(h / gcell_)) + 2;
  auto clamp_x = [&](double x) { return std::clamp(static_cast<int>(std::floor((x - gx0_) / gcell_)), 0, gnx_ - 1); };
  auto clamp_y = [&](double y) { return std::clamp(static_cast<int>(std::floor((y - gy0_) / gcell_)), 0, gny_ - 1); };
  // a cut's buckets row by row: a line's chord of its stadium's box in the row, an arc's box
  auto each_bucket = [&](std::size_t k, auto&& put) {
    const Cut& c = cuts_[k];
    const XYBox& b = reach[k];
    const int j0 = clamp_y(b.y0), j1 = clamp_y(b.y1);
    for (int j = j0; j <= j1; ++j) {
      double x0 = b.x0, x1 = b.x1;
      if (!c.is_arc && c.a[1] != c.b[1]) {
        const double r = shapes_[c.tool].radius();
        const double yl = gy0_ + j * gcell_ - r, yh = gy0_ + (j + 1) * gcell_ + r;
        const double vy = c.b[1] - c.a[1];
        double t0 = (yl - c.a[1]) / vy, t1 = (yh - c.a[1]) / vy;
        if (t0 > t1) std::swap(t0, t1);
        t0 = std::clamp(t0, 0.0, 1.0);
        t1 = std::clamp(t1, 0.0, 1.0);
        const double xa = c.a[0] + t0 * (c.b[0] - c.a[0]), xb = c.a[0] + t1 * (c.b[0] - c.a[0]);
        x0 = std::max(x0, std::min(xa, xb) - r);
        x1 = std::min(x1, std::max(xa, xb) + r);
      }
      for (int i = clamp_x(x0), i1 = clamp_x(x1); i <= i1; ++i) put(static_cast<std::size_t>(j) * gnx_ + i);
    }
  };
  std::vector<std::uint32_t> count(static_cast<std::size_t>(gnx_) * gny_ + 1, 0);
  for (std::size_t k = 0; k < cuts_.size(); ++k) each_bucket(k, [&](std::size_t q) { ++count[q + 1]; });
  for (std::size_t q = 1; q < count.size(); ++q) count[q] += count[q - 1];
  first_ = count;
  items_.resize(count.back());
  for (std::size_t k = 0; k < cuts_.size(); ++k)
    each_bucket(k, [&](std::size_t q) { items_[count[q]++] = static_cast<std::uint32_t>(k); });
}

template <class Visit>
void CutLog::visit(double x, double y, const Visit& v) const {
  if (!indexed_) index();
  if (gnx_ == 0 || !std::isfinite(x) || !std::isfinite(y)) return;
  const double fx = (x - gx0_) / gcell_, fy = (y - gy0_) / gcell_;
  if (fx < 0 || fy < 0 || fx >= gnx_ || fy >= gny_) return;
  const std::size_t q = static_cast<std::size_t>(static_cast<int>(fy)) * gnx_ + static_cast<int>(fx);
  for (std::uint32_t n = first_[q]; n < first_[q + 1]; ++n)
    if (!v(items_[n])) return;
}

CutLog::Lowest CutLog::lowest_at(double x, double y) const {
  Lowest best;
  visit(x, y, [&](std::uint32_t k) {
    const double z = lowest_of(cuts_[k], x, y);
    if (z < best.z) best = {z, k};
    return true;
  });
  return best;
}

std::int64_t CutLog::any_below(double x, double y, double z) const {
  std::int64_t found = -1;
  visit(x, y, [&](std::uint32_t k) {
    if (lowest_of(cuts_[k], x, y) < z) found = k;
    return found < 0;
  });
  return found;
}

std::int64_t CutLog::nearest(double x, double y, double* distance) const {
  std::int64_t best = -1;
  double d = INFINITY;
  visit(x, y, [&](std::uint32_t k) {
    const double e = distance_of(cuts_[k], x, y);
    if (e < d) d = e, best = k;
    return true;
  });
  if (distance) *distance = d;
  return best;
}

}  // namespace ncurve::sim
