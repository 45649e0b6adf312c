// The look-ahead modes in the time planner: G05.1 Q0 / G08 P0 make each block end at rest.
#include <gtest/gtest.h>

#include "motion/planner.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

motion::PlanTotals plan(const std::string& text, const machine::MachineProfile& profile,
                        std::vector<motion::BlockTime>* blocks = nullptr) {
  auto r = test::run(text, profile);
  EXPECT_TRUE(r.result.ok()) << (r.result.alarm ? r.result.alarm->message : "");
  motion::Planner planner(profile, [&](const motion::BlockTime& b) {
    if (blocks) blocks->push_back(b);
  });
  for (const auto& m : r.moves) planner.on_move(m);
  planner.finish();
  return planner.totals();
}

// 1000 mm/s^2 on every axis, no processing time, in position at once.
machine::MachineProfile simple() {
  auto p = test::zero_offset_mill();
  p.motion.acceleration = {1000, 1000, 1000, 1000, 1000, 1000};
  p.motion.block_time = 0;
  p.motion.macro_time = 0;
  p.motion.look_ahead = 10;
  p.max_cutting_feed = 100000;
  p.servo.kv = {1000, 1000, 1000, 1000, 1000, 1000};
  return p;
}

}  // namespace

// Two collinear 10 mm blocks at F6000 (100 mm/s), a = 1000 mm/s^2: a ramp 0 -> 100 mm/s takes
// 100 / 1000 = 0.1 s over 100^2 / (2 * 1000) = 5 mm.
// Look-ahead on: up 5 mm (0.1 s), cruise 10 mm (0.1 s), down 5 mm (0.1 s): 0.3 s, one stop.
// Look-ahead off: each block up 5 mm and down 5 mm, 0.2 s: 0.4 s, two stops.
TEST(LookAhead, OffStopsAtEachBlockEnd) {
  std::vector<motion::BlockTime> on_blocks, off_blocks;
  auto on = plan("G01 X10. F6000.\nX20.\nM30\n", simple(), &on_blocks);
  EXPECT_NEAR(on.seconds, 0.3, 1e-9);
  EXPECT_EQ(on.stops, 1u);
  EXPECT_EQ(on.without_lookahead, 0u);
  EXPECT_NEAR(on_blocks.at(0).v_out, 6000, 1e-6);
  auto off = plan("G05.1 Q0\nG01 X10. F6000.\nX20.\nM30\n", simple(), &off_blocks);
  EXPECT_NEAR(off.seconds, 0.4, 1e-9);
  EXPECT_EQ(off.stops, 2u);
  EXPECT_EQ(off.without_lookahead, 2u);
  EXPECT_NEAR(off_blocks.at(0).v_out, 0, 1e-9);
  EXPECT_NEAR(off_blocks.at(0).settle, 0, 1e-12);  // no in-position check, unlike G61
  // back on: the same as never off; the profile may start with it off
  EXPECT_NEAR(plan("G08 P0\nG08 P1\nG01 X10. F6000.\nX20.\nM30\n", simple()).seconds, 0.3, 1e-9);
  auto p = simple();
  p.motion.look_ahead_at_power_on = false;
  EXPECT_NEAR(plan("G01 X10. F6000.\nX20.\nM30\n", p).seconds, 0.4, 1e-9);
}

// With acc/dec after interpolation the profile already describes the control without look-ahead:
// the modes change nothing (no filter here: 20 mm at 100 mm/s, 0.2 s).
TEST(LookAhead, NoEffectWithAccDecAfterInterpolation) {
  auto p = simple();
  p.motion.acc_dec = machine::AccDec::after;
  EXPECT_NEAR(plan("G01 X10. F6000.\nX20.\nM30\n", p).seconds, 0.2, 1e-9);
  EXPECT_NEAR(plan("G05.1 Q0\nG01 X10. F6000.\nX20.\nM30\n", p).seconds, 0.2, 1e-9);
}
