// Time of feed-per-revolution cuts under constant surface speed (G96) with the spindle clamped by
// G50 S, against the closed-form integral of the time along the move.
//
// Under G96 S V (m/min) the spindle turns n(r) = 1000 V / (2 pi r) rev/min at radius r (mm), at
// most N = G50 S: n = N below the clamp radius rc = 1000 V / (2 pi N). At F mm/rev the tool moves
// F n(r) mm/min, so a move of length L whose radius runs linearly from r0 to r1 takes
//   t = 60 / F * integral ds / n(r(s)) = 60 / F * L / |r1 - r0| * integral_{r0}^{r1} dr / n(r)
// with 1/n(r) = 2 pi r / (1000 V) above rc, 1/N below it:
//   integral_a^b dr / n = (rc - a) / N + pi (b^2 - rc^2) / (1000 V)   for a <= rc <= b,
//   pi (b^2 - a^2) / (1000 V) above rc, (b - a) / N below it.
// At constant radius r: t = 60 L / (F n(r)).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {

constexpr double kPi = std::numbers::pi;

// integral over [a, b] (0 < a < b) of 1/n(r) for G96 S v clamped at n_max
double inverse_speed_integral(double a, double b, double v, double n_max) {
  const double rc = 1000 * v / (2 * kPi * n_max);
  if (b <= rc) return (b - a) / n_max;
  if (a >= rc) return kPi * (b * b - a * a) / (1000 * v);
  return (rc - a) / n_max + kPi * (b * b - rc * rc) / (1000 * v);
}

machine::MachineProfile lathe() {
  auto p = machine::default_lathe();
  p.gcode_system = 'A';
  return p;
}

std::vector<machine::Move> cuts(const test::Ran& r) {
  std::vector<machine::Move> out;
  for (const auto& m : r.motions())
    if (m.kind == machine::MoveKind::line) out.push_back(m);
  return out;
}

}  // namespace

