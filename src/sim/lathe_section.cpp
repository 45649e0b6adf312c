#include "sim/lathe_section.hpp"

#include <clipper.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace ncurve::sim {

using geom::V2;
using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Section coordinates in kSectionUnit: IntPoint.X is X (the radius), IntPoint.Y is Z. Clipper sweeps
// its scan line along Y: along the spindle axis, the direction most moves of a lathe run, so that few
// of a batch's sweeps are active on any one scan beam. Clipper's orientation (outer boundaries
// counter-clockwise in X, Y) is clockwise with Z to the right and X up.
cInt to_units(double mm) { return static_cast<cInt>(std::llround(mm / kSectionUnit)); }
IntPoint section_point(double z, double x) { return {to_units(x), to_units(z)}; }

bool finite(V2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Twice the signed area of the triangle o, a, b (exact: coordinates are below 2^31 in size).
cInt cross(const IntPoint& o, const IntPoint& a, const IntPoint& b) {
  return (a.X - o.X) * (b.Y - o.Y) - (a.Y - o.Y) * (b.X - o.X);
}

// The convex hull of the points, counter-clockwise, by Andrew's monotone chain (collinear points
// dropped). The input is sorted in place.
Path convex_hull(Path& p) {
  std::sort(p.begin(), p.end(), [](const IntPoint& a, const IntPoint& b) { return a.X != b.X ? a.X < b.X : a.Y < b.Y; });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return {};
  Path h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower hull
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h.size() >= 3 ? h : Path{};
}

// The part of the segment a..b inside the box (Liang-Barsky); false when none is.
bool clip_segment(V2& a, V2& b, V2 lo, V2 hi) {
  double t0 = 0, t1 = 1;
  const V2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    if (t0 > t1) return false;
  }
  const V2 a0 = a;
  if (t0 > 0) a = a0 + t0 * d;
  if (t1 < 1) b = a0 + t1 * d;
  // rounding (a segment of 1e300 mm) may leave a point outside: into the box
  a = {std::clamp(a.x, lo.x, hi.x), std::clamp(a.y, lo.y, hi.y)};
  b = {std::clamp(b.x, lo.x, hi.x), std::clamp(b.y, lo.y, hi.y)};
  return true;
}

double path_area(const Path& p) {
  double a = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const IntPoint &u = p[i], &v = p[(i + 1) % n];
    a += static_cast<double>(u.X * v.Y - v.X * u.Y);
  }
  return a / 2 * kSectionUnit * kSectionUnit;
}

// The integral of the radius over the polygon, mm^3.
double path_moment(const Path& p) {
  double m = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const IntPoint &u = p[i], &v = p[(i + 1) % n];
    m += static_cast<double>(u.X * v.Y - v.X * u.Y) * static_cast<double>(u.X + v.X);
  }
  return m / 6 * kSectionUnit * kSectionUnit * kSectionUnit;
}

}  // namespace

struct LatheSection::State {
  Paths section;
  // The sweeps not yet subtracted, merged as a binary counter merges: a sweep enters at level 0 and
  // two unions of the same level become one of the next, so that a batch of n overlapping sweeps
  // costs some n log n edges in Clipper rather than the n^2 of one union of them all.
  std::vector<std::pair<int, Paths>> pending;
  int pending_sweeps = 0;

