// A tool's tip along an arc or helix in the XY plane. For a cell at distance D from the centre
// the squared distance to the tip at angle s along the move is u(s) = rho^2 + D^2 - 2 rho D
// cos(beta + s) (law of cosines); the cell is within reach R where cos(beta + s) >= c0, a window
// of half-width acos(c0) about each turn's nearest angle.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/lowest.hpp"
#include "sim/zmap.hpp"

namespace ncurve::sim {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

struct ArcCell {
  double rho, d;    // the arc's radius, the cell's distance from the centre
  double beta;      // s = -beta (+ turns) is the move's angle nearest the cell, in [-pi, pi)
  double length;    // the sweep's size, radians
  double z0, dzds;  // the tip's height along the move

  double u(double s) const { return rho * rho + d * d - 2 * rho * d * std::cos(beta + s); }
  double z(double s) const { return z0 + dzds * s; }
  // the least u on [s0, s1]: at a nearest angle within it, else at an end
  double u_min(double s0, double s1) const {
    if (rho == 0 || d == 0) return u(s0);
    if (std::floor((s1 + beta) / kTwoPi) >= std::ceil((s0 + beta) / kTwoPi)) return (rho - d) * (rho - d);
    return std::min(u(s0), u(s1));
  }
};

// The windows of s in [0, length] where the cell is within reach r; returns how many.
int reach_windows(const ArcCell& c, double r, double (&w)[8][2]) {
  double half;
  if (c.rho == 0 || c.d == 0) {
    if (c.u(0) > r * r) return 0;
    half = std::numbers::pi;
  } else {
    const double c0 = (c.rho * c.rho + c.d * c.d - r * r) / (2 * c.rho * c.d);
    if (c0 > 1) return 0;
    half = c0 <= -1 ? std::numbers::pi : std::acos(c0);
  }
  if (half >= std::numbers::pi) {
    w[0][0] = 0;
    w[0][1] = c.length;
    return 1;
  }
  int n = 0;
  const double k0 = std::ceil((c.beta - half) / kTwoPi), k1 = std::floor((c.length + c.beta + half) / kTwoPi);
  for (double k = k0; k <= k1 && n < 8; ++k) {
    const double m = kTwoPi * k - c.beta;
    const double lo = std::max(m - half, 0.0), hi = std::min(m + half, c.length);
    if (lo <= hi) {
      w[n][0] = lo;
      w[n][1] = hi;
      ++n;
    }
  }
  return n;
}

// Where the tool's height over the cell, as a function of s, is convex, concave or neither, by
// c = cos(beta + s), with A = rho^2 + D^2, B = 2 rho D:
// - ball: f'' has the sign of B c^2 + 2 (R^2 - A) c + B (from H(u) = R - sqrt(R^2 - u));
// - cone: of the distance's d'' = B (2 A c - B c^2 - B) / (4 d^3);
// - bull-nose: linear where the cell is over its flat bottom; convex where u'' >= 0 (c >= 0; its
//   height is convex, non-decreasing in u); else unknown.
enum class Curvature { convex, concave, unknown };

struct CurvatureSplit {
  double roots[2];  // the values of c where the curvature changes (or the bull-nose's flat ends)
  int n = 0;
};

CurvatureSplit curvature_split(const ArcCell& c, const ToolShape& tool) {
  const double a = c.rho * c.rho + c.d * c.d, b = 2 * c.rho * c.d, r2 = tool.radius() * tool.radius();
  CurvatureSplit s;
  auto quadratic = [&](double qa, double qb, double qc) {  // qa c^2 + qb c + qc = 0
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return;
    const double sq = std::sqrt(disc);
    s.roots[s.n++] = (-qb - sq) / (2 * qa);
    s.roots[s.n++] = (-qb + sq) / (2 * qa);
  };
  switch (tool.kind()) {
    case ToolShape::Kind::ball: quadratic(b, 2 * (r2 - a), b); break;
    case ToolShape::Kind::cone: quadratic(b, -2 * a, b); break;
    default: {
      s.roots[s.n++] = 0;
      const double flat = tool.radius() - tool.corner();  // where the flat bottom meets the torus
      s.roots[s.n++] = (a - flat * flat) / b;
      break;
    }
  }
  return s;
}

Curvature curvature_at(const ArcCell& c, const ToolShape& tool, double cs) {
  const double a = c.rho * c.rho + c.d * c.d, b = 2 * c.rho * c.d, r2 = tool.radius() * tool.radius();
  switch (tool.kind()) {
    case ToolShape::Kind::ball: return b * cs * cs + 2 * (r2 - a) * cs + b >= 0 ? Curvature::convex : Curvature::concave;
    case ToolShape::Kind::cone: return 2 * a * cs - b * cs * cs - b >= 0 ? Curvature::convex : Curvature::concave;
    default: {
      const double flat = tool.radius() - tool.corner();
      if (a - b * cs <= flat * flat) return Curvature::concave;  // over the flat bottom: linear in s
      return cs >= 0 ? Curvature::convex : Curvature::unknown;
    }
  }
}

// dH/du of a bull-nose: the torus's slope dh/dd over 2 d; infinite at the rim.
double bull_slope(const ToolShape& tool, double u) {
  const double d = std::sqrt(u), e = d - (tool.radius() - tool.corner());
  if (e <= 0) return 0;
  const double w2 = tool.corner() * tool.corner() - e * e;
  return w2 > 0 ? e / (std::sqrt(w2) * 2 * d) : kUnreached;
}

// A helix with a shaped tool on one window, cut where the curvature changes: a convex piece by
// golden section, a concave one at its ends, any other by branch and bound.
double lowest_on_helix(const ArcCell& c, const ToolShape& tool, double s0, double s1) {
  const double r2 = tool.radius() * tool.radius();
  auto f = [&](double s) { return c.z(s) + tool.lower(std::min(c.u(s), r2)); };
  if (c.rho == 0 || c.d == 0) return std::min(f(s0), f(s1));  // u constant
  const CurvatureSplit split = curvature_split(c, tool);
  double cuts[24];
  int n = 0;
  cuts[n++] = s0;
  const double k0 = std::floor((s0 + c.beta - std::numbers::pi) / kTwoPi), k1 = std::ceil((s1 + c.beta + std::numbers::pi) / kTwoPi);
  for (double k = k0; k <= k1 && n < 20; ++k) {
    const double m = kTwoPi * k - c.beta;
    auto cut = [&](double e) {
      if (e > s0 && e < s1 && n < 22) cuts[n++] = e;
    };
    cut(m - std::numbers::pi);
    for (int q = 0; q < split.n; ++q) {
      if (!(split.roots[q] > -1 && split.roots[q] < 1)) continue;
      const double angle = std::acos(split.roots[q]);
      cut(m - angle);
      cut(m + angle);
    }
  }
  cuts[n++] = s1;
  std::sort(cuts, cuts + n);
  double best = kUnreached;
  for (int p = 0; p + 1 < n; ++p) {
    const double a = cuts[p], b = cuts[p + 1];
    switch (curvature_at(c, tool, std::cos(c.beta + 0.5 * (a + b)))) {
      case Curvature::convex: best = std::min(best, lowest_convex(a, b, kLowestTolerance, f)); break;
      case Curvature::concave: best = std::min({best, f(a), f(b)}); break;
      case Curvature::unknown: {
        // u and |sin(beta + s)| are monotone on the piece and the bull-nose's dH/du grows with u,
        // so f' = dz/ds + H'(u) B sin(beta + s) lies between its values' bounds at the ends: two
        // lines from the ends bound f from below, to second order in the span.
        const double bb = 2 * c.rho * c.d;
        auto bound = [&](double x, double y) {
          const double fx = f(x), fy = f(y), sx = std::sin(c.beta + x), sy = std::sin(c.beta + y);
          const double ux = std::min(c.u(x), r2), uy = std::min(c.u(y), r2);
          const double g_lo = bull_slope(tool, std::min(ux, uy)) * bb * std::min(std::abs(sx), std::abs(sy));
          const double g_hi = bull_slope(tool, std::max(ux, uy)) * bb * std::max(std::abs(sx), std::abs(sy));
          const bool rising = std::sin(c.beta + 0.5 * (x + y)) > 0;
          const double d_lo = c.dzds + (rising ? g_lo : -g_hi), d_hi = c.dzds + (rising ? g_hi : -g_lo);
          const double coarse = std::min(c.z(x), c.z(y)) + tool.lower(std::min(c.u_min(x, y), r2));
          if (!std::isfinite(d_lo) || !std::isfinite(d_hi)) return coarse;  // at the rim
          // the least over [x, y] of max(fx + d_lo (s - x), fy - d_hi (y - s))
          double lb = std::min(std::max(fx, fy - d_hi * (y - x)), std::max(fx + d_lo * (y - x), fy));
          if (d_lo < d_hi) {
            const double t = (fy - fx - d_hi * y + d_lo * x) / (d_lo - d_hi);
            if (t > x && t < y) lb = std::min(lb, fx + d_lo * (t - x));
          }
          return std::max(lb, coarse);
        };
        best = std::min(best, lowest_on(a, b, kLowestTolerance, f, bound));
        break;
      }
    }
  }
  return best;
}

// The lowest tool point over the cell, or kUnreached.
double lowest_on_arc(const ArcCell& c, const ToolShape& tool) {
  double w[8][2];
  const int n = reach_windows(c, tool.radius(), w);
  double best = kUnreached;
  for (int k = 0; k < n; ++k) {
    const double s0 = w[k][0], s1 = w[k][1];
    double z;
    if (tool.kind() == ToolShape::Kind::flat) z = std::min(c.z(s0), c.z(s1));
    else if (c.dzds == 0) z = c.z0 + tool.lower(c.u_min(s0, s1));
    else z = lowest_on_helix(c, tool, s0, s1);
    best = std::min(best, z);
  }
  return best;
}

// The arc seen from the vertical line through (x, y).
ArcCell arc_cell(const Arc& arc, double x, double y) {
  const double length = std::abs(arc.sweep), dir = arc.sweep < 0 ? -1.0 : 1.0;
  ArcCell c{arc.radius, 0, 0, length, arc.z_start, length > 0 ? (arc.z_end - arc.z_start) / length : 0};
  const double dx = x - arc.cx, dy = y - arc.cy;
  c.d = std::hypot(dx, dy);
  // the point's angle phi; beta = dir (start - phi), wrapped
  const double phi = c.d > 0 ? std::atan2(dy, dx) : 0;
  double beta = std::remainder(dir * (arc.start_angle - phi), kTwoPi);
  if (beta >= std::numbers::pi) beta -= kTwoPi;
  c.beta = beta;
  return c;
}

bool arc_valid(const Arc& arc) { return arc.radius >= 0 && std::isfinite(std::abs(arc.sweep)); }

}  // namespace

