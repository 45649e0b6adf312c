#include "sim/curve_walls.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "sim/verifier.hpp"

namespace ncurve::sim {

namespace {

// Where the material starts along p + s u at `level`, from s_in (under the cut) out to s_in +
// reach: marching in steps, then halving the step that leaves the cut. The wall's s and the cut
// that made it; nullopt when p + s_in u is not under the cut.
struct Wall {
  double s;
  std::int64_t cut;
};
std::optional<Wall> find_wall(const CutLog& cuts, double px, double py, double ux, double uy, double s_in,
                              double reach, double level) {
  auto below = [&](double s) { return cuts.any_below(px + s * ux, py + s * uy, level) >= 0; };
  if (!below(s_in)) return std::nullopt;
  const double step = std::max(cuts.largest_radius() / 64, 1e-4);
  double lo = s_in, hi = NAN;
  for (double s = s_in + step; s <= s_in + reach + step; s += step) {
    if (!below(s)) {
      hi = s;
      break;
    }
    lo = s;
  }
  if (!std::isnan(hi))
    for (int k = 0; k < 60 && hi - lo > 1e-8; ++k) {
      const double mid = 0.5 * (lo + hi);
      (below(mid) ? lo : hi) = mid;
    }
  return Wall{lo, cuts.lowest_at(px + lo * ux, py + lo * uy).cut};
}

}  // namespace

std::vector<double> points_along(const geom::Curve& curve, const WallOptions& o,
                                 const std::function<std::array<double, 2>(double t)>& at) {
  constexpr int kSurvey = 4096;
  std::vector<double> t(kSurvey + 1), length(kSurvey + 1, 0);
  double px = 0, py = 0;
  for (int k = 0; k <= kSurvey; ++k) {
    t[k] = curve.t0() + (curve.t1() - curve.t0()) * k / kSurvey;
    const std::array<double, 2> p = at(t[k]);
    if (k > 0) {
      const double step = std::hypot(p[0] - px, p[1] - py);
      length[k] = length[k - 1] + (std::isfinite(step) ? step : 0);
    }
    px = p[0], py = p[1];
  }
  const double total = length.back();
  if (!(total > 0)) throw std::runtime_error(fmt::format("the curve {} has no length in the plane measured", curve.name()));
  const auto n = static_cast<std::size_t>(
      std::clamp(total / o.spacing, static_cast<double>(o.min_points), static_cast<double>(o.max_points)));
  std::vector<double> out;
  out.reserve(n + 1);
  std::size_t k = 1;
  for (std::size_t i = 0; i <= n; ++i) {
    const double s = total * static_cast<double>(i) / static_cast<double>(n);
    while (k < length.size() - 1 && length[k] < s) ++k;
    const double span = length[k] - length[k - 1];
    const double f = span > 0 ? std::clamp((s - length[k - 1]) / span, 0.0, 1.0) : 0.0;
    out.push_back(t[k - 1] + f * (t[k] - t[k - 1]));
  }
  return out;
}

void WallReport::summarize() {
  largest_gouge = largest_left = rms = 0;
  gouge_at = left_at = -1;
  double sum2 = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double e = points[k].error;
    if (e > largest_gouge) largest_gouge = e, gouge_at = static_cast<std::int64_t>(k);
    if (-e > largest_left) largest_left = -e, left_at = static_cast<std::int64_t>(k);
    sum2 += e * e;
  }
  if (!points.empty()) rms = std::sqrt(sum2 / static_cast<double>(points.size()));
}

std::size_t WallReport::beyond(double tol) const {
  return static_cast<std::size_t>(
      std::count_if(points.begin(), points.end(), [&](const WallPoint& p) { return std::abs(p.error) > tol; }));
}