// Facing X60 -> X10 (radius 30 -> 5) at F0.2 under G96 S100, G50 S1000: rc = 15.9155 mm, so the cut
// is clamped from r = 15.9155 in. t = 300 * [(15.9155 - 5) / 1000 + pi (30^2 - 15.9155^2) / 100000]
// = 3.2746 + 6.0950 = 9.3696 s (without the clamp: 300 pi (30^2 - 5^2) / 100000 = 8.2467 s).
TEST(SurfaceSpeed, FacingCutIsClampedBelowTheClampRadius) {
  auto r = run("G99 G00 X60. Z0\nG50 S1000\nG96 S100\nG01 X10. F0.2\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  const auto c = cuts(r);
  ASSERT_EQ(c.size(), 1u);
  const double want = 60 / 0.2 * inverse_speed_integral(5, 30, 100, 1000);
  EXPECT_NEAR(want, 9.3696, 1e-4);
  EXPECT_NEAR(c[0].seconds, want, 1e-9);
  // with no clamp the mean radius gives the time exactly
  auto free = run("G99 G00 X60. Z0\nG96 S100\nG01 X10. F0.2\nM30\n", lathe());
  ASSERT_EQ(cuts(free).size(), 1u);
  EXPECT_NEAR(cuts(free)[0].seconds, 60 / 0.2 * kPi * (30 * 30 - 5 * 5) / (1000 * 100), 1e-9);
}

// G90 X60. Z-30. R-10. from X100 Z2 under G96 S100, G50 S700 (rc = 22.7364 mm): the taper cut runs
// from X40 Z2 (r 20) to X60 Z-30 (r 30), L = sqrt(32^2 + 10^2), crossing the clamp radius:
// t = 300 * L / 10 * [(22.7364 - 20) / 700 + pi (30^2 - 22.7364^2) / 100000] = 16.0354 s; the
// feed out X60 -> X100 (r 30 -> 50, L 20) is above it: t = 300 pi (50^2 - 30^2) / 100000 = 15.0796 s.
// G94 X20. Z-2. from X100 Z2 under G50 S1000: the face cut r 50 -> 10 at Z-2 (L 40),
// t = 300 * [(15.9155 - 10) / 1000 + pi (50^2 - 15.9155^2) / 100000] = 22.9493 s; the feed out in Z
// at r 10 turns at the clamp: t = 60 * 4 / (0.2 * 1000) = 1.2 s.
TEST(SurfaceSpeed, TaperAndFaceCyclesAreClamped) {
  auto r = run("G99 G00 X100. Z2.\nG50 S700\nG96 S100\nG90 X60. Z-30. R-10. F0.2\nG00 X100. Z2.\nG50 S1000\n"
               "G94 X20. Z-2. F0.2\nM30\n",
               lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  const auto c = cuts(r);
  ASSERT_EQ(c.size(), 4u);
  // the cuts' end points (radius, Z), by the G90 / G94 rules
  EXPECT_NEAR(c[0].start[0], 20, 1e-9);
  EXPECT_NEAR(c[0].end[0], 30, 1e-9);
  EXPECT_NEAR(c[0].end[2], -30, 1e-9);
  EXPECT_NEAR(c[2].start[0], 50, 1e-9);
  EXPECT_NEAR(c[2].end[0], 10, 1e-9);
  const double taper = std::hypot(32.0, 10.0);
  EXPECT_NEAR(c[0].seconds, 300 * taper / 10 * inverse_speed_integral(20, 30, 100, 700), 1e-9);
  EXPECT_NEAR(c[1].seconds, 300 * inverse_speed_integral(30, 50, 100, 700), 1e-9);
  EXPECT_NEAR(c[2].seconds, 300 * inverse_speed_integral(10, 50, 100, 1000), 1e-9);
  EXPECT_NEAR(c[3].seconds, 60 * 4 / (0.2 * 1000), 1e-9);
}

// A G02 arc under G96 without the clamp: t = 60 / F * 2 pi / (1000 V) * integral of r ds. G02 X60.
// Z-10. R10. from X40 Z0 is clockwise seen from +Y (Z right, X up): the quarter circle about
// (r 30, Z0) from below its centre (a = -90 deg from +Z toward +X) to the -Z side (a = -180 deg).
// Along it r = 30 + 10 sin(a), so integral r ds = 10 * integral_{-180}^{-90} (30 + 10 sin a) da
// = 10 (30 pi / 2 - 10) = 150 pi - 100 (a mean radius of 23.63, not the centre's 30).
TEST(SurfaceSpeed, ArcTimeFollowsTheRadius) {
  auto r = run("G99 G00 X40. Z0\nG96 S100\nG02 X60. Z-10. R10. F0.2\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  std::vector<machine::Move> arcs;
  for (const auto& m : r.motions())
    if (m.kind == machine::MoveKind::arc) arcs.push_back(m);
  ASSERT_EQ(arcs.size(), 1u);
  const double integral = 150 * kPi - 100;
  EXPECT_NEAR(arcs[0].seconds, 300 * 2 * kPi / (1000 * 100) * integral, 1e-6);
}

namespace {
int feed_clamps(const ncurve::test::Ran& r) {
  int n = 0;
  for (const auto& w : r.result.warnings) n += w.code == "NC2073";
  return n;
}
}  // namespace

// Over the maximum cutting feed the control clamps the feed (No.1430) without an alarm: the move
// takes the clamped feed's time and ncurve warns (NC2073).
TEST(FeedClamp, PerRevolutionOverTheMaximumIsClampedAndWarned) {
  machine::MachineProfile p = machine::default_lathe();  // max_cutting 10000 mm/min, 1000 rev/min without S
  auto r = run("G99 G00 X40. Z0\nG01 X28. F25.\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(feed_clamps(r), 1);
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[1].seconds, 6.0 / 10000 * 60, 1e-12);  // 6 mm (radius) at 10000 mm/min
  EXPECT_EQ(r.result.warnings.front().span.line, 2u);
}

TEST(FeedClamp, PerMinuteOverTheMaximumIsClampedAndWarned) {
  auto r = run("G00 X0 Y0\nG01 X30. Y40. F20000.\nG02 X80. Y40. R25. F15000.\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(feed_clamps(r), 2);
  const auto m = r.motions();
  EXPECT_NEAR(m[1].seconds, 50.0 / 10000 * 60, 1e-12);
  EXPECT_NEAR(m[2].seconds, std::numbers::pi * 25 / 10000 * 60, 1e-9);
}

TEST(FeedClamp, FeedsAtOrBelowTheMaximumAreNotWarned) {
  auto mill = run("G00 X0 Y0\nG01 X30. Y40. F10000.\nX0 F500.\nM30\n");
  EXPECT_EQ(feed_clamps(mill), 0);
  EXPECT_NEAR(mill.motions()[1].seconds, 50.0 / 10000 * 60, 1e-12);
  auto lathe = run("G99 G00 X40. Z0 S1000 M03\nG01 X28. F0.2\nM30\n", machine::default_lathe());
  EXPECT_EQ(feed_clamps(lathe), 0);
}
