#include "sim/section_walls.hpp"

#include <algorithm>
#include <cmath>

#include "machine/arc_points.hpp"

namespace ncurve::sim {

void ProfileMoves::on_move(const machine::Move& m) {
  if (m.kind != machine::MoveKind::line && m.kind != machine::MoveKind::arc) return;
  auto add = [&](const machine::AxisVector& a, const machine::AxisVector& b) {
    segments_.push_back({a[2], std::fabs(a[0]), b[2], std::fabs(b[0]), m.file, m.line});
  };
  if (m.kind == machine::MoveKind::line || m.plane != 18) {
    add(m.start, m.end);
    return;
  }
  machine::AxisVector from = m.start;
  machine::arc_points(m, 1e-3, [&](const machine::AxisVector& p) {
    add(from, p);
    from = p;
  });
}

std::int64_t ProfileMoves::nearest(double z, double r) const {
  std::int64_t best = -1;
  double d = INFINITY;
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const Segment& s = segments_[k];
    const double e = geom::point_segment_distance({z, r, 0}, {s.z0, s.r0, 0}, {s.z1, s.r1, 0});
    if (e < d) d = e, best = static_cast<std::int64_t>(k);
  }
  return best;
}

BlockOf ProfileMoves::block() const {
  return [this](std::int64_t k) {
    const Segment& s = segments_[static_cast<std::size_t>(k)];
    return std::pair{s.file, s.line};
  };
}

WallReport measure_section_walls(const LatheSection& section, const ProfileMoves& moves, const geom::Curve& curve,
                                 const geom::Placement& place, const WallOptions& o) {
  WallReport r;
  r.design = WallDesign::edge;
  r.turned = true;
  auto zr = [&](double t) {
    const geom::Vec3 p = place(curve.point(t));
    return std::array<double, 2>{p[2], p[0]};
  };
  std::vector<std::array<double, 2>> surface;  // each point's surface found, (Z, radius)
  for (const double t : points_along(curve, o, zr)) {
    const geom::Curve::Jet j = curve.jet(t);
    const geom::Vec3 p = place(j.p), d = place.direction(j.d1);
    const double z = p[2], radius = p[0], dz = d[2], dr = d[0], speed = std::hypot(dz, dr);
    if (!(speed > 0) || !std::isfinite(z + radius)) continue;
    const double nr = std::fabs(dz) / speed;  // the normal's radial part
    if (nr < std::sin(6 * 3.141592653589793 / 180)) {
      ++r.no_design;
      continue;
    }
    // the part's surface: the boundary nearest the curve on the radial line at z (a ring of stock
    // left farther out, beyond the insert's reach, is not the surface cut here)
    const std::vector<double> across = section.crossings(z);
    double part = NAN;
    for (double c : across)
      if (std::isnan(part) || std::fabs(c - radius) < std::fabs(part - radius)) part = c;
    // the material's side of that surface: below it (an outside profile) when an odd number of
    // crossings lie below a point just under it
    const bool below = std::isnan(part) ||
                       std::count_if(across.begin(), across.end(), [&](double c) { return c < part - 1e-6; }) % 2 == 1;
    const double beyond = std::isnan(part) ? radius : below ? radius - part : part - radius;  // + a gouge
    WallPoint w;
    w.t = t, w.x = z, w.y = radius;
    const double sign = below ? 1 : -1;  // the normal into the material (as a wall's)
    w.nx = sign * (dz > 0 ? dr : -dr) / speed, w.ny = -sign * nr;
    w.error = beyond * nr;
    surface.push_back({z, std::isnan(part) ? radius : part});
    r.points.push_back(w);
  }
  r.summarize();
  // the move that made the surface, where a finding or the summary names it: the search is over
  // every feed move
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    const auto at = static_cast<std::int64_t>(k);
    if (std::fabs(r.points[k].error) > o.tol || at == r.gouge_at || at == r.left_at)
      r.points[k].cut = moves.nearest(surface[k][0], surface[k][1]);
  }
  return r;
}

}  // namespace ncurve::sim
