// The cut part's walls against a curve: expected walls from closed-form geometry (a straight
// groove, a circle's contour) and from a second implementation (the distance to every chord of
// the path, brute force) for the first paper's spiral groove.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/curve_walls.hpp"

namespace ncurve::sim {
namespace {

using geom::Curve;
using geom::CurveSpec;

Curve expression(const std::string& x, const std::string& y, double from, double to) {
  CurveSpec spec;
  spec.name = "expr";
  spec.x = x;
  spec.y = y;
  spec.z = "0";
  spec.from = from;
  spec.to = to;
  return Curve(spec, {});
}

machine::Move block(std::uint32_t line) {
  machine::Move m;
  m.line = line;
  return m;
}

TEST(CurveWalls, StraightGrooveOnTheLineHasNoError) {
  CutLog cuts;
  cuts.add(ToolShape::flat(1.5), {0, 0, -0.5}, {20, 0, -0.5}, std::nullopt, block(10));
  WallOptions o;
  o.top = 0;
  const WallReport r = measure_walls(cuts, expression("t", "0", 2, 18), o);
  ASSERT_GT(r.points.size(), 1000u);  // both walls of 16 mm at 0.01 mm
  EXPECT_EQ(r.not_cut, 0u);
  EXPECT_LT(r.largest_gouge, 1e-6);
  EXPECT_LT(r.largest_left, 1e-6);
  for (const WallPoint& p : r.points) {
    EXPECT_DOUBLE_EQ(p.design_offset, 1.5);
    EXPECT_DOUBLE_EQ(p.level, -0.25);  // halfway from the floor to the top
  }
  EXPECT_TRUE(wall_findings(block_of(cuts), r, 0.01).empty());
}

TEST(CurveWalls, GrooveBesideTheLineGougesOneWallAndLeavesTheOther) {
  CutLog cuts;
  // the path 0.02 to the left (+Y) of the curve's direction (+X)
  cuts.add(ToolShape::flat(1.5), {0, 0.02, -0.5}, {20, 0.02, -0.5}, std::nullopt, block(10));
  WallOptions o;
  const WallReport r = measure_walls(cuts, expression("t", "0", 2, 18), o);
  EXPECT_NEAR(r.largest_gouge, 0.02, 1e-6);
  EXPECT_NEAR(r.largest_left, 0.02, 1e-6);
  for (const WallPoint& p : r.points) EXPECT_NEAR(p.error, p.ny > 0 ? 0.02 : -0.02, 1e-6);
  const std::vector<Finding> f = wall_findings(block_of(cuts), r, 0.01);
  ASSERT_EQ(f.size(), 2u);  // one a block and code
  EXPECT_EQ(f[0].diagnostic.code, "NC2087");
  EXPECT_EQ(f[1].diagnostic.code, "NC2088");
  EXPECT_EQ(f[0].diagnostic.span.line, 10u);
  EXPECT_NEAR(f[0].amount, 0.02, 1e-6);
  EXPECT_NEAR(f[0].at[1], 1.52, 1e-6);  // the gouged wall, 1.5 + 0.02 from the curve
  EXPECT_TRUE(wall_findings(block_of(cuts), r, 0.03).empty());
}

TEST(CurveWalls, BallGrooveWallAtHalfDepth) {
  // a ball R 2 sunk 1 mm: at half depth (0.5 above the tip) the groove is sqrt(2 R h - h^2) wide each way
  CutLog cuts;
  cuts.add(ToolShape::ball(2), {0, 0, -1}, {20, 0, -1}, std::nullopt, block(10));
  const WallReport r = measure_walls(cuts, expression("t", "0", 2, 18), WallOptions{});
  ASSERT_FALSE(r.points.empty());
  for (const WallPoint& p : r.points) {
    EXPECT_NEAR(p.design_offset, std::sqrt(2 * 2 * 0.5 - 0.25), 1e-12);
    EXPECT_NEAR(p.error, 0, 1e-6);
  }
}

TEST(CurveWalls, GrooveTheToolNeverCutIsNotMeasured) {
  CutLog cuts;
  cuts.add(ToolShape::flat(1.5), {0, 0, -0.5}, {10, 0, -0.5}, std::nullopt, block(10));
  WallOptions o;
  o.min_points = 1000;
  const WallReport r = measure_walls(cuts, expression("t", "0", 0, 20), o);
  // the tool's end disc reaches X 11.5: the 2000 steps' points beyond have no groove under them
  EXPECT_NEAR(static_cast<double>(r.not_cut), (20 - 11.5) / 20 * 2000, 2.0);
  // within the end disc the groove narrows: its walls short of the design by up to R
  EXPECT_NEAR(r.largest_left, 1.5, 0.01);
}

TEST(CurveWalls, ContourEdgeByACompensatedCircle) {
  // a pocket's wall on the circle of radius 10: the tool's axis on radius 10 - D
  const Curve circle = expression("10*COS[t]", "10*SIN[t]", 0, 360);
  for (const double d : {3.0, 2.98, 3.05}) {
    CutLog cuts;
    Arc arc;
    arc.radius = 10 - d;
    arc.sweep = 2 * std::numbers::pi;
    arc.z_start = arc.z_end = -5;
    cuts.add(ToolShape::flat(3), {arc.radius, 0, -5}, {arc.radius, 0, -5}, arc, block(20));
    WallOptions o;
    o.design = WallDesign::edge;
    const WallReport r = measure_walls(cuts, circle, o);
    ASSERT_GT(r.points.size(), 500u);
    EXPECT_EQ(r.not_cut, 0u);
    // a smaller D puts the tool out by 3 - D: a gouge of it; a larger leaves stock
    for (const WallPoint& p : r.points) EXPECT_NEAR(p.error, 3 - d, 1e-6) << d;
    for (const WallPoint& p : r.points) EXPECT_NEAR(p.nx * p.x + p.ny * p.y, 10, 1e-9);  // measured outwards
  }
}

// The first paper's spiral r = 1 + 2 theta over one turn as 100 equal-angle chords, cut 0.5 deep by
// a flat end mill of R 1.5 (examples/spiral.nc): every wall measured against the one a second
// implementation finds from the distance to all the chords, and the largest errors against the
// chords' largest distance from the spiral.
TEST(CurveWalls, SpiralGrooveAgainstTheChordsOffset) {
  const double R = 1.5;
  std::vector<std::array<double, 2>> p;
  for (int k = 0; k <= 100; ++k) {
    const double th = 2 * std::numbers::pi * k / 100, r = 1 + 2 * th;
    p.push_back({r * std::cos(th), r * std::sin(th)});
  }
  CutLog cuts;
  for (std::size_t k = 1; k < p.size(); ++k)
    cuts.add(ToolShape::flat(R), {p[k - 1][0], p[k - 1][1], -0.5}, {p[k][0], p[k][1], -0.5}, std::nullopt,
             block(static_cast<std::uint32_t>(20 + k)));
  const Curve spiral = expression("[1+2*t*PI/180]*COS[t]", "[1+2*t*PI/180]*SIN[t]", 0, 360);
  const WallReport r = measure_walls(cuts, spiral, WallOptions{});

  auto distance = [&](double x, double y) {
    double best = INFINITY;
    for (std::size_t k = 1; k < p.size(); ++k) {
      const double vx = p[k][0] - p[k - 1][0], vy = p[k][1] - p[k - 1][1];
      const double t = std::clamp(((x - p[k - 1][0]) * vx + (y - p[k - 1][1]) * vy) / (vx * vx + vy * vy), 0.0, 1.0);
      best = std::min(best, std::hypot(x - p[k - 1][0] - t * vx, y - p[k - 1][1] - t * vy));
    }
    return best;
  };
  ASSERT_GT(r.points.size(), 8000u);
  for (std::size_t k = 0; k < r.points.size(); k += 7) {
    const WallPoint& w = r.points[k];
    // the wall: where the distance to the chords first reaches R along the normal
    double lo = 0, hi = 0;
    for (double s = 0.01; s < 2 * R; s += 0.01) {
      if (distance(w.x + s * w.nx, w.y + s * w.ny) > R) {
        hi = s;
        break;
      }
      lo = s;
    }
    for (int k = 0; k < 50; ++k) {
      const double mid = 0.5 * (lo + hi);
      (distance(w.x + mid * w.nx, w.y + mid * w.ny) > R ? hi : lo) = mid;
    }
    ASSERT_NEAR(w.error, lo - R, 1e-6) << "t = " << w.t;
  }
  // the chords' sagitta: the largest distance from the spiral to its chords, sampled finely
  double sagitta = 0;
  for (int k = 0; k <= 100000; ++k) {
    const double th = 2 * std::numbers::pi * k / 100000, rr = 1 + 2 * th;
    sagitta = std::max(sagitta, distance(rr * std::cos(th), rr * std::sin(th)));
  }
  EXPECT_NEAR(sagitta, 0.0069, 0.0001);  // the seeds' 6.9 um for 100 equal-angle segments
  // the chords lie inside the spiral's turn: the outer wall is short by up to the sagitta, the
  // inner one cut beyond by as much, both within the curvature's share of the tool's radius
  EXPECT_NEAR(r.largest_left, sagitta, 0.15 * sagitta);
  EXPECT_NEAR(r.largest_gouge, sagitta, 0.15 * sagitta);
  // where the spiral turns tighter than the tool (radius of curvature 1.24 at t = 0) the inner
  // wall has no design
  EXPECT_GT(r.no_design, 0u);
}

}  // namespace
}  // namespace ncurve::sim

