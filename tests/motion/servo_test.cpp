// The servo model against closed forms: the circular test's radius reduction and ellipse, feed
// forward and acc/dec filters; the contour error of straight and cornering paths.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

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

namespace {
// Plans and simulates a program on `p`, returning the simulator after it has settled.
std::unique_ptr<motion::ServoSim> simulate(const std::string& text, const machine::MachineProfile& p) {
  auto r = test::run(text, p);
  EXPECT_TRUE(r.result.ok());
  auto sim = std::make_unique<motion::ServoSim>(p);
  motion::Planner planner(p, [&](const motion::BlockTime& b) { sim->on_block(b); });
  for (const auto& m : r.moves) planner.on_move(m);
  planner.finish();
  sim->finish(0.5);
  return sim;
}
}  // namespace

TEST(Servo, CuttingAndRapidContourErrorsAreApart) {
  // A straight move at 45 degrees with Kv X 30, Y 20: each axis lags by its speed / Kv, so the
  // machine runs beside the line by V/2 (1/Ky - 1/Kx) once at speed (cutting F1000: 0.138889 mm;
  // the rapid back, each axis at 15000 mm/min, V = 15000 sqrt 2: 2.946278 mm).
  auto p = machine::default_mill();
  p.servo.kv[1] = 20;
  auto sim = simulate("G92 X0 Y0 Z0\nG90 G01 X50. Y50. F1000.\nG00 X-450. Y-450.\nM30\n", p);
  const double gap = 1 / 20.0 - 1 / 30.0;
  EXPECT_NEAR(sim->cutting().max_error, 1000 / 60.0 / 2 * gap, 1e-6);
  EXPECT_EQ(sim->cutting().max_line, 2u);
  EXPECT_NEAR(sim->rapids().max_error, 15000 * std::sqrt(2.0) / 60 / 2 * gap, 1e-6);
  EXPECT_EQ(sim->rapids().max_line, 3u);
  EXPECT_EQ(sim->stats().max_error, sim->rapids().max_error);
  EXPECT_EQ(sim->stats().ticks, sim->cutting().ticks + sim->rapids().ticks);
  // a program of rapids alone has no cutting samples
  auto rapids = simulate("G92 X0 Y0 Z0\nG00 X10.\nM30\n", p);
  EXPECT_EQ(rapids->cutting().ticks, 0u);
  EXPECT_GT(rapids->rapids().ticks, 0u);
}

TEST(Servo, CircleAngleMeansNothingWhenTheAxesRespondAlike) {
  auto p = machine::default_mill();
  EXPECT_FALSE(circle(p, 50, 5000).angle_meaningful);  // equal gains: the circle only shrinks
  p.servo.kv[1] = 25;
  EXPECT_TRUE(circle(p, 50, 5000).angle_meaningful);
  p.servo.kv[1] = 30;  // equal gains, unequal filters after interpolation: an ellipse again
  p.motion.acc_dec = machine::AccDec::after;
  p.motion.time_constant = {0.02, 0.03, 0.03, 0, 0, 0};
  auto r = circle(p, 50, 5000);
  EXPECT_TRUE(r.angle_meaningful);
  EXPECT_NEAR(r.roundness, 5000 / 60.0 * (0.03 - 0.02) / 2, 0.02 * r.roundness);  // V |Tx - Ty| / 2 (linear)
  p.motion.time_constant = {0.03, 0.03, 0.01, 0, 0, 0};  // Z differs, but the circle is in X Y
  EXPECT_FALSE(circle(p, 50, 5000).angle_meaningful);
}

TEST(Servo, LatheCircleIsInTheZXPlane) {
  auto p = machine::default_lathe();
  p.servo.kv = {30, 30, 25, 30, 30, 30};  // Z lags more than X
  auto r = circle(p, 50, 5000);
  const auto plane = motion::circle_plane(p);
  EXPECT_EQ(plane.p, 2);
  EXPECT_EQ(plane.q, 0);
  EXPECT_TRUE(r.angle_meaningful);
  // the first axis (Z) lagging: the ellipse's smallest radius at 135 degrees from +Z towards +X,
  // as X lagging puts it at 135 degrees on a mill; roundness V (1/25 - 1/30)
  EXPECT_LT(angle_gap(r.max_deviation_angle, 135), 3);
  EXPECT_NEAR(r.roundness, 5000 / 60.0 * (1 / 25.0 - 1 / 30.0), 0.01 * r.roundness);
  p.servo.kv[2] = 30;
  p.servo.kv[1] = 10;  // Y is not an axis of the lathe's circle
  EXPECT_FALSE(circle(p, 50, 5000).angle_meaningful);
}

TEST(Servo, CircleFiguresAreAtTheFeedTheControlAllows) {
  auto p = machine::default_mill();  // cutting feed at most 10000 mm/min
  auto r = circle(p, 50, 20000);
  EXPECT_EQ(r.feed_reached, 10000);
  const double V = 10000 / 60.0;
  EXPECT_NEAR(r.radius_reduction, V * V / (2 * 50 * 30.0 * 30.0), 0.01 * r.radius_reduction);
  EXPECT_NEAR(r.fanuc_radius_reduction, V * V / (2 * 50 * 30.0 * 30.0), 1e-12);
  // three turns of R 1000 km at 1 mm/min: refused rather than simulated for years
  motion::CircleTest t;
  t.radius = 1e6;
  t.feed = 1;
  EXPECT_THROW(motion::circle_test(p, t), std::runtime_error);
}