WallReport measure_walls(const CutLog& cuts, const geom::Curve& curve, const WallOptions& o) {
  WallReport r;
  r.design = o.design;
  auto xy = [&](double t) {
    const geom::Vec3 p = curve.point(t);
    return std::array<double, 2>{p[0], p[1]};
  };
  for (const double t : points_along(curve, o, xy)) {
    const geom::Curve::Jet j = curve.jet(t);
    const double px = j.p[0], py = j.p[1], dx = j.d1[0], dy = j.d1[1];
    const double speed = std::hypot(dx, dy);
    if (!(speed > 0) || !std::isfinite(px + py)) continue;
    const double nx = -dy / speed, ny = dx / speed;  // the left normal
    const double kappa = (dx * j.d2[1] - dy * j.d2[0]) / (speed * speed * speed);  // > 0: turning left
    WallPoint w{t, px, py, 0, 0, 0, 0, 0, -1};
    if (o.design == WallDesign::groove) {
      const CutLog::Lowest floor = cuts.lowest_at(px, py);
      if (floor.cut < 0 || !(floor.z < o.top - kFindingDepth)) {
        ++r.not_cut;
        continue;
      }
      w.level = 0.5 * (floor.z + o.top);
      const double half = cuts.shape(cuts[static_cast<std::size_t>(floor.cut)]).radius_at(w.level - floor.z);
      for (const double side : {1.0, -1.0}) {
        if (side * kappa > 0 && 1 / std::abs(kappa) <= half) {  // the offset wall folds over: no design wall
          ++r.no_design;
          continue;
        }
        const auto wall = find_wall(cuts, px, py, side * nx, side * ny, 0, half + cuts.largest_radius(), w.level);
        if (!wall) continue;
        w.nx = side * nx, w.ny = side * ny;
        w.design_offset = half;
        w.error = wall->s - half;
        w.cut = wall->cut;
        r.points.push_back(w);
      }
      continue;
    }
    // an edge: the tool's side is the one whose axis passes nearer the point a tool radius away
    double dl = INFINITY, dr = INFINITY;
    const double reach = cuts.largest_radius();
    const std::int64_t left = cuts.nearest(px + reach * nx, py + reach * ny, &dl);
    const std::int64_t right = cuts.nearest(px - reach * nx, py - reach * ny, &dr);
    if (left < 0 && right < 0) {
      ++r.not_cut;
      continue;
    }
    const double tool_side = dl <= dr ? 1.0 : -1.0;
    const double radius = cuts.shape(cuts[static_cast<std::size_t>(dl <= dr ? left : right)]).radius();
    const CutLog::Lowest floor = cuts.lowest_at(px + tool_side * radius * nx, py + tool_side * radius * ny);
    if (floor.cut < 0 || !(floor.z < o.top - kFindingDepth)) {
      ++r.not_cut;
      continue;
    }
    w.level = 0.5 * (floor.z + o.top);
    w.nx = -tool_side * nx, w.ny = -tool_side * ny;
    const auto wall = find_wall(cuts, px, py, w.nx, w.ny, -radius / 2, radius / 2 + cuts.largest_radius(), w.level);
    if (!wall) {
      ++r.not_cut;
      continue;
    }
    w.error = wall->s;
    w.cut = wall->cut;
    r.points.push_back(w);
  }
  r.summarize();
  return r;
}

BlockOf block_of(const CutLog& cuts) {
  return [&cuts](std::int64_t k) {
    const CutLog::Cut& c = cuts[static_cast<std::size_t>(k)];
    return std::pair{c.file, c.line};
  };
}

std::vector<Finding> wall_findings(const BlockOf& block, const WallReport& walls, double tol) {
  // the worst point of each block and code, listed in the order of the blocks' first cuts
  struct Worst {
    std::int64_t first_cut;
    std::size_t point;
  };
  std::map<std::tuple<const nc::SourceFile*, std::uint32_t, bool>, Worst> worst;
  for (std::size_t k = 0; k < walls.points.size(); ++k) {
    const WallPoint& p = walls.points[k];
    if (!(std::abs(p.error) > tol) || p.cut < 0) continue;
    const auto [file, line] = block(p.cut);
    auto [it, added] = worst.try_emplace({file, line, p.error > 0}, Worst{p.cut, k});
    if (added) continue;
    it->second.first_cut = std::min(it->second.first_cut, p.cut);
    if (std::abs(p.error) > std::abs(walls.points[it->second.point].error)) it->second.point = k;
  }
  std::vector<std::pair<std::int64_t, std::size_t>> order;
  for (const auto& [key, w] : worst) order.emplace_back(w.first_cut, w.point);
  std::sort(order.begin(), order.end());
  std::vector<Finding> out;
  for (const auto& [first, k] : order) {
    const WallPoint& p = walls.points[k];
    machine::Move m;
    std::tie(m.file, m.line) = block(p.cut);
    const double s = p.design_offset + p.error;  // the wall found, from the curve
    const double u = p.x + s * p.nx, v = p.y + s * p.ny;
    const std::array<double, 3> at = walls.turned ? std::array<double, 3>{v, 0, u} : std::array<double, 3>{u, v, p.level};
    const std::string where =
        walls.turned ? fmt::format("at t = {:.6g} of the curve (Z{:.4f}, radius {:.4f})", p.t, p.x, p.y)
                     : fmt::format("at t = {:.6g} of the curve (X{:.4f} Y{:.4f}, at Z{:.4f})", p.t, p.x, p.y, p.level);
    if (p.error > 0)
      out.push_back(finding_at(m, "NC2087",
                               fmt::format("the cut goes {:.4f} mm beyond the design's wall {}, more than the tolerance "
                                           "{:g} mm: the part is gouged",
                                           p.error, where, tol),
                               at, p.error));
    else
      out.push_back(finding_at(m, "NC2088",
                               fmt::format("the cut stops {:.4f} mm short of the design's wall {}, more than the "
                                           "tolerance {:g} mm: stock is left",
                                           -p.error, where, tol),
                               at, -p.error));
  }
  return out;
}

}  // namespace ncurve::sim
