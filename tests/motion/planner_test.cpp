// The feed planner against closed-form trapezoid, S-curve, stall and starvation cases.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/planner.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

struct Planned {
  motion::PlanTotals totals;
  std::vector<motion::BlockTime> blocks;
};

Planned plan(const std::string& text, const machine::MachineProfile& profile) {
  auto r = test::run(text, profile);
  EXPECT_TRUE(r.result.ok()) << (r.result.alarm ? r.result.alarm->message : "");
  Planned out;
  motion::Planner planner(profile, [&](const motion::BlockTime& b) { out.blocks.push_back(b); });
  for (const auto& m : r.moves) planner.on_move(m);
  planner.finish();
  out.totals = planner.totals();
  return out;
}

// A mill whose dynamics are simple numbers: 1000 mm/s^2 on every axis, no processing time.
machine::MachineProfile simple() {
  auto p = test::zero_offset_mill();
  p.decimal_calculator = true;
  p.motion.acceleration = {1000, 1000, 1000, 1000, 1000, 1000};
  p.motion.block_time = 0;
  p.motion.macro_time = 0;
  p.motion.look_ahead = 10;
  p.max_cutting_feed = 100000;
  p.servo.kv = {1000, 1000, 1000, 1000, 1000, 1000};  // in position at once after a stop
  return p;
}

}  // namespace

TEST(Planner, ClosedFormRamps) {
  EXPECT_DOUBLE_EQ(motion::change_time(100, 1000, 0), 0.1);
  EXPECT_DOUBLE_EQ(motion::change_time(100, 1000, 10000), 0.2);        // a/j + dv/a
  EXPECT_DOUBLE_EQ(motion::change_time(10, 1000, 10000), 2 * std::sqrt(10.0 / 10000));  // a is not reached
  EXPECT_DOUBLE_EQ(motion::change_distance(0, 100, 1000, 0), 5);
  EXPECT_NEAR(motion::reachable(0, 5, 1000, 0), 100, 1e-12);
  EXPECT_NEAR(motion::change_distance(20, motion::reachable(20, 7, 1000, 10000), 1000, 10000), 7, 1e-6);
  // the ramp's own integration agrees with its closed-form end
  motion::Ramp r{10, 90, 1000, 10000};
  EXPECT_NEAR(r.distance(r.duration()), motion::change_distance(10, 90, 1000, 10000), 1e-9);
  EXPECT_NEAR(r.speed(r.duration()), 90, 1e-9);
  EXPECT_NEAR(r.speed(r.duration() / 2), 50, 1e-9);  // symmetric S-curve
}

TEST(Planner, SingleLineTrapezoidAndTriangle) {
  // 100 mm at 100 mm/s, 1000 mm/s^2: 0.1 s up (5 mm), 0.9 s cruise, 0.1 s down.
  auto p = plan("G01 X100. F6000.\nM30\n", simple());
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_NEAR(p.blocks[0].seconds, 1.1, 1e-9);
  EXPECT_NEAR(p.blocks[0].v_peak, 6000, 1e-6);
  EXPECT_NEAR(p.totals.seconds, 1.1, 1e-9);
  EXPECT_NEAR(p.totals.programmed_seconds, 1.0, 1e-9);
  // 4 mm cannot reach 100 mm/s: triangle, t = 2 sqrt(L/a), peak sqrt(a L)
  auto q = plan("G01 X4. F6000.\nM30\n", simple());
  EXPECT_NEAR(q.blocks[0].seconds, 2 * std::sqrt(4.0 / 1000), 1e-9);
  EXPECT_NEAR(q.blocks[0].v_peak, 60 * std::sqrt(1000 * 4.0), 1e-6);
}

TEST(Planner, JerkLimitedLine) {
  auto prof = simple();
  prof.motion.jerk = 10000;
  // each ramp: a/j + v/a = 0.2 s covering 10 mm; cruise 80 mm at 100 mm/s
  auto p = plan("G01 X100. F6000.\nM30\n", prof);
  EXPECT_NEAR(p.totals.seconds, 0.2 + 0.8 + 0.2, 1e-9);
}

TEST(Planner, LookAheadCarriesSpeedThroughCollinearBlocksAndExactStopDoesNot) {
  auto two = plan("G01 X50. F6000.\nX100.\nM30\n", simple());
  EXPECT_NEAR(two.totals.seconds, 1.1, 1e-9);
  EXPECT_NEAR(two.blocks[0].v_out, 6000, 1e-6);
  auto stop = plan("G61\nG01 X50. F6000.\nX100.\nM30\n", simple());
  EXPECT_NEAR(stop.totals.seconds, 2 * (0.2 + 0.4), 1e-9);
  auto g09 = plan("G01 G09 X50. F6000.\nX100.\nM30\n", simple());
  EXPECT_NEAR(g09.totals.seconds, 2 * (0.2 + 0.4), 1e-9);
  EXPECT_EQ(g09.blocks[0].v_out, 0);
  // an M code between the blocks waits for the motion to end
  auto m = plan("G01 X50. F6000.\nM08\nX100.\nM30\n", simple());
  EXPECT_NEAR(m.totals.seconds, 2 * (0.2 + 0.4), 1e-9);
}