  void add_sweep(Paths sweep) {
    pending.emplace_back(0, std::move(sweep));
    ++pending_sweeps;
    while (pending.size() >= 2 && pending.back().first == pending[pending.size() - 2].first) {
      auto b = std::move(pending.back());
      pending.pop_back();
      auto& a = pending.back();
      ClipperLib::Clipper c;
      c.AddPaths(a.second, ClipperLib::ptSubject, true);
      c.AddPaths(b.second, ClipperLib::ptClip, true);
      Paths out;
      c.Execute(ClipperLib::ctUnion, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
      a.second = std::move(out);
      ++a.first;
    }
  }
  int batch = kDefaultBatch;
  bool empty = true;
  V2 lo{}, hi{};  // the stock's box, mm
  double area0 = 0, moment0 = 0;

  // The region the outline sweeps moving from a to b (its mirror image across the axis with it where
  // it crosses below), clipped to where it can reach the stock's box; none beyond.
  Paths sweep(const ToolOutline& tool, V2 a, V2 b) const {
    if (empty || tool.empty() || !finite(a) || !finite(b)) return {};
    V2 tlo = tool.points[0], thi = tool.points[0];
    for (const V2& q : tool.points) {
      tlo = {std::min(tlo.x, q.x), std::min(tlo.y, q.y)};
      thi = {std::max(thi.x, q.x), std::max(thi.y, q.y)};
    }
    const double margin = kSectionUnit;
    const V2 l{lo.x - thi.x - margin, -hi.y - thi.y - margin}, h{hi.x - tlo.x + margin, hi.y - tlo.y + margin};
    if (!clip_segment(a, b, l, h)) return {};
    Path points;
    points.reserve(2 * tool.points.size());
    for (const V2& q : tool.points) {
      points.push_back(section_point(a.x + q.x, a.y + q.y));
      points.push_back(section_point(b.x + q.x, b.y + q.y));
    }
    Path hull = convex_hull(points);
    if (hull.empty()) return {};
    cInt low = hull[0].X;
    for (const IntPoint& p : hull) low = std::min(low, p.X);
    if (low >= 0) return {std::move(hull)};
    // the part turns: the tool cuts at |X| on the far side of the axis too
    Path mirror(hull.rbegin(), hull.rend());
    for (IntPoint& p : mirror) p.X = -p.X;
    return {std::move(hull), std::move(mirror)};
  }
};

namespace {

// The chords of an arc from a to b about c through `sweep`, its radius going from |a - c| to |b - c|
// in proportion to the angle, each at most kChordError from it: f(from, to) for each.
template <class F>
void for_each_chord(V2 a, V2 b, V2 c, double sweep, F f) {
  const double r0 = geom::norm(a - c), r1 = geom::norm(b - c);
  const double a0 = std::atan2(a.y - c.y, a.x - c.x);
  const int n = arc_chords(std::max(r0, r1), std::fabs(sweep));
  V2 p = a;
  for (int k = 1; k <= n; ++k) {
    const double t = static_cast<double>(k) / n, angle = a0 + sweep * t, r = r0 + (r1 - r0) * t;
    const V2 q = k == n ? b : c + r * V2{std::cos(angle), std::sin(angle)};
    f(p, q);
    p = q;
  }
}

struct IntBox {
  IntPoint lo{0, 0}, hi{-1, -1};
  bool empty() const { return lo.X > hi.X; }
  void add(const Paths& ps) {
    for (const Path& p : ps)
      for (const IntPoint& q : p) {
        if (empty()) lo = hi = q;
        lo = {std::min(lo.X, q.X), std::min(lo.Y, q.Y)};
        hi = {std::max(hi.X, q.X), std::max(hi.Y, q.Y)};
      }
  }
  bool meets(const IntBox& o) const {
    return !empty() && !o.empty() && lo.X <= o.hi.X && o.lo.X <= hi.X && lo.Y <= o.hi.Y && o.lo.Y <= hi.Y;
  }
};

}  // namespace

LatheSection::LatheSection(const Cylinder& stock, int batch) : stock_(stock), s_(std::make_unique<State>()) {
  State& s = *s_;
  s.batch = std::max(batch, 1);
  const double outer = stock.diameter / 2, inner = std::max(stock.inner_diameter / 2, 0.0);
  const double face = stock.face, back = stock.face - stock.length;
  if (!(std::isfinite(outer) && std::isfinite(inner) && std::isfinite(face) && std::isfinite(back))) return;
  s.lo = {std::clamp(back, -kSectionReach, kSectionReach), std::min(inner, kSectionReach)};
  s.hi = {std::clamp(face, -kSectionReach, kSectionReach), std::min(outer, kSectionReach)};
  const IntPoint lo = section_point(s.lo.x, s.lo.y), hi = section_point(s.hi.x, s.hi.y);
  if (!(lo.X < hi.X && lo.Y < hi.Y)) return;
  s.empty = false;
  s.section = {{lo, {hi.X, lo.Y}, hi, {lo.X, hi.Y}}};
  s.area0 = path_area(s.section[0]);
  s.moment0 = path_moment(s.section[0]);
}

LatheSection::~LatheSection() = default;
LatheSection::LatheSection(LatheSection&&) noexcept = default;
LatheSection& LatheSection::operator=(LatheSection&&) noexcept = default;

bool LatheSection::cut(const ToolOutline& tool, const machine::Move& m) {
  if (!m.is_motion()) return false;
  const V2 a{m.start[2], m.start[0]}, b{m.end[2], m.end[0]};
  if (m.kind != machine::MoveKind::arc) {
    if (!finite(a) || !finite(b)) return false;
    cut_line(tool, a, b);
    return true;
  }
  const V2 c{m.center[2], m.center[0]};
  if (m.plane != 18 || !finite(a) || !finite(b) || !finite(c) || !std::isfinite(m.sweep)) return false;
  cut_arc(tool, a, b, c, m.sweep);
  return true;
}

void LatheSection::cut_line(const ToolOutline& tool, V2 a, V2 b) {
  State& s = *s_;
  Paths sweep = s.sweep(tool, a, b);
  if (sweep.empty()) return;
  s.add_sweep(std::move(sweep));
  if (s.pending_sweeps >= s.batch) flush();
}

void LatheSection::cut_arc(const ToolOutline& tool, V2 a, V2 b, V2 centre, double sweep) {
  if (s_->empty || tool.empty() || !finite(a) || !finite(b) || !finite(centre) || !std::isfinite(sweep)) return;
  for_each_chord(a, b, centre, sweep, [&](V2 p, V2 q) { cut_line(tool, p, q); });
}

LatheSection::Overlap LatheSection::overlap(const ToolOutline& tool, const machine::Move& m) const {
  State& s = *s_;
  if (!m.is_motion() || s.empty || tool.empty()) return {};
  const V2 a{m.start[2], m.start[0]}, b{m.end[2], m.end[0]};
  if (!finite(a) || !finite(b)) return {};
  Paths region;
  auto add = [&](V2 p, V2 q) {
    for (Path& path : s.sweep(tool, p, q)) region.push_back(std::move(path));
  };
  if (m.kind == machine::MoveKind::arc) {
    const V2 c{m.center[2], m.center[0]};
    if (m.plane != 18 || !finite(c) || !std::isfinite(m.sweep)) return {};
    for_each_chord(a, b, c, m.sweep, add);
  } else {
    add(a, b);
  }
  IntBox box;
  box.add(region);
  auto meet = [&]() {
    IntBox section;
    section.add(s.section);
    Paths out;
    if (!box.meets(section)) return out;
    ClipperLib::Clipper c;
    c.AddPaths(s.section, ClipperLib::ptSubject, true);
    c.AddPaths(region, ClipperLib::ptClip, true);
    c.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
  };
  Paths out = meet();
  if (out.empty()) return {};
  if (!s.pending.empty()) {
    flush();
    out = meet();
  }
  Overlap o;
  double moment_z = 0, moment_x = 0;
  for (const Path& p : out) {
    o.area += path_area(p);
    for (std::size_t i = 0, n = p.size(); i < n; ++i) {
      const IntPoint &u = p[i], &v = p[(i + 1) % n];
      const double c = static_cast<double>(u.X * v.Y - v.X * u.Y);
      moment_x += c * static_cast<double>(u.X + v.X);
      moment_z += c * static_cast<double>(u.Y + v.Y);
    }
  }
  IntBox ob;
  ob.add(out);
  if (ob.empty()) return {};
  o.lo = {ob.lo.Y * kSectionUnit, ob.lo.X * kSectionUnit};
  o.hi = {ob.hi.Y * kSectionUnit, ob.hi.X * kSectionUnit};
  const double twice = 2 * o.area / (kSectionUnit * kSectionUnit);  // in units^2, x2
  if (twice != 0) o.centroid = {moment_z / (3 * twice) * kSectionUnit, moment_x / (3 * twice) * kSectionUnit};
  return o;
}

void LatheSection::flush() const {
  State& s = *s_;
  if (s.pending.empty()) return;
  ClipperLib::Clipper c;
  c.AddPaths(s.section, ClipperLib::ptSubject, true);
  for (const auto& [level, paths] : s.pending) c.AddPaths(paths, ClipperLib::ptClip, true);
  Paths out;
  c.Execute(ClipperLib::ctDifference, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  s.section = std::move(out);
  s.pending.clear();
  s.pending_sweeps = 0;
}

double LatheSection::area() const {
  flush();
  double a = 0;
  for (const Path& p : s_->section) a += path_area(p);
  return a;
}

double LatheSection::area_removed() const { return s_->area0 - area(); }

double LatheSection::volume() const {
  flush();
  double m = 0;
  for (const Path& p : s_->section) m += path_moment(p);
  return 2 * kPi * m;
}

double LatheSection::volume_removed() const { return 2 * kPi * s_->moment0 - volume(); }

std::vector<std::vector<V2>> LatheSection::polygons() const {
  flush();
  std::vector<std::vector<V2>> out;
  out.reserve(s_->section.size());
  for (const Path& p : s_->section) {
    std::vector<V2>& q = out.emplace_back();
    q.reserve(p.size());
    for (auto v = p.rbegin(); v != p.rend(); ++v) q.push_back({v->Y * kSectionUnit, v->X * kSectionUnit});
  }
  return out;
}

namespace {

// Each radius (in units) where the line Z = z crosses the section's boundary, to `f`.
template <class F>
void each_crossing(const Paths& section, double z, F f) {
  if (!std::isfinite(z)) return;
  const double u = z / kSectionUnit;
  for (const Path& p : section)
    for (std::size_t i = 0, n = p.size(); i < n; ++i) {
      const IntPoint &a = p[i], &b = p[(i + 1) % n];
      const double az = static_cast<double>(a.Y), bz = static_cast<double>(b.Y);
      if (u < std::min(az, bz) || u > std::max(az, bz)) continue;
      if (a.Y == b.Y) {
        f(static_cast<double>(a.X));
        f(static_cast<double>(b.X));
      } else {
        f(a.X + (b.X - a.X) * (u - az) / (bz - az));
      }
    }
}

// The crossing `pick` keeps, mm; NaN where there is none.
template <class Pick>
double radius_at(const Paths& section, double z, Pick pick) {
  bool any = false;
  double best = 0;
  each_crossing(section, z, [&](double y) {
    best = any ? pick(best, y) : y;
    any = true;
  });
  return any ? best * kSectionUnit : kNaN;
}

}  // namespace

double LatheSection::outer_radius(double z) const {
  flush();
  return radius_at(s_->section, z, [](double a, double b) { return std::max(a, b); });
}

std::vector<double> LatheSection::crossings(double z) const {
  flush();
  std::vector<double> out;
  each_crossing(s_->section, z, [&](double y) { out.push_back(y * kSectionUnit); });
  std::sort(out.begin(), out.end());
  return out;
}

double LatheSection::inner_radius(double z) const {
  flush();
  return radius_at(s_->section, z, [](double a, double b) { return std::min(a, b); });
}

Mesh LatheSection::mesh(int segments) const {
  flush();
  const int n = std::clamp(segments, 3, 1 << 16);
  std::vector<double> cs(n), sn(n);
  for (int k = 0; k < n; ++k) cs[k] = std::cos(2 * kPi * k / n), sn[k] = std::sin(2 * kPi * k / n);
  std::size_t points = 0;
  for (const Path& p : s_->section) points += p.size();
  if (static_cast<double>(points) * n >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("the part's mesh would have more vertices than an index holds: fewer segments");
  Mesh mesh;
  for (const Path& clipper_path : s_->section) {
    const Path p(clipper_path.rbegin(), clipper_path.rend());  // outer boundaries counter-clockwise in (Z, X)
    // each contour point's first vertex; a point on the axis has one, others one per step
    std::vector<std::uint32_t> first(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      first[i] = static_cast<std::uint32_t>(mesh.vertices.size());
      const double z = p[i].Y * kSectionUnit, x = p[i].X * kSectionUnit;
      if (p[i].X == 0) mesh.vertices.push_back({0, 0, z});
      else
        for (int k = 0; k < n; ++k) mesh.vertices.push_back({x * cs[k], x * sn[k], z});
    }
    // the band each edge a -> b sweeps: with the section's interior on the edge's left (Z right, X up),
    // (a_k, b_k, b_k+1) and (a_k, b_k+1, a_k+1) face outwards
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t j = (i + 1) % p.size();
      const bool a_axis = p[i].X == 0, b_axis = p[j].X == 0;
      if (a_axis && b_axis) continue;
      for (int k = 0; k < n; ++k) {
        const int k1 = (k + 1) % n;
        const std::uint32_t ak = first[i] + (a_axis ? 0 : k), ak1 = first[i] + (a_axis ? 0 : k1);
        const std::uint32_t bk = first[j] + (b_axis ? 0 : k), bk1 = first[j] + (b_axis ? 0 : k1);
        if (!b_axis) mesh.triangles.push_back({ak, bk, bk1});
        if (!a_axis) mesh.triangles.push_back({ak, bk1, ak1});
      }
    }
  }
  return mesh;
}

}  // namespace ncurve::sim