XYBox arc_box(const Arc& arc) {
  const double rho = arc.radius, length = std::abs(arc.sweep), dir = arc.sweep < 0 ? -1.0 : 1.0;
  auto at = [&](double s) {
    const double t = arc.start_angle + dir * s;
    return std::array<double, 2>{arc.cx + rho * std::cos(t), arc.cy + rho * std::sin(t)};
  };
  auto p0 = at(0), p1 = at(length);
  XYBox b{std::min(p0[0], p1[0]), std::max(p0[0], p1[0]), std::min(p0[1], p1[1]), std::max(p0[1], p1[1])};
  for (int q = 0; q < 4; ++q) {
    const double qa = q * std::numbers::pi / 2;
    // the move's s that reaches angle qa first
    double s = std::fmod(dir * (qa - arc.start_angle), kTwoPi);
    if (s < 0) s += kTwoPi;
    if (s <= length) {
      auto p = at(s);
      b.x0 = std::min(b.x0, p[0]);
      b.x1 = std::max(b.x1, p[0]);
      b.y0 = std::min(b.y0, p[1]);
      b.y1 = std::max(b.y1, p[1]);
    }
  }
  return b;
}

double lowest_over(const ToolShape& tool, const Arc& arc, double x, double y) {
  if (!arc_valid(arc)) return kUnreached;
  return lowest_on_arc(arc_cell(arc, x, y), tool);
}