namespace ncurve::sim {
namespace {

TEST(CurveWalls, RadiusAtIsTheInverseOfTheLowerSurface) {
  for (const ToolShape& t : {ToolShape::ball(2), ToolShape::bull_nose(3, 1), ToolShape::cone(4, 90)})
    for (double h = 0.01; h < t.rim_height(); h += 0.01) EXPECT_NEAR(t.lower(std::pow(t.radius_at(h), 2)), h, 1e-9);
  EXPECT_DOUBLE_EQ(ToolShape::flat(3).radius_at(0.001), 3);
  EXPECT_DOUBLE_EQ(ToolShape::cone(4, 90).radius_at(1), 1);  // a 90-degree point: as wide as high
  EXPECT_DOUBLE_EQ(ToolShape::bull_nose(3, 1).radius_at(5), 3);
  EXPECT_DOUBLE_EQ(ToolShape::ball(2).radius_at(-1), 0);
}

TEST(CurveWalls, PointProbeIsTheCellsHeight) {
  // lowest_over at a cell's centre is the height the map's row kernels give that cell
  ZMap map(Box{{-10, -10, -10}, {10, 10, 0}}, 0.5);
  const ToolShape tools[] = {ToolShape::flat(2), ToolShape::ball(2), ToolShape::bull_nose(2, 0.5), ToolShape::cone(2, 118)};
  for (const ToolShape& t : tools) {
    ZMap a = map, b = map;
    a.cut_line(t, {-6, -3, -1}, {5, 4, -3});
    Arc arc{1, -1, 5, 0.3, 2.5, -1, -4};
    b.cut_arc(t, arc);
    for (int j = 0; j < map.ny(); ++j)
      for (int i = 0; i < map.nx(); ++i) {
        const double x = map.cell_x(i), y = map.cell_y(j);
        EXPECT_EQ(std::min(0.0, lowest_over(t, {-6, -3, -1}, {5, 4, -3}, x, y)), a.height(i, j));
        EXPECT_EQ(std::min(0.0, lowest_over(t, arc, x, y)), b.height(i, j));
      }
  }
}

}  // namespace
}  // namespace ncurve::sim
