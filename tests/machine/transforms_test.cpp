// The pure maths of the mill coordinate transforms (machine/transforms.hpp), against values worked
// out by hand: cos 30 = 0.8660254, sin 30 = 0.5, and so on.
#include "machine/frame/transforms.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace ncurve::machine;

namespace {
constexpr double kEps = 1e-12;
const double kRoot3Half = std::sqrt(3.0) / 2;  // cos 30, sin 60

void expect_point(const AxisVector& got, double x, double y, double z = 0) {
  EXPECT_NEAR(got[0], x, kEps);
  EXPECT_NEAR(got[1], y, kEps);
  EXPECT_NEAR(got[2], z, kEps);
}
}  // namespace

TEST(Polar, AbsoluteRadiusAndAngleAboutTheOrigin) {
  const V2 p = polar_point({5, 5}, 100.0, 30.0, false);  // the current position plays no part
  EXPECT_NEAR(p.x, 100 * kRoot3Half, kEps);
  EXPECT_NEAR(p.y, 50, kEps);
}

TEST(Polar, AbsoluteWithoutAngleKeepsTheCurrentAngle) {
  const V2 p = polar_point({3, 4}, 10.0, std::nullopt, false);  // angle atan(4/3): (3,4) * 10/5
  EXPECT_NEAR(p.x, 6, kEps);
  EXPECT_NEAR(p.y, 8, kEps);
}

TEST(Polar, AbsoluteWithoutRadiusKeepsTheCurrentDistance) {
  const V2 p = polar_point({0, 20}, std::nullopt, 180.0, false);
  EXPECT_NEAR(p.x, -20, kEps);
  EXPECT_NEAR(p.y, 0, kEps);
}

TEST(Polar, IncrementalAngleWithoutRadiusTurnsAboutTheOrigin) {
  // the manual's bolt hole circle: at 100 mm 30 deg, G91 Y120. -> 100 mm at 150 deg
  const V2 p = polar_point({100 * kRoot3Half, 50}, std::nullopt, 120.0, true);
  EXPECT_NEAR(p.x, -100 * kRoot3Half, kEps);
  EXPECT_NEAR(p.y, 50, kEps);
}

TEST(Polar, IncrementalRadiusIsMeasuredFromTheCurrentPosition) {
  // at (10, 0) (angle 0 about the origin): G91 X5. Y90. -> 5 mm from (10, 0) at 0 + 90 deg
  const V2 p = polar_point({10, 0}, 5.0, 90.0, true);
  EXPECT_NEAR(p.x, 10, kEps);
  EXPECT_NEAR(p.y, 5, kEps);
  // at (0, 10) (angle 90): G91 X4. alone -> 4 mm further along the same angle
  const V2 q = polar_point({0, 10}, 4.0, std::nullopt, true);
  EXPECT_NEAR(q.x, 0, kEps);
  EXPECT_NEAR(q.y, 14, kEps);
}

TEST(Transforms, NoneIsTheIdentity) {
  Transforms t;
  EXPECT_FALSE(t.active());
  expect_point(t.apply({1, 2, 3}), 1, 2, 3);
  EXPECT_FALSE(t.reverses(0, 1));
  EXPECT_EQ(t.radius_factor(0, 1), 1);
}

TEST(Transforms, RotationAboutACentre) {
  Transforms t;
  t.rotating = true;
  t.angle_deg = 90;
  t.centre = {10, 0};
  expect_point(t.apply({20, 0, 7}), 10, 10, 7);  // (10,0) from the centre turned to (0,10)
  expect_point(t.invert({10, 10, 7}), 20, 0, 7);
  expect_point(t.apply_vector({1, 0, 0}), 0, 1);
  EXPECT_FALSE(t.reverses(0, 1));
}

TEST(Transforms, RotationInTheZXPlane) {
  Transforms t;  // G18: first axis Z (2), second X (0): +30 deg turns +Z towards +X
  t.rotating = true;
  t.p = 2;
  t.q = 0;
  t.angle_deg = 30;
  expect_point(t.apply({0, 5, 10}), 5, 5, 10 * kRoot3Half);
}

TEST(Transforms, MirrorAboutAPosition) {
  Transforms t;
  t.mirrored[0] = true;
  t.mirror_at[0] = 5;
  expect_point(t.apply({8, 1, 0}), 2, 1);
  expect_point(t.invert({2, 1, 0}), 8, 1);
  EXPECT_TRUE(t.reverses(0, 1));
  EXPECT_FALSE(t.reverses(1, 2));  // the YZ plane is not mirrored
  t.mirrored[1] = true;            // both axes: a half turn, not a reflection
  EXPECT_FALSE(t.reverses(0, 1));
}

TEST(Transforms, ScalingPerAxisWithANegativeFactor) {
  Transforms t;
  t.scaling = true;
  t.factor = {2, -1, 0.5, 1, 1, 1};
  t.scale_centre = {10, 10, 0};
  expect_point(t.apply({13, 14, 8}), 16, 6, 4);  // 10 + 2*3, 10 - 4, 0.5*8
  expect_point(t.invert({16, 6, 4}), 13, 14, 8);
  expect_point(t.apply_vector({1, 1, 1}), 2, -1, 0.5);
  EXPECT_TRUE(t.reverses(0, 1));
  EXPECT_EQ(t.radius_factor(0, 1), 2);    // the larger of |2| and |-1|
  EXPECT_EQ(t.radius_factor(1, 2), 1);    // |-1| against 0.5
}