void ZMap::arc_rows(const ToolShape& tool, const Arc& arc, int& j0, int& j1) const {
  j0 = j1 = 0;
  if (!arc_valid(arc)) return;
  const double r = tool.radius(), pad = 1e-9 * (1 + r + arc.radius);
  const XYBox box = arc_box(arc);
  rows_of(box.y0 - r - pad, box.y1 + r + pad, j0, j1);
}

void ZMap::pass_arc(const ToolShape& tool, const Arc& arc, Pass& p) {
  const double r = tool.radius(), rho = arc.radius, pad = 1e-9 * (1 + r + rho);
  if (!arc_valid(arc)) return;
  const XYBox box = arc_box(arc);
  const double outer = rho + r;
  int j0, j1;
  arc_rows(tool, arc, j0, j1);
  j0 = std::max(j0, p.lo);
  j1 = std::min(j1, p.hi);
  for (int j = j0; j < j1; ++j) {
    const double y = cell_y(j), dy = y - arc.cy;
    const double w2 = outer * outer - dy * dy;
    if (w2 < 0) continue;
    const double w = std::sqrt(w2);
    int i0, i1;
    cells_of(std::max(box.x0 - r, arc.cx - w) - pad, std::min(box.x1 + r, arc.cx + w) + pad, i0, i1);
    if (i1 <= i0) continue;
    double* hr = row(j).data();
    before_row(hr + i0, i1 - i0, p);
    for (int i = i0; i < i1; ++i) hr[i] = std::min(hr[i], lowest_on_arc(arc_cell(arc, cell_x(i), y), tool));
    after_row(hr + i0, i0, j, i1 - i0, p);
  }
}

}  // namespace ncurve::sim
