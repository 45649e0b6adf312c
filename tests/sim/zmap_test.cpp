// The Z-map against closed forms. Each cell holds the exact lowest tool point on the vertical line
// through its centre, so a height is checked to rounding (1e-9 mm; kLowestTolerance where the
// lowest is found by minimising); a position in XY is within one cell; a volume counts whole
// cells, so it is within depth x (band of half a cell diagonal either side of the outline).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/zmap.hpp"

using namespace ncurve::sim;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kExact = 1e-9;

// 100 x 100 x 20 mm, top at Z0: 1000 x 1000 cells of 0.1 mm, centres at 0.05 + 0.1 k
ZMap stock() { return ZMap(Box{{0, 0, -20}, {100, 100, 0}}); }

// the cell's index along an axis for a centre coordinate c = 0.05 + 0.1 k
int at(double c) { return static_cast<int>(std::lround((c - 0.05) / 0.1)); }

double dist_to_segment(double px, double py, double ax, double ay, double bx, double by) {
  const double vx = bx - ax, vy = by - ay;
  const double t = std::clamp(((px - ax) * vx + (py - ay) * vy) / (vx * vx + vy * vy), 0.0, 1.0);
  return std::hypot(px - ax - t * vx, py - ay - t * vy);
}

// a volume's bound: depth x a band of sqrt(2) cells about an outline of this length
double volume_bound(const ZMap& m, double depth, double perimeter) {
  return depth * std::sqrt(2.0) * m.cell() * perimeter;
}

}  // namespace

TEST(ZMap, GridFromTheStock) {
  ZMap m = stock();
  EXPECT_EQ(m.nx(), 1000);
  EXPECT_EQ(m.ny(), 1000);
  EXPECT_DOUBLE_EQ(m.cell(), 0.1);
  EXPECT_DOUBLE_EQ(m.height_at(50, 50), 0);
  EXPECT_TRUE(std::isnan(m.height_at(-1, 50)));
  EXPECT_EQ(m.volume_removed(), 0);
  // the shorter side gets the 1000 cells
  ZMap long_stock(Box{{0, 0, 0}, {200, 50, 10}});
  EXPECT_EQ(long_stock.nx(), 4000);
  EXPECT_EQ(long_stock.ny(), 1000);
  ZMap given(Box{{0, 0, 0}, {10, 10, 1}}, 0.5);
  EXPECT_EQ(given.nx(), 20);
  EXPECT_THROW(ZMap(Box{{0, 0, 0}, {0, 10, 1}}), std::invalid_argument);
}