TEST(Planner, ShortLookAheadMustBeAbleToStopWithinWhatItSees) {
  // 20 blocks of 1 mm at 100 mm/s; one block of look-ahead: leaving a block the planner must be
  // able to stop by the end of the next one, so v_out <= sqrt(2 a * 1 mm) ~ 44.7 mm/s, and inside a
  // block the peak is sqrt(v_in^2/2 + v_out^2/2 + a L) = sqrt(3 a L).
  std::string text = "G91 G01 F6000.\n";
  for (int i = 0; i < 20; ++i) text += "X1.\n";
  text += "M30\n";
  auto prof = simple();
  prof.motion.look_ahead = 1;
  auto one = plan(text, prof);
  double cap = std::sqrt(2 * 1000 * 1.0) * 60;
  for (const auto& b : one.blocks) EXPECT_LE(b.v_out, cap + 1e-6);
  EXPECT_NEAR(one.blocks[10].v_out, cap, 1e-6);  // in the middle the speed settles at the cap
  EXPECT_NEAR(one.blocks[10].v_peak, std::sqrt(3 * 1000 * 1.0) * 60, 1e-6);
  prof.motion.look_ahead = 30;
  auto many = plan(text, prof);
  EXPECT_NEAR(many.totals.seconds, 0.2 + 0.1, 1e-9);  // 20 mm as one trapezoid
  EXPECT_GT(one.totals.seconds, many.totals.seconds);
}

TEST(Planner, CornerSpeedDifference) {
  // X then Y at 100 mm/s; each axis may change speed by 30 mm/s at once (1800 mm/min): the corner is
  // taken at 30 mm/s. Each 50 mm block: ramp 100 <-> 30 covers (100^2-30^2)/2000 = 4.55 mm.
  auto prof = simple();
  prof.motion.corner_speed = {1800, 1800, 1800, 0, 0, 0};
  auto p = plan("G01 X50. F6000.\nY50.\nM30\n", prof);
  EXPECT_NEAR(p.blocks[0].v_out, 1800, 1e-6);
  double ramp_t = 0.07, ramp_d = (100 * 100 - 30 * 30) / 2000.0;
  double one = 0.1 + ramp_t + (50 - 5 - ramp_d) / 100;
  EXPECT_NEAR(p.totals.seconds, 2 * one, 1e-9);
}

TEST(Planner, BlockProcessingTimeStarvesShortBlocks) {
  auto prof = simple();
  prof.motion.block_time = 0.004;  // 0.05 mm blocks: at most 12.5 mm/s
  std::string text = "G91 G01 F6000.\n";
  for (int i = 0; i < 200; ++i) text += "X0.05\n";
  text += "M30\n";
  auto p = plan(text, prof);
  EXPECT_EQ(p.totals.starved, 200u);
  EXPECT_NEAR(p.blocks[100].cap, 12.5 * 60, 1e-6);
  EXPECT_EQ(p.blocks[100].limit, motion::Limit::block_time);
  // reading the first two blocks (G91 G01 F and X) takes 0.008 s; then 10 mm at 12.5 mm/s, plus
  // one ramp up and down to 12.5 mm/s (0.0125 s each, 0.078 mm each)
  EXPECT_NEAR(p.blocks[0].wait, 0.008, 1e-12);
  EXPECT_EQ(p.totals.stops, 1u);  // the control keeps reading just in time: no stop on the way
  EXPECT_NEAR(p.totals.seconds, 0.008 + (10 - 2 * 0.078125) / 12.5 + 2 * 0.0125, 1e-9);
}

TEST(Planner, MacroStatementsStallMotionWhenTheyCannotKeepUp) {
  // Each 1 mm block at 10 mm/s takes 0.1 s; 3 statements of 0.05 s each before it take 0.15 s.
  // With unlimited acceleration (acc/dec after interpolation, no filter) the motion waits 0.05 s
  // for each block after the first: total = compute of all + the last block's motion.
  auto prof = simple();
  prof.motion.acc_dec = machine::AccDec::after;
  prof.motion.macro_time = 0.05;
  prof.motion.look_ahead = 1;
  std::string text = "G91 G01 F600.\n#1=0\nWHILE[#1LT10]DO1\n#1=#1+1\nX1.\nEND1\nM30\n";
  auto p = plan(text, prof);
  ASSERT_EQ(p.blocks.size(), 10u);
  // statements before each X1.: first: #1=0, WHILE, #1=#1+1 (3); later: END1, WHILE, #1=#1+1 (3)
  EXPECT_NEAR(p.blocks[0].start, 0.15, 1e-9);
  EXPECT_NEAR(p.blocks[1].wait, 0.05, 1e-9);
  EXPECT_NEAR(p.totals.seconds, 10 * 0.15 + 0.1, 1e-9);
  EXPECT_EQ(p.totals.waits, 10u);  // the first block waits too
  EXPECT_EQ(p.totals.macro_statements, 32u);  // 3 per turn + the last END1 and WHILE
  // fast enough macros run ahead in the buffer: only the first block waits
  prof.motion.macro_time = 0.01;
  auto q = plan(text, prof);
  EXPECT_NEAR(q.totals.seconds, 0.03 + 10 * 0.1, 1e-9);
}


