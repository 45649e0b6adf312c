// Lathe single cutting cycles (G90/G92/G94), threading (G32) and G76 beyond the point lists of
// tests/programs/lathe/lt_*: what marks a thread cut, its time, which blocks keep or clear the
// cycle's data, the modal G code a program reads, and how the writers show a thread. Values worked
// out by hand from the FANUC 0i-TF / 30i-B lathe operator's manuals.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <sstream>
#include <string>
#include <vector>

#include "report/writers.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;
using machine::MoveKind;

namespace {
machine::MachineProfile lathe(char system = 'A') {
  auto p = machine::default_lathe();
  p.gcode_system = system;
  p.reference_points[0] = {100, 0, 100, 0, 0, 0};  // home X200 (diameter) Z100
  return p;
}

std::string listing(const std::vector<machine::Move>& got) {
  std::string s;
  for (const auto& m : got)
    s += fmt::format("{} {} X{:.4f} Z{:.4f}{}\n", m.line, machine::to_string(m.kind), 2 * m.end[0], m.end[2],
                     m.threading ? " thread" : "");
  return s;
}

std::vector<machine::Move> motions_from(const test::Ran& r, std::uint32_t line) {
  std::vector<machine::Move> out;
  for (const auto& m : r.moves)
    if (m.is_motion() && m.line >= line) out.push_back(m);
  return out;
}
}  // namespace

