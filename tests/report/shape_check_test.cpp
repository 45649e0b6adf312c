// The contour measured against a curve: approach and departure moves set aside, and corners off
// the curve found, on a circle of radius 10 mm written as 10 degree chords.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "report/shape_check.hpp"

using namespace ncurve;

namespace {
geom::Curve circle(double radius) {
  geom::CurveSpec spec;
  spec.name = "circle";
  spec.x = std::to_string(radius) + "*COS[t]";
  spec.y = std::to_string(radius) + "*SIN[t]";
  spec.z = std::string(1, '0');  // (assigning the literal trips a false -Wrestrict in GCC 12)
  spec.from = 0, spec.to = 360;
  return geom::Curve(spec, {});
}

machine::Move line(double x0, double y0, double x1, double y1) {
  machine::Move m;
  m.kind = machine::MoveKind::line;
  m.start = {x0, y0, 0, 0, 0, 0};
  m.end = {x1, y1, 0, 0, 0, 0};
  m.length = std::hypot(x1 - x0, y1 - y0);
  return m;
}

// 36 chords of a circle of radius r from angle 0, lines numbered from `first_line`.
std::vector<machine::Move> chords(double r, std::uint32_t first_line) {
  std::vector<machine::Move> out;
  const double k = std::numbers::pi / 180;
  for (int i = 0; i < 36; ++i) {
    out.push_back(line(r * std::cos(10 * i * k), r * std::sin(10 * i * k), r * std::cos(10 * (i + 1) * k),
                       r * std::sin(10 * (i + 1) * k)));
    out.back().line = first_line + static_cast<std::uint32_t>(i);
  }
  return out;
}
}  // namespace

TEST(ShapeCheck, ApproachAndDepartureMovesAreSetAside) {
  const geom::Curve c = circle(10);
  std::vector<machine::Move> moves{line(15, 5, 15, 0), line(15, 0, 10, 0)};  // two moves in from outside
  for (const auto& m : chords(10, 3)) moves.push_back(m);
  moves.push_back(line(10, 0, 15, 0));  // and out again
  const auto span = report::contour_span(moves, c, geom::Placement{}, 0.01);
  EXPECT_EQ(span.first, 2u);
  EXPECT_EQ(span.last, moves.size() - 1);
  // a contour that starts elsewhere keeps every move (its measurement shows how far off it is)
  const auto elsewhere = report::contour_span(chords(12, 1), c, geom::Placement{}, 0.01);
  EXPECT_EQ(elsewhere.first, 0u);
  EXPECT_EQ(elsewhere.last, 36u);
}

TEST(ShapeCheck, CornersOffTheCurveAreFound) {
  const geom::Curve c = circle(10);
  const report::CurveNearest nearest(c, geom::Placement{});
  std::vector<double> ends;  // each chord ends at t = 10 (i + 1) degrees
  for (int i = 0; i < 36; ++i) ends.push_back(10.0 * (i + 1));
  // chords of the circle itself: every corner on it
  EXPECT_FALSE(report::farthest_off_curve(chords(10, 1), nearest, 0, ends, 0.01).has_value());
  // chords of a circle 2 mm larger: every corner 2 mm off, more than half a chord (1.05 mm)
  const auto off = report::farthest_off_curve(chords(12, 1), nearest, 0, ends, 0.01);
  ASSERT_TRUE(off.has_value());
  EXPECT_NEAR(off->distance, 2, 1e-9);
  EXPECT_NEAR(nearest.distance(off->at), 2, 1e-9);
  // 0.2 mm larger: off by less than half a chord (1.74 mm x 0.6 / 2): a coarse fit, not the wrong curve
  EXPECT_FALSE(report::farthest_off_curve(chords(10.2, 1), nearest, 0, ends, 0.01).has_value());
  // the nearest point anywhere on the curve, not only in order
  EXPECT_NEAR(nearest.distance({0, -13, 0}), 3, 1e-9);
  EXPECT_NEAR(nearest.distance({0.5, 0.5, 0}), 10 - std::sqrt(0.5), 1e-9);
}
