// The plane's point type: its arithmetic, lengths, turns and the intersections of lines and
// circles, against closed forms (3-4-5 triangles, unit circles, 30-degree turns).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geom/plane.hpp"

using namespace ncurve::geom;

namespace {
void expect_near(V2 a, V2 b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
}
}  // namespace

TEST(Plane, ArithmeticIsComponentwise) {
  const V2 a{1, 2}, b{4, -3};
  expect_near(a + b, {5, -1}, 0);
  expect_near(a - b, {-3, 5}, 0);
  expect_near(-a, {-1, -2}, 0);
  expect_near(2.5 * a, {2.5, 5}, 0);
  expect_near(b / 2, {2, -1.5}, 0);
  EXPECT_EQ(dot(a, b), -2);
  EXPECT_EQ(cross(a, b), -11);  // b is clockwise of a
  EXPECT_EQ(cross(b, a), 11);
  EXPECT_EQ(cross(V2{1, 0}, V2{0, 1}), 1);  // +Y is left of +X
}

TEST(Plane, LengthsAndUnitVectors) {
  const V2 v{3, -4};
  EXPECT_EQ(norm(v), 5);
  EXPECT_EQ(sqrt_norm(v), 5);
  expect_near(unit(v), {0.6, -0.8});
  expect_near(sqrt_unit(v), {0.6, -0.8});
  expect_near(unit(V2{}), {0, 0}, 0);  // the zero vector stays zero
  expect_near(sqrt_unit(V2{}), {0, 0}, 0);
  EXPECT_DOUBLE_EQ(norm(V2{3e200, 4e200}), 5e200);  // hypot: no overflow of the squares
  EXPECT_TRUE(std::isinf(sqrt_norm(V2{3e200, 4e200})));
}

TEST(Plane, PerpendicularAndRotation) {
  expect_near(perp(V2{2, 1}), {-1, 2}, 0);
  EXPECT_EQ(dot(perp(V2{2, 1}), V2{2, 1}), 0);
  const double t = std::numbers::pi / 6;
  expect_near(rotate(V2{2, 0}, t), {std::sqrt(3.0), 1});
  expect_near(rotate(V2{0, 1}, -t), {0.5, std::sqrt(3.0) / 2});
  expect_near(rotate(V2{1, 1}, std::cos(t), std::sin(t)), rotate(V2{1, 1}, t), 0);
  expect_near(rotate(V2{1, 2}, std::numbers::pi), {-1, -2});
}

TEST(Plane, LinesMeetOrAreParallel) {
  // y = x and y = 4 - x meet at (2, 2)
  const auto x = line_line({0, 0}, {1, 1}, {0, 4}, {1, -1});
  ASSERT_TRUE(x);
  expect_near(*x, {2, 2});
  // the point is p1 + u d1 with u from the cross products, whatever the lengths of d1 and d2
  const auto y = line_line({1, 0}, {0, 3}, {-5, 6}, {2, 0});
  ASSERT_TRUE(y);
  expect_near(*y, {1, 6});
  EXPECT_FALSE(line_line({0, 0}, {1, 2}, {5, 5}, {-2, -4}));
}

TEST(Plane, LineAndCircle) {
  // the X axis through the circle of radius 5 about (1, 3): x = 1 -+ 4
  const auto p = line_circle({-10, 0}, {1, 0}, {1, 3}, 5);
  ASSERT_EQ(p.size(), 2u);
  expect_near(p[0], {-3, 0});  // the nearer to the line's start first
  expect_near(p[1], {5, 0});
  const auto tangent = line_circle({0, 2}, {2, 0}, {0, 0}, 2);  // y = 2 touches the circle of radius 2
  ASSERT_EQ(tangent.size(), 2u);
  expect_near(tangent[0], {0, 2});
  expect_near(tangent[1], {0, 2});
  EXPECT_TRUE(line_circle({0, 3}, {1, 0}, {0, 0}, 2).empty());  // misses
  EXPECT_TRUE(line_circle({0, 0}, {0, 0}, {0, 0}, 2).empty());  // no direction
}

TEST(Plane, TwoCircles) {
  // radius 5 about (0, 0) and radius 5 about (8, 0): (4, +-3), the left of the way from c1 to c2 first
  const auto p = circle_circle({0, 0}, 5, {8, 0}, 5);
  ASSERT_EQ(p.size(), 2u);
  expect_near(p[0], {4, 3});
  expect_near(p[1], {4, -3});
  // 3-4-5: radius 3 about the origin, radius 4 about (5, 0) meet at (9/5, +-12/5)
  const auto q = circle_circle({0, 0}, 3, {5, 0}, 4);
  ASSERT_EQ(q.size(), 2u);
  expect_near(q[0], {1.8, 2.4});
  expect_near(q[1], {1.8, -2.4});
  const auto touch = circle_circle({0, 0}, 1, {2, 0}, 1);
  ASSERT_EQ(touch.size(), 2u);
  expect_near(touch[0], {1, 0});
  EXPECT_TRUE(circle_circle({0, 0}, 1, {3, 0}, 1).empty());    // apart
  EXPECT_TRUE(circle_circle({0, 0}, 5, {1, 0}, 1).empty());    // one inside the other
  EXPECT_TRUE(circle_circle({1, 1}, 2, {1, 1}, 2).empty());    // concentric
}
