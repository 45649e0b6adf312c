// A tool's tip along a straight line: the stadium of cells it reaches row by row, and in each
// cell the lowest point of the swept tool on the cell's vertical line.
#include <algorithm>
#include <cmath>

#include "base/vector_clones.hpp"
#include "sim/lowest.hpp"
#include "sim/zmap.hpp"

namespace ncurve::sim {

namespace {

// The move relative to its start: the tip at A + t (vx, vy, dz), t in [0, 1].
struct LineMove {
  double ax, ay, az;
  double vx, vy, dz;
  double a;  // vx^2 + vy^2
  double r;
};

// Flat end mill: the parameters where the cell is within R of the axis are the roots of a
// quadratic, whose discriminant is a R^2 - (o x v)^2 (Lagrange's identity); z is linear in t, so
// the lowest is at the interval's end in the falling direction.
NCURVE_VECTOR_CLONES void flat_row(double* __restrict h, int n, double ox0, double oy,
                                   const double* __restrict steps, const LineMove& m) {
  const double vx = m.vx, vy = m.vy, az = m.az, dz = m.dz, inv_a = 1 / m.a;
  const double ar2 = m.a * m.r * m.r, vyoy = vy * oy, vxoy = vx * oy;
  const bool falling = dz < 0;
  for (int k = 0; k < n; ++k) {
    const double ox = ox0 + steps[k];
    const double ov = ox * vx + vyoy, cr = vxoy - vy * ox;
    const double disc = ar2 - cr * cr;
    const double sq = std::sqrt(std::max(disc, 0.0));
    const double lo = std::max((ov - sq) * inv_a, 0.0), hi = std::min((ov + sq) * inv_a, 1.0);
    const double t = falling ? hi : lo;
    const bool reached = (disc >= 0) & (lo <= hi);
    h[k] = std::min(h[k], reached ? az + t * dz : kUnreached);
  }
}

// Ball end mill: the ball's centre sweeps a capsule of radius R; the lowest point of the
// capsule on the vertical line is where an upward ray enters it (the infinite cylinder about the
// axis if it enters within the segment, else the sphere at the end it entered beyond). The ray
// meets the cylinder where disc = |ba|^2 (a R^2 - (o x v)^2) >= 0 (Lagrange's identity).
NCURVE_VECTOR_CLONES void ball_row(double* __restrict h, int n, double ox0, double oy,
                                   const double* __restrict steps, const LineMove& m) {
  const double vx = m.vx, vy = m.vy, a = m.a, dz = m.dz, r2 = m.r * m.r;
  const double baba = a + dz * dz, inv_a = 1 / a, base = m.az + m.r, ar2 = a * r2;
  const double vyoy = vy * oy, vxoy = vx * oy, oy2 = oy * oy, eyb2 = (oy - vy) * (oy - vy);
  for (int k = 0; k < n; ++k) {
    const double ox = ox0 + steps[k];
    const double baoa = vx * ox + vyoy, cr = vxoy - vy * ox;
    const double disc = baba * (ar2 - cr * cr);
    const double t = (baoa * dz - std::sqrt(std::max(disc, 0.0))) * inv_a;
    const double y = baoa + t * dz;
    const bool at_b = y >= baba;
    // the squared horizontal distance to the end sphere's centre
    const double exb = ox - vx;
    const double e2 = at_b ? exb * exb + eyb2 : ox * ox + oy2;
    const double cap2 = r2 - e2;
    const double zcap = (at_b ? dz : 0.0) - std::sqrt(std::max(cap2, 0.0));
    const bool side = (y > 0) & (y < baba);
    const bool reached = (disc >= 0) & (side | (cap2 >= 0));
    h[k] = std::min(h[k], reached ? base + (side ? t : zcap) : kUnreached);
  }
}

// Any tool on a level line: its lower surface at the cell's distance from the segment.
void level_row(double* h, int n, double ox0, double oy, double step, const LineMove& m, const ToolShape& tool) {
  for (int k = 0; k < n; ++k) {
    const double ox = ox0 + k * step;
    const double t = m.a > 0 ? std::clamp((ox * m.vx + oy * m.vy) / m.a, 0.0, 1.0) : 0.0;
    const double ex = ox - t * m.vx, ey = oy - t * m.vy;
    h[k] = std::min(h[k], m.az + tool.lower(ex * ex + ey * ey));
  }
}

// Any tool on a vertical line: at its lower end.
void plunge_row(double* h, int n, double ox0, double oy, double step, const LineMove& m, const ToolShape& tool) {
  const double zlow = m.az + std::min(m.dz, 0.0);
  for (int k = 0; k < n; ++k) {
    const double ox = ox0 + k * step;
    h[k] = std::min(h[k], zlow + tool.lower(ox * ox + oy * oy));
  }
}

// Bull-nose or cone on a sloping line: z(t) + lower(u(t)) over the parameters where the cell is
// within reach. u is a convex quadratic in t and the shape's height a convex, non-decreasing
// function of u (bull-nose) or of sqrt(u), the distance to the axis, itself convex in t (cone):
// the sum is convex.
void sloping_row(double* h, int n, double ox0, double oy, double step, const LineMove& m, const ToolShape& tool) {
  const double r2 = m.r * m.r;
  for (int k = 0; k < n; ++k) {
    const double ox = ox0 + k * step;
    const double ov = ox * m.vx + oy * m.vy, oo = ox * ox + oy * oy;
    const double disc = ov * ov - m.a * (oo - r2);
    if (disc < 0) continue;
    const double sq = std::sqrt(disc);
    const double lo = std::max((ov - sq) / m.a, 0.0), hi = std::min((ov + sq) / m.a, 1.0);
    if (lo > hi) continue;
    auto f = [&](double t) {
      const double ex = ox - t * m.vx, ey = oy - t * m.vy;
      return m.az + t * m.dz + tool.lower(std::min(ex * ex + ey * ey, r2));  // within reach by construction
    };
    h[k] = std::min(h[k], lowest_convex(lo, hi, kLowestTolerance, f));
  }
}

}  // namespace

double lowest_over(const ToolShape& tool, const Point3& a, const Point3& b, double x, double y) {
  LineMove m{a[0], a[1], a[2], b[0] - a[0], b[1] - a[1], b[2] - a[2], 0, tool.radius()};
  m.a = m.vx * m.vx + m.vy * m.vy;
  const double ox = x - a[0], oy = y - a[1];
  double h = kUnreached;
  const double no_step = 0;
  if (m.a <= 1e-24 * (1 + m.dz * m.dz)) plunge_row(&h, 1, ox, oy, 0, m, tool);
  else if (tool.kind() == ToolShape::Kind::flat) flat_row(&h, 1, ox, oy, &no_step, m);
  else if (tool.kind() == ToolShape::Kind::ball) ball_row(&h, 1, ox, oy, &no_step, m);
  else if (m.dz == 0) level_row(&h, 1, ox, oy, 0, m, tool);
  else sloping_row(&h, 1, ox, oy, 0, m, tool);
  return h;
}

void ZMap::line_rows(const ToolShape& tool, const Point3& a, const Point3& b, int& j0, int& j1) const {
  const double r = tool.radius(), pad = 1e-9 * (1 + r);
  rows_of(std::min(a[1], b[1]) - r - pad, std::max(a[1], b[1]) + r + pad, j0, j1);
}

void ZMap::pass_line(const ToolShape& tool, const Point3& a, const Point3& b, Pass& p) {
  LineMove m{a[0], a[1], a[2], b[0] - a[0], b[1] - a[1], b[2] - a[2], 0, tool.radius()};
  m.a = m.vx * m.vx + m.vy * m.vy;
  const double r = m.r, pad = 1e-9 * (1 + r);
  const double len = std::sqrt(m.a);
  // the outward normal of the stadium's sides
  const double nx = len > 0 ? -m.vy / len : 0, ny = len > 0 ? m.vx / len : 0;
  const bool plunge = m.a <= 1e-24 * (1 + m.dz * m.dz);
  const double inv_vy = 1 / m.vy;  // used where vy != 0
  int j0, j1;
  line_rows(tool, a, b, j0, j1);
  j0 = std::max(j0, p.lo);
  j1 = std::min(j1, p.hi);
  for (int j = j0; j < j1; ++j) {
    const double y = cell_y(j);
    // the row's chord of the stadium: of the end discs and the two sides
    double xl = kUnreached, xh = -kUnreached;
    auto disc_chord = [&](double cx, double cy) {
      const double dy = y - cy, w2 = r * r - dy * dy;
      if (w2 < 0) return;
      const double w = std::sqrt(w2);
      xl = std::min(xl, cx - w);
      xh = std::max(xh, cx + w);
    };
    disc_chord(a[0], a[1]);
    disc_chord(b[0], b[1]);
    if (!plunge && m.vy != 0) {
      for (double side : {-1.0, 1.0}) {
        const double t = (y - a[1] - side * r * ny) * inv_vy;
        if (t >= 0 && t <= 1) {
          const double x = a[0] + side * r * nx + t * m.vx;
          xl = std::min(xl, x);
          xh = std::max(xh, x);
        }
      }
    }
    int i0, i1;
    cells_of(xl - pad, xh + pad, i0, i1);
    if (i1 <= i0) continue;
    if (!plunge && (tool.kind() == ToolShape::Kind::flat || tool.kind() == ToolShape::Kind::ball))
      whole_vectors(i0, i1);
    double* hr = row(j).data() + i0;
    const int n = i1 - i0;
    const double ox0 = cell_x(i0) - a[0], oy = y - a[1];
    before_row(hr, n, p);
    if (plunge) plunge_row(hr, n, ox0, oy, cell(), m, tool);
    else if (tool.kind() == ToolShape::Kind::flat) flat_row(hr, n, ox0, oy, steps_.data(), m);
    else if (tool.kind() == ToolShape::Kind::ball) ball_row(hr, n, ox0, oy, steps_.data(), m);
    else if (m.dz == 0) level_row(hr, n, ox0, oy, cell(), m, tool);
    else sloping_row(hr, n, ox0, oy, cell(), m, tool);
    after_row(hr, i0, j, n, p);
  }
}

}  // namespace ncurve::sim