TEST(LatheCycles, G92MarksOnlyTheThreadCutAndFeedsItPerRevolutionAtTheLead) {
  // G98 (feed per minute) is in force: the thread is still fed at F per revolution
  auto r = run("G21 G98\nG00 X25. Z5.\nG92 X19.2 Z-20. F1.5 Q45000\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto m = motions_from(r, 3);
  ASSERT_EQ(m.size(), 4u) << listing(m);
  EXPECT_FALSE(m[0].threading);
  EXPECT_TRUE(m[1].threading);
  EXPECT_TRUE(m[1].feed_per_rev);
  EXPECT_DOUBLE_EQ(m[1].feed, 1.5);
  EXPECT_EQ(m[1].thread_start, 45000);  // Q45000: 45 degrees after the one-rotation signal
  EXPECT_FALSE(m[2].threading);
  EXPECT_EQ(m[2].kind, MoveKind::rapid);
  EXPECT_FALSE(m[3].threading);
}

TEST(LatheCycles, G90CutsAtTheProgrammedFeedNotAsAThread) {
  auto r = run("G21 G99\nG00 X60. Z2.\nG90 X50. Z-30. F0.25\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  for (const auto& m : motions_from(r, 3)) EXPECT_FALSE(m.threading);
}

TEST(LatheCycles, ConsecutiveG32BlocksContinueOneThread) {
  auto r = run("G21 G99\nG00 X19.4 Z5.\nG32 Z-20. F3. Q90000\nX24. Z-22.\nG00 X30.\nZ5.\nX19.4\n"
               "G32 Z-20. Q180000\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto m = motions_from(r, 3);
  ASSERT_EQ(m.size(), 6u) << listing(m);
  EXPECT_EQ(m[0].thread_start, 90000);
  EXPECT_EQ(m[1].thread_start, -1);  // continues the cut of line 3: no wait for the spindle
  EXPECT_TRUE(m[1].threading);
  EXPECT_EQ(m[5].thread_start, 180000);  // the second start, after other moves
  EXPECT_DOUBLE_EQ(m[5].feed, 3.0);            // F is modal
}

TEST(LatheCycles, ThreadTimeIsTheLongAxisOverLeadTimesSpeed) {
  // 25 mm along Z at 1.5 mm/rev and 600 rev/min: 25 / 900 min = 1.6667 s; a steep taper (X 20 mm radius,
  // Z 5 mm) has the lead along X: 20 / 900 min
  auto r = run("G21 G99 S600 M03\nG00 X20. Z5.\nG32 Z-20. F1.5\nG00 X0. Z5.\nG32 X40. Z0.\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto m = motions_from(r, 3);
  ASSERT_EQ(m.size(), 3u) << listing(m);
  EXPECT_NEAR(m[0].seconds, 25.0 / 900 * 60, 1e-9);
  EXPECT_NEAR(m[2].seconds, 20.0 / 900 * 60, 1e-9);
}

TEST(LatheCycles, AGroup01CodeOrAOneShotCodeClearsTheCycleData) {
  // after G00 the next G90 has no Z of its own: the end point's Z is the start point's (no Z travel)
  auto r = run("G21 G99\nG00 X60. Z2.\nG90 X50. Z-30. F0.2\nG00 X60. Z2.\nG90 X45.\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto m = motions_from(r, 5);
  ASSERT_EQ(m.size(), 2u) << listing(m);
  EXPECT_NEAR(2 * m[0].end[0], 45, 1e-9);
  EXPECT_NEAR(m[0].end[2], 2, 1e-9);
  EXPECT_NEAR(2 * m[1].end[0], 60, 1e-9);  // (3) back to A's X, no Z travel
  // G10 (one-shot, no motion) clears too, the mode stays: X45 cuts with no Z travel
  auto g10 = run("G21 G99\nG00 X60. Z2.\nG90 X50. Z-30. F0.2\nG10 P1 X0.\nX45.\nM30\n", lathe());
  ASSERT_TRUE(g10.result.ok()) << nc::format(*g10.result.alarm);
  EXPECT_EQ(motions_from(g10, 5).size(), 2u) << listing(motions_from(g10, 5));
  // G94 after G90 keeps X, Z, R (another single cycle code of group 01)
  auto kept = run("G21 G99\nG00 X60. Z2.\nG90 X50. Z-30. F0.2\nG94 X20.\nM30\n", lathe());
  ASSERT_TRUE(kept.result.ok()) << nc::format(*kept.result.alarm);
  auto k = motions_from(kept, 4);
  ASSERT_EQ(k.size(), 4u) << listing(k);
  EXPECT_NEAR(k[0].end[2], -30, 1e-9);  // (1) rapid to the kept Z-30
}

TEST(LatheCycles, ModalInformationReadsTheCycleCodeAsWritten) {
  auto a = run("G21 G99\nG00 X60. Z2.\nG90 X50. Z-30. F0.2\n#100=#4001\nG32 Z-40. F1.5\n#101=#4001\nM30\n",
               lathe());
  ASSERT_TRUE(a.result.ok()) << nc::format(*a.result.alarm);
  EXPECT_EQ(a.var(100), 90);
  EXPECT_EQ(a.var(101), 32);
  auto b = run("G21 G95\nG00 X60. Z2.\nG77 X50. Z-30. F0.2\n#100=#4001\nM30\n", lathe('B'));
  ASSERT_TRUE(b.result.ok()) << nc::format(*b.result.alarm);
  EXPECT_EQ(b.var(100), 77);
}

TEST(LatheCycles, SystemCCodesAndSystemAOnesDoNotMix) {
  // on system C, G92 sets the coordinate system and G78 is the threading cycle
  auto c = run("G21 G95\nG00 X25. Z5.\nG92 X50. Z10.\nG78 X44.2 Z-15. F1.5\nM30\n", lathe('C'));
  ASSERT_TRUE(c.result.ok()) << nc::format(*c.result.alarm);
  auto m = motions_from(c, 4);
  ASSERT_EQ(m.size(), 4u) << listing(m);
  EXPECT_TRUE(m[1].threading);
  // on system A, G77 is no G code of the control
  auto a = run("G21 G99\nG77 X50. Z-30. F0.2\nM30\n", lathe());
  EXPECT_EQ(a.alarm_code(), "PS0010");
}

TEST(LatheCycles, G76FirstBlockIsModalAndRewritesTheChamferOfG92) {
  // P001060: m 0 (taken as one finishing pass), r 10, a 60; Q and R keep the parameters' zeros. Two threads
  // from one first block; then G92 pulls out over r = 1 lead, as No.5130 rewritten by G76 says
  const std::string text =
      "G21 G99\nG00 X24. Z5.\nG76 P001060\n"
      "G76 X18.16 Z-20. P920 Q920 F1.5\n"   // first depth = k: one rough pass at k, one finishing pass
      "G76 X18.16 Z-40. P920 Q920 F1.5\n"
      "G92 X19.2 Z-20. F1.5\nM30\n";
  auto r = run(text, lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto m = motions_from(r, 4);
  // per pass: rapid in, thread, chamfer, rapid out, rapid back: 2 passes x 5 x 2 threads, then G92's 5
  ASSERT_EQ(m.size(), 25u) << listing(m);
  EXPECT_NEAR(2 * m[0].end[0], 18.16, 1e-9);
  EXPECT_NEAR(m[1].end[2], -18.5, 1e-9);   // the chamfer starts 1.5 before Z-20
  EXPECT_NEAR(2 * m[2].end[0], 21.16, 1e-9);
  EXPECT_EQ(m[11].line, 5u);
  EXPECT_NEAR(m[11].end[2], -38.5, 1e-9);
  EXPECT_NEAR(m[21].end[2], -18.5, 1e-9);  // G92's chamfer
  EXPECT_NEAR(2 * m[22].end[0], 22.2, 1e-9);
}

TEST(LatheCycles, G76AlarmsOfTheManual) {
  auto decimal = run("G21 G99\nG00 X24. Z5.\nG76 P0110.60\nM30\n", lathe());
  EXPECT_EQ(decimal.alarm_code(), "PS0007");
  auto angle = run("G21 G99\nG00 X24. Z5.\nG76 P011050\nM30\n", lathe());
  EXPECT_EQ(angle.alarm_code(), "PS0315");
  auto depth = run("G21 G99\nG00 X24. Z5.\nG76 X18.16 Z-20. P920 Q-10 F1.5\nM30\n", lathe());
  EXPECT_EQ(depth.alarm_code(), "PS0317");
  auto lead = run("G21 G99\nG00 X24. Z5.\nG76 X18.16 Z-20. P920 Q350\nM30\n", lathe());
  EXPECT_EQ(lead.alarm_code(), "PS0011");
  // the alarm list: PS0003 more digits than the word permits, PS0006 a minus sign where none may be
  EXPECT_EQ(run("G21 G99\nG00 X24. Z5.\nG76 P1011060\nM30\n", lathe()).alarm_code(), "PS0003");
  EXPECT_EQ(run("G21 G99\nG00 X24. Z5.\nG76 P-11060\nM30\n", lathe()).alarm_code(), "PS0006");
  EXPECT_EQ(run("G21 G99\nG00 X24. Z5.\nG32 Z-10. F1.5 Q-1000\nM30\n", lathe()).alarm_code(), "PS0006");
}

TEST(LatheCycles, ThreadingParametersAreChecked) {
  auto p = machine::default_lathe();
  EXPECT_THROW(machine::set_parameter(p, "5143", 45), std::runtime_error);
  EXPECT_THROW(machine::set_parameter(p, "5130", 128), std::runtime_error);
  EXPECT_THROW(machine::set_parameter(p, "5142", 0), std::runtime_error);
  machine::set_parameter(p, "5140", 100);
  EXPECT_DOUBLE_EQ(p.g76_min_depth, 0.1);
  machine::set_parameter(p, "0001#1", 1);
  EXPECT_TRUE(p.series10_format);
}

TEST(LatheCycles, WritersShowAThread) {
  auto r = run("G21 G99\nG00 X19.4 Z5.\nG32 Z-20. F3. Q180000\nX24. Z-22.\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  std::ostringstream jsonl, gcode;
  const auto profile = lathe();  // the writers keep a reference to it
  report::JsonlWriter j(jsonl, profile);
  report::GcodeWriter g(gcode, profile, "t.nc");
  for (const auto& m : r.moves) {
    j.on_move(m);
    g.on_move(m);
  }
  g.finish();
  EXPECT_NE(jsonl.str().find(R"("feed_unit":"mm/rev","threading":true,"thread_start_deg":180,)"), std::string::npos)
      << jsonl.str();
  EXPECT_NE(jsonl.str().find(R"("f":3,"feed_unit":"mm/rev","threading":true,"length")"), std::string::npos)
      << jsonl.str();
  // the first thread cut moves Z only: X stays at 19.4
  EXPECT_NE(gcode.str().find("G00 X19.4 Z5.\nG32 Z-20. F3. Q180000\nG32 X24. Z-22.\n"), std::string::npos) << gcode.str();
}