TEST(Transforms, MirrorThenScaleThenRotate) {
  Transforms t;
  t.mirrored[0] = true;  // x -> -x
  t.scaling = true;
  t.factor = {2, 2, 2, 1, 1, 1};
  t.rotating = true;
  t.angle_deg = 90;
  // (1, 0): mirror (-1, 0), scale (-2, 0), turn 90 deg (0, -2)
  expect_point(t.apply({1, 0, 0}), 0, -2);
  expect_point(t.invert({0, -2, 0}), 1, 0);
  // the mirror and scaling stages alone: where a later stage's centre goes
  expect_point(t.mirror_and_scale({3, 1, 0}), -6, 2);
}

TEST(Transforms, InvertUndoesApply) {
  Transforms t;
  t.mirrored[1] = true;
  t.mirror_at[1] = -3;
  t.scaling = true;
  t.factor = {1.5, 0.75, 1, 1, 1, 1};
  t.scale_centre = {2, 1, 0};
  t.rotating = true;
  t.angle_deg = -37;
  t.centre = {4, -2};
  for (double x : {-50.0, 0.0, 12.5})
    for (double y : {-7.0, 3.0}) {
      const AxisVector back = t.invert(t.apply({x, y, 9}));
      EXPECT_NEAR(back[0], x, 1e-9);
      EXPECT_NEAR(back[1], y, 1e-9);
      EXPECT_NEAR(back[2], 9, 1e-9);
    }
}

// ---- the modes in a running program: modal information and positions ----

#include "support/run_program.hpp"

TEST(TransformModes, ModalInformationFollowsTheCodes) {
  // #4011 group 11 (G50/G51), #4016 group 16 (G68/G69), #4017 group 17 (G15/G16), #4022 group 22 (G50.1/G51.1)
  auto r = ncurve::test::run(
      "G90 G17 G00 X0. Y0. Z0.\n#101=#4011\n#102=#4016\n#103=#4017\n#104=#4022\n"
      "G16\nG51.1 X5.\nG51 X0. Y0. Z0. P200000\nG68 X0. Y0. R30.\n"
      "#111=#4011\n#112=#4016\n#113=#4017\n#114=#4022\n"
      "G69\nG50\nG50.1 X0.\nG15\n#121=#4011\n#122=#4016\n#123=#4017\n#124=#4022\nM30\n");
  ASSERT_TRUE(r.result.ok()) << ncurve::nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(101), 50);
  EXPECT_EQ(r.var(102), 69);
  EXPECT_EQ(r.var(103), 15);
  EXPECT_DOUBLE_EQ(r.var(104), 50.1);
  EXPECT_EQ(r.var(111), 51);
  EXPECT_EQ(r.var(112), 68);
  EXPECT_EQ(r.var(113), 16);
  EXPECT_DOUBLE_EQ(r.var(114), 51.1);
  EXPECT_EQ(r.var(121), 50);
  EXPECT_EQ(r.var(122), 69);
  EXPECT_EQ(r.var(123), 15);
  EXPECT_DOUBLE_EQ(r.var(124), 50.1);
}

TEST(TransformModes, EndPointReadsInProgramCoordinatesCurrentPositionAsMoved) {
  // G68 90 deg about (0,0): programmed (10,0) is the tool at (0,10). #5001.. the programmed end
  // point, #5041.. where the tool is.
  auto r = ncurve::test::run("G90 G17 G00 X0. Y0. Z0.\nG68 X0. Y0. R90.\nG01 X10. Y0. F100.\n"
                             "#101=#5001\n#102=#5002\n#103=#5041\n#104=#5042\nG69\nM30\n");
  ASSERT_TRUE(r.result.ok()) << ncurve::nc::format(*r.result.alarm);
  EXPECT_NEAR(r.var(101), 10, 1e-9);
  EXPECT_NEAR(r.var(102), 0, 1e-9);
  EXPECT_NEAR(r.var(103), 0, 1e-9);
  EXPECT_NEAR(r.var(104), 10, 1e-9);
}

TEST(TransformModes, ALatheKeepsG50AsCoordinateSystemSetting) {
  // G-code system A: G50 X_ Z_ sets the coordinate system (X a diameter): the tool at X100 (dia) Z50
  auto r = ncurve::test::run("G50 X100. Z50.\nG00 X80. Z40.\nM30\n", ncurve::machine::default_lathe());
  ASSERT_TRUE(r.result.ok()) << ncurve::nc::format(*r.result.alarm);
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 1u);
  EXPECT_NEAR(m[0].start[0], 50, 1e-9);  // radius
  EXPECT_NEAR(m[0].end[0], 40, 1e-9);
  EXPECT_NEAR(m[0].end[2], 40, 1e-9);
  EXPECT_EQ(r.var(4011), 0);  // no scaling: a system A lathe has no group 11 (G98/G99 of B and C)
}

TEST(TransformModes, IncrementalMoveAfterG69IsWarned) {
  auto r = ncurve::test::run("G90 G17 G00 X0. Y0. Z0.\nG68 X0. Y0. R90.\nG01 X10. F100.\nG69\nG91 X5.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << ncurve::nc::format(*r.result.alarm);
  bool warned = false;
  for (const auto& w : r.result.warnings) warned = warned || w.code == "NC2012";
  EXPECT_TRUE(warned);
  const auto m = r.motions();
  EXPECT_NEAR(m.back().end[0], 5, 1e-9);  // from the tool at (0,10), by the increment
  EXPECT_NEAR(m.back().end[1], 10, 1e-9);
}