TEST(Planner, WithoutABufferComputeAndMotionAddUp) {
  // look_ahead 0: each block is read and computed only after the previous one has ended, and
  // stops at its end. 1 mm at 1000 mm/s^2 from rest to rest: a triangle of 2 sqrt(1/1000) s.
  auto prof = simple();
  prof.motion.macro_time = 0.05;
  prof.motion.look_ahead = 0;
  std::string text = "G91 G01 F6000.\n#1=0\nWHILE[#1LT10]DO1\n#1=#1+1\nX1.\nEND1\nM30\n";
  auto p = plan(text, prof);
  ASSERT_EQ(p.blocks.size(), 10u);
  const double move = 2 * std::sqrt(1.0 / 1000);
  EXPECT_NEAR(p.totals.seconds, 10 * (0.15 + move), 1e-9);
  EXPECT_EQ(p.totals.stops, 10u);
  for (const auto& b : p.blocks) EXPECT_NEAR(b.wait, 0.15, 1e-9);
  // with a buffer of one block the computing hides behind the motion
  prof.motion.look_ahead = 1;
  auto q = plan(text, prof);
  EXPECT_LT(q.totals.seconds, 10 * 0.15 + move + 1e-9);
}
TEST(Planner, AccDecAfterInterpolationAddsTheFilterDelay) {
  auto prof = simple();
  prof.motion.acc_dec = machine::AccDec::after;
  prof.motion.time_constant = {0.05, 0.05, 0.05, 0, 0, 0};
  auto p = plan("G01 X50. F6000.\nY50.\nM30\n", prof);
  EXPECT_NEAR(p.totals.seconds, 1.0 + 0.05, 1e-9);  // linear filter: the end lags by T
  prof.motion.filter = machine::Filter::exponential;
  auto e = plan("G01 X50. F6000.\nY50.\nM30\n", prof);  // settles within 0.02 mm: T ln(v T / w)
  EXPECT_NEAR(e.totals.seconds, 1.0 + 0.05 * std::log(100 * 0.05 / 0.02), 1e-9);
}

TEST(Planner, ArcFeedIsClampedByCentripetalAcceleration) {
  // R = 1 mm at 100 mm/s would need 10,000 mm/s^2; the clamp is sqrt(a R) = 31.6 mm/s.
  auto p = plan("G01 X1. F6000.\nG03 X-1. Y0 I-1. J0\nM30\n", simple());
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[1].limit, motion::Limit::arc);
  EXPECT_NEAR(p.blocks[1].cap, 60 * std::sqrt(1000.0), 1e-6);
  // with a jerk limit the centripetal acceleration v^2/R turns at v^3/R^2: at J = 10,000 mm/s^3
  // the clamp is cbrt(J R^2) = 21.5 mm/s, below sqrt(a R) = 31.6
  auto jerk = simple();
  jerk.motion.jerk = 10000;
  auto q = plan("G01 X1. F6000.\nG03 X-1. Y0 I-1. J0\nM30\n", jerk);
  EXPECT_EQ(q.blocks[1].limit, motion::Limit::arc);
  EXPECT_NEAR(q.blocks[1].cap, 60 * std::cbrt(10000.0), 1e-6);
  jerk.motion.jerk = 1e6;  // fast enough: acceleration decides again
  auto r = plan("G01 X1. F6000.\nG03 X-1. Y0 I-1. J0\nM30\n", jerk);
  EXPECT_NEAR(r.blocks[1].cap, 60 * std::sqrt(1000.0), 1e-6);
}

TEST(Planner, ExactStopWaitsForThePositionLoopToSettle) {
  // Braking at a = 1000 mm/s^2 leaves a following error of a / Kv^2 = 1.11 mm at Kv = 30 /s; the
  // in-position check (0.02 mm) passes after ln(1.11 / 0.02) / Kv.
  auto prof = simple();
  prof.servo.kv = {30, 30, 30, 30, 30, 30};
  auto p = plan("G61\nG01 X50. F6000.\nX100.\nM30\n", prof);
  double settle = std::log(1000.0 / 900 / 0.02) / 30;
  EXPECT_NEAR(p.blocks[0].settle, settle, 1e-12);
  EXPECT_NEAR(p.totals.seconds, 2 * (0.2 + 0.4 + settle), 1e-9);
}
