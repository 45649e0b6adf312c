// The servo model against closed forms: the circular test's radius reduction and ellipse, feed
// forward and acc/dec filters; the contour error of straight and cornering paths.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/circle.hpp"
#include "motion/servo.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {
motion::CircleResult circle(const machine::MachineProfile& p, double R, double F, bool cw = false) {
  motion::CircleTest t;
  t.radius = R;
  t.feed = F;
  t.clockwise = cw;
  return motion::circle_test(p, t);
}

double angle_gap(double a, double b) {
  double d = std::fmod(std::fabs(a - b), 180.0);  // the ellipse repeats every 180 degrees
  return std::min(d, 180 - d);
}
}  // namespace

TEST(Servo, EqualGainsShrinkTheCircleByVSquaredOver2RKvSquared) {
  auto p = machine::default_mill();  // Kv = 30 /s
  for (double F : {2000.0, 5000.0}) {
    auto r = circle(p, 50, F);
    double V = F / 60, closed = V * V / (2 * 50 * 30.0 * 30.0);
    EXPECT_NEAR(r.radius_reduction, closed, 0.01 * closed) << F;
    // the 1 ms command samples are chords of the circle: sag R (w dt)^2 / 8 apart from the model
    double sag = 50 * std::pow(V / 50 * 0.001, 2) / 8;
    EXPECT_NEAR(r.radius_reduction, r.harmonic_radius_reduction, sag + 1e-7);
    EXPECT_LT(r.roundness, 1e-5);
  }
  // four times the feed, sixteen times the reduction
  EXPECT_NEAR(circle(p, 50, 4000).radius_reduction / circle(p, 50, 1000).radius_reduction, 16, 0.1);
}

TEST(Servo, MismatchedGainsGiveAnEllipseAt45Degrees) {
  auto p = machine::default_mill();
  p.servo.kv[1] = 25;  // Y lags more than X
  auto r = circle(p, 50, 5000);
  double V = 5000 / 60.0;
  EXPECT_NEAR(r.roundness, V * (1 / 25.0 - 1 / 30.0), 0.01 * r.roundness);
  EXPECT_NEAR(r.roundness, r.harmonic_roundness, 1e-5);
  EXPECT_LT(angle_gap(r.max_deviation_angle, 45), 3);  // smallest radius at 45 and 225 degrees
  p.servo.kv = {25, 30, 30, 30, 30, 30};  // X lags more: the ellipse turns to 135 degrees
  EXPECT_LT(angle_gap(circle(p, 50, 5000).max_deviation_angle, 135), 3);
  // clockwise mirrors it
  EXPECT_LT(angle_gap(circle(p, 50, 5000, true).max_deviation_angle, 45), 3);
}

TEST(Servo, FeedForwardCutsTheReductionBy1MinusAlphaSquared) {
  auto p = machine::default_mill();
  double plain = circle(p, 50, 5000).radius_reduction;
  p.servo.feed_forward = 0.8;
  EXPECT_NEAR(circle(p, 50, 5000).radius_reduction / plain, 1 - 0.64, 0.01);
}

TEST(Servo, AccDecFiltersAfterInterpolation) {
  auto p = machine::default_mill();
  p.motion.acc_dec = machine::AccDec::after;
  p.motion.time_constant = {0.03, 0.03, 0.03, 0, 0, 0};
  double V = 5000 / 60.0, servo = 1 / (30.0 * 30.0);
  auto lin = circle(p, 50, 5000);  // FANUC: linear T adds T^2/12 to the bracket
  EXPECT_NEAR(lin.radius_reduction, V * V / 100 * (0.03 * 0.03 / 12 + servo), 0.01 * lin.radius_reduction);
  p.motion.filter = machine::Filter::exponential;  // exponential T adds T^2
  auto exp = circle(p, 50, 5000);
  EXPECT_NEAR(exp.radius_reduction, V * V / 100 * (0.03 * 0.03 + servo), 0.01 * exp.radius_reduction);
  EXPECT_NEAR(exp.radius_reduction, exp.harmonic_radius_reduction, 1e-4);
}

TEST(Servo, Seed002FormulaPeaksAt45DegreesWhenAccelerationsAreEqual) {
  auto p = machine::default_mill();
  p.motion.acceleration = {1100, 1100, 1100, 0, 0, 0};
  auto r = circle(p, 120, 140);
  double V = 140 / 60.0;
  EXPECT_NEAR(r.seed002_angle, 45, 0.01);
  EXPECT_NEAR(r.seed002_error, V * V / 2 * 0.5 * std::sqrt(2.0) / 1100, 1e-12);  // (8): sqrt2/2 (2/a)
  p.motion.acceleration[1] = 750;  // unequal: larger, and away from 45
  auto u = circle(p, 120, 140);
  EXPECT_GT(u.seed002_error, r.seed002_error);
  EXPECT_GT(std::fabs(u.seed002_angle - 45), 1);
}

TEST(Servo, StraightLinesLagAlongThePathButCornersCutInside) {
  auto run_contour = [](const std::string& text) {
    auto p = machine::default_mill();
    p.decimal_calculator = true;
    auto r = test::run(text, p);
    EXPECT_TRUE(r.result.ok());
    motion::ServoSim sim(p);
    motion::Planner planner(p, [&](const motion::BlockTime& b) { sim.on_block(b); });
    for (const auto& m : r.moves) planner.on_move(m);
    planner.finish();
    sim.finish(0.5);
    return sim.stats();
  };
  auto line = run_contour("G01 X100. Y50. F3000.\nM30\n");
  EXPECT_LT(line.max_error, 1e-9);
  EXPECT_GT(line.ticks, 1000u);
  // a sharp corner without deceleration: the machine rounds it; with exact stop it does not
  auto corner = run_contour("G01 X50. F3000.\nY50.\nM30\n");
  EXPECT_GT(corner.max_error, 0.01);
  EXPECT_EQ(corner.max_line, 2u);
  auto stopped = run_contour("G61\nG01 X50. F3000.\nY50.\nM30\n");
  EXPECT_LT(stopped.max_error, 0.05 * corner.max_error);
}