TEST(ZMap, ToolShapes) {
  EXPECT_EQ(ToolShape::flat(5).lower(16), 0);
  EXPECT_EQ(ToolShape::flat(5).lower(26), kUnreached);
  EXPECT_NEAR(ToolShape::ball(5).lower(9), 1, 1e-15);           // 5 - 4
  EXPECT_NEAR(ToolShape::bull_nose(5, 2).lower(9), 0, 0);      // on the flat bottom
  EXPECT_NEAR(ToolShape::bull_nose(5, 2).lower(25), 2, 1e-15);  // at the rim
  EXPECT_NEAR(ToolShape::bull_nose(5, 2).lower(16), 2 - std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(ToolShape::cone(5, 90).lower(4), 2, 1e-15);
  EXPECT_EQ(ToolShape::bull_nose(5, 5).kind(), ToolShape::Kind::ball);
  EXPECT_EQ(ToolShape::bull_nose(5, 0).kind(), ToolShape::Kind::flat);
}

// A flat end mill's straight slot: length x width x depth plus two half-disc ends.
TEST(ZMap, FlatSlotVolume) {
  ZMap m = stock();
  const double r = 5, depth = 3, len = 60;
  m.cut_line(ToolShape::flat(r), {20, 50, -depth}, {20 + len, 50, -depth});
  const double exact = len * 2 * r * depth + kPi * r * r * depth;
  EXPECT_NEAR(m.volume_removed(), exact, volume_bound(m, depth, 2 * len + 2 * kPi * r));
  EXPECT_NEAR(m.volume_removed(), exact, exact * 1e-3);
  // every cell inside is at the floor, every cell outside untouched
  for (int j = 0; j < m.ny(); j += 7)
    for (int i = 0; i < m.nx(); i += 3) {
      const double d = dist_to_segment(m.cell_x(i), m.cell_y(j), 20, 50, 80, 50);
      if (d < r - kExact) {
        ASSERT_EQ(m.height(i, j), -depth) << i << " " << j;
      } else if (d > r + kExact) {
        ASSERT_EQ(m.height(i, j), 0) << i << " " << j;
      }
    }
}

// A circular pocket (plunge at the centre, out to the circle, a full G03 circle): its wall at
// the path's radius plus the tool's, within a cell.
TEST(ZMap, CircularPocketWall) {
  ZMap m = stock();
  const auto tool = ToolShape::flat(4);
  const double cx = 50, cy = 50, rho = 6, floor = -5;
  m.cut_line(tool, {cx, cy, 5}, {cx, cy, floor});
  m.cut_line(tool, {cx, cy, floor}, {cx + rho, cy, floor});
  m.cut_arc(tool, Arc{cx, cy, rho, 0, 2 * kPi, floor, floor});
  const double wall = rho + 4;
  for (int j = 0; j < m.ny(); ++j)
    for (int i = 0; i < m.nx(); ++i) {
      const double d = std::hypot(m.cell_x(i) - cx, m.cell_y(j) - cy);
      if (d < wall - kExact) {
        ASSERT_EQ(m.height(i, j), floor);
      } else if (d > wall + kExact) {
        ASSERT_EQ(m.height(i, j), 0);
      }
    }
  // along +X from the centre, the first uncut cell is within a cell beyond the wall
  const int j = at(50.05);
  int i = at(50.05);
  while (m.height(i, j) == floor) ++i;
  const double edge = std::hypot(m.cell_x(i) - cx, m.cell_y(j) - cy);
  EXPECT_GE(edge, wall);
  EXPECT_LE(edge, wall + m.cell());
  EXPECT_NEAR(m.volume_removed(), kPi * wall * wall * -floor, volume_bound(m, -floor, 2 * kPi * wall));
}

// An arc of a quarter turn, either way round: cut along it and round its ends, not beyond.
TEST(ZMap, ArcReachesItsSweepOnly) {
  for (double sweep : {kPi / 2, -kPi / 2}) {
    ZMap m = stock();
    const double start = sweep > 0 ? 0 : kPi / 2;
    m.cut_arc(ToolShape::flat(1), Arc{50.05, 50.05, 10, start, sweep, -1, -1});
    auto h = [&](double angle, double radius) {
      return m.height_at(50.05 + radius * std::cos(angle), 50.05 + radius * std::sin(angle));
    };
    EXPECT_EQ(h(kPi / 4, 10), -1);
    EXPECT_EQ(h(kPi / 4, 10.9), -1);
    EXPECT_EQ(h(kPi / 4, 8.9), 0);
    EXPECT_EQ(h(-0.05, 10), -1);           // 0.5 mm from the start: in the end disc
    EXPECT_EQ(h(100 * kPi / 180, 10), 0);  // 1.74 mm beyond the end
    EXPECT_EQ(h(kPi, 10), 0);
  }
}

// A ball end mill's slot: a circle of radius R in cross-section.
TEST(ZMap, BallSlotCrossSection) {
  ZMap m = stock();
  const double r = 3, tip = -2, y0 = 50.05;
  m.cut_line(ToolShape::ball(r), {20, y0, tip}, {80, y0, tip});
  const int i = at(50.05);
  for (int k = -40; k <= 40; ++k) {
    const double dy = 0.1 * k;
    const double expect = std::abs(dy) <= r ? std::min(tip + r - std::sqrt(r * r - dy * dy), 0.0) : 0.0;
    EXPECT_NEAR(m.height(i, at(y0 + dy)), expect, kExact) << dy;
  }
}

// The ball along a slanting line: the sphere at the cell's distance from the segment.
TEST(ZMap, BallLevelLineAnyDirection) {
  ZMap m = stock();
  const double r = 4, tip = -3;
  m.cut_line(ToolShape::ball(r), {20, 20, tip}, {70, 60, tip});
  for (int j = 100; j < 700; j += 13)
    for (int i = 100; i < 800; i += 11) {
      const double d = dist_to_segment(m.cell_x(i), m.cell_y(j), 20, 20, 70, 60);
      const double expect = d <= r ? std::min(tip + r - std::sqrt(r * r - d * d), 0.0) : 0.0;
      ASSERT_NEAR(m.height(i, j), expect, kExact) << i << " " << j;
    }
}

// Parallel passes of a ball end mill at stepover s leave scallops h = R - sqrt(R^2 - (s/2)^2).
TEST(ZMap, BallScallopHeight) {
  ZMap m = stock();
  const double r = 5, s = 2, tip = -3;
  for (int k = 0; k < 5; ++k) m.cut_line(ToolShape::ball(r), {20, 41.05 + k * s, tip}, {80, 41.05 + k * s, tip});
  const double h = r - std::sqrt(r * r - s * s / 4);
  for (int k = 0; k < 4; ++k) {
    const double pass = 41.05 + k * s;
    for (double x : {30.05, 50.05, 70.05}) {
      EXPECT_NEAR(m.height_at(x, pass), tip, kExact);
      EXPECT_NEAR(m.height_at(x, pass + s / 2), tip + h, kExact);  // the cusp, midway
      // no cell between the passes higher than the cusp
      for (int q = 0; q <= 20; ++q) EXPECT_LE(m.height_at(x, pass + 0.1 * q), tip + h + kExact);
    }
  }
}

// A flat end mill ramping down along +X: each cell keeps the height at which the tool's trailing
// edge last passed over it.
TEST(ZMap, FlatRampFloor) {
  ZMap m = stock();
  const double r = 5, x0 = 20, x1 = 60, y0 = 50.05, slope = -0.1;
  m.cut_line(ToolShape::flat(r), {x0, y0, 0}, {x1, y0, slope * (x1 - x0)});
  for (int k = -60; k <= 60; k += 3)
    for (int i = at(10.05); i <= at(70.05); ++i) {
      const double x = m.cell_x(i), dy = 0.1 * k;
      if (std::abs(dy) > r) continue;
      const double w = std::sqrt(r * r - dy * dy);
      const double last = std::min(x + w, x1);  // the tool centre's last X over the cell
      const double expect = last >= std::max(x - w, x0) ? slope * (last - x0) : 0.0;
      ASSERT_NEAR(m.height(i, at(y0 + dy)), expect, kExact) << x << " " << dy;
    }
}

// Ball, bull-nose and cone ramps: on the path's line the floor is where the tool's profile has
// the ramp's slope: the ball R (sec a - 1) below its centre's line, the bull-nose's torus at
// slope m, the cone (steeper than the ramp) at its tip.
TEST(ZMap, RampFloorsOfShapedTools) {
  const double x0 = 20, x1 = 60, y0 = 50.05, m_ = -0.1;
  auto ramp = [&](const ToolShape& tool) {
    ZMap m = stock();
    m.cut_line(tool, {x0, y0, 0}, {x1, y0, m_ * (x1 - x0)});
    return m;
  };
  const ZMap ball = ramp(ToolShape::ball(5));
  const ZMap bull = ramp(ToolShape::bull_nose(5, 1));
  const ZMap cone = ramp(ToolShape::cone(3, 118));
  const double e = 0.1 / std::sqrt(1.01);  // the torus's offset where its slope is 0.1
  for (int i = at(30.05); i <= at(50.05); ++i) {
    const double x = ball.cell_x(i);
    const int j = at(y0);
    EXPECT_NEAR(ball.height(i, j), m_ * (x - x0) + 5 - 5 * std::sqrt(1 + m_ * m_), kExact) << x;
    EXPECT_NEAR(bull.height(i, j), m_ * (x + 4 + e - x0) + 1 - 1 / std::sqrt(1.01), kLowestTolerance + kExact) << x;
    EXPECT_NEAR(cone.height(i, j), m_ * (x - x0), kLowestTolerance + kExact) << x;
  }
}

// A flat end mill's helix, one turn down: each cell keeps the height at the last angle the tool
// covered it (the law of cosines gives the angles).
TEST(ZMap, FlatHelixBottom) {
  ZMap m = stock();
  const double cx = 50.05, cy = 50.05, rho = 8, r = 3, z1 = -2;
  m.cut_arc(ToolShape::flat(r), Arc{cx, cy, rho, 0, 2 * kPi, 0, z1});
  int checked = 0;
  for (int j = at(40.05); j <= at(60.05); j += 3)
    for (int i = at(38.05); i <= at(62.05); i += 2) {
      const double dx = m.cell_x(i) - cx, dy = m.cell_y(j) - cy, d = std::hypot(dx, dy);
      const double c0 = (rho * rho + d * d - r * r) / (2 * rho * d);
      if (c0 > 1 + 1e-9) {
        ASSERT_EQ(m.height(i, j), 0) << dx << " " << dy;
        continue;
      }
      if (c0 > 1 - 1e-9) continue;  // touched at one angle: either way within rounding
      const double alpha = std::acos(c0);
      double phi = std::atan2(dy, dx);
      if (phi < 0) phi += 2 * kPi;
      const double last = (phi <= alpha || phi + alpha >= 2 * kPi) ? 2 * kPi : phi + alpha;
      ASSERT_NEAR(m.height(i, j), z1 * last / (2 * kPi), kExact) << dx << " " << dy;
      ++checked;
    }
  EXPECT_GT(checked, 500);
}

// A helix of radius under the tool's: the cell on its axis stays at one distance from the tip,
// so its bottom is the lowest tip height plus the shape's height there.
TEST(ZMap, HelixBottomOnTheAxis) {
  const double rho = 2, z1 = -2;
  for (const auto& tool : {ToolShape::ball(4), ToolShape::bull_nose(4, 1), ToolShape::bull_nose(4, 3),
                           ToolShape::cone(4, 90)}) {
    ZMap m = stock();
    m.cut_arc(tool, Arc{50.05, 50.05, rho, 0.3, 4 * kPi / 3, 0, z1});
    EXPECT_NEAR(m.height_at(50.05, 50.05), z1 + tool.lower(rho * rho), kLowestTolerance + kExact);
  }
}

// A ball's helix off the axis: against the definition sampled finely (each sample's height is
// an upper bound of the lowest; the lowest is smooth where the tool reaches well inside).
TEST(ZMap, BallHelixAgainstSampling) {
  ZMap m = stock();
  const double cx = 50.05, cy = 50.05, rho = 8, r = 3, z0 = 0, z1 = -4, start = 0.2, sweep = -5.0;
  const auto tool = ToolShape::ball(r);
  m.cut_arc(tool, Arc{cx, cy, rho, start, sweep, z0, z1});
  const int n = 200'000;
  for (double px : {57.05, 55.45, 50.05, 45.55}) {
    for (double py : {50.05, 52.35, 44.05, 57.95}) {
      double best = kUnreached;
      for (int k = 0; k <= n; ++k) {
        const double s = static_cast<double>(k) / n, a = start + sweep * s;
        const double ex = px - cx - rho * std::cos(a), ey = py - cy - rho * std::sin(a);
        best = std::min(best, z0 + (z1 - z0) * s + tool.lower(ex * ex + ey * ey));
      }
      const double h = m.height_at(px, py);
      if (best == kUnreached) {
        EXPECT_EQ(h, 0);
        continue;
      }
      EXPECT_LE(h, std::min(best, 0.0) + kLowestTolerance) << px << " " << py;
      EXPECT_GE(h, std::min(best, 0.0) - 1e-6) << px << " " << py;
    }
  }
}
