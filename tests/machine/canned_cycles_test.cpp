// Drilling canned cycles (G73, G74, G76, G81..G89, G80, G98/G99, rigid tapping) against moves worked out by hand from
// the FANUC 30i-B / 0i-MF operator's manual: position at the current level, rapid to R, the cycle's
// motions to Z, return to the initial level (G98) or R (G99); G91 R from the initial level, Z from R.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <string>
#include <vector>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;
using machine::MoveKind;

namespace {
struct Want {
  std::uint32_t line;
  MoveKind kind;
  double x, y, z;
};

std::string listing(const std::vector<machine::Move>& got) {
  std::string s;
  for (const auto& m : got)
    s += fmt::format("{} {} {:.4f} {:.4f} {:.4f}\n", m.line, machine::to_string(m.kind), m.end[0], m.end[1], m.end[2]);
  return s;
}

// Every move (motions, dwells and spindle events) from the first on line `from`.
void expect_moves(const test::Ran& r, std::uint32_t from, const std::vector<Want>& want) {
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  std::vector<machine::Move> got;
  for (const auto& m : r.moves)
    if (m.line >= from && (m.is_motion() || m.kind == MoveKind::dwell || m.kind == MoveKind::spindle))
      got.push_back(m);
  ASSERT_EQ(got.size(), want.size()) << listing(got);
  for (std::size_t i = 0; i < want.size(); ++i) {
    SCOPED_TRACE(fmt::format("move {}\n{}", i, listing(got)));
    EXPECT_EQ(got[i].line, want[i].line);
    EXPECT_EQ(machine::to_string(got[i].kind), machine::to_string(want[i].kind));
    EXPECT_NEAR(got[i].end[0], want[i].x, 1e-9);
    EXPECT_NEAR(got[i].end[1], want[i].y, 1e-9);
    EXPECT_NEAR(got[i].end[2], want[i].z, 1e-9);
  }
}
constexpr auto R = MoveKind::rapid;
constexpr auto L = MoveKind::line;
constexpr auto D = MoveKind::dwell;
constexpr auto S = MoveKind::spindle;
}  // namespace

TEST(CannedCycles, G81G98ReturnsToTheInitialLevel) {
  auto r = run("G90 G17 G00 X0. Y0. Z50.\nG98 G81 X10. Y20. Z-5. R2. F100.\nX30.\nG80\nM30\n");
  expect_moves(r, 2, {{2, R, 10, 20, 50}, {2, R, 10, 20, 2}, {2, L, 10, 20, -5}, {2, R, 10, 20, 50},
                      {3, R, 30, 20, 50}, {3, R, 30, 20, 2}, {3, L, 30, 20, -5}, {3, R, 30, 20, 50}});
}

TEST(CannedCycles, G81G99ReturnsToPointR) {
  auto r = run("G90 G17 G00 X0. Y0. Z50.\nG99 G81 X10. Y20. Z-5. R2. F100.\nX30.\nG80\nM30\n");
  expect_moves(r, 2, {{2, R, 10, 20, 50}, {2, R, 10, 20, 2}, {2, L, 10, 20, -5}, {2, R, 10, 20, 2},
                      {3, R, 30, 20, 2}, {3, L, 30, 20, -5}, {3, R, 30, 20, 2}});
  // the hole position at the return level is the end point
  EXPECT_DOUBLE_EQ(r.var(5001), 30);
  EXPECT_DOUBLE_EQ(r.var(5003), 2);
}

// G91: R from the initial level (20 - 18 = 2), Z from R (2 - 7 = -5); K3 steps X by 10 each time.
TEST(CannedCycles, G91RepeatsStepByTheIncrement) {
  auto r = run("G90 G00 X0. Y0. Z20.\nG91 G99 G81 X10. Z-7. R-18. K3 F100.\nM30\n");
  expect_moves(r, 2, {{2, R, 10, 0, 20}, {2, R, 10, 0, 2}, {2, L, 10, 0, -5}, {2, R, 10, 0, 2},
                      {2, R, 20, 0, 2}, {2, L, 20, 0, -5}, {2, R, 20, 0, 2},
                      {2, R, 30, 0, 2}, {2, L, 30, 0, -5}, {2, R, 30, 0, 2}});
}

// K in cycle mode is the number of repeats, a count: K3 beside decimal points is no mixed program
// (NC2001), while X10 without its point still is. G91: R from the initial level (10 - 8 = 2), Z from
// R (2 - 7 = -5); three holes stepping X by 10 from X10.
TEST(CannedCycles, TheRepeatCountIsNoDimension) {
  const std::string holes = "G90 G99 G81 X10. Y10. Z-5. R2. F200.\nG91 X10. R-8. Z-7. K3\nG80\nM30\n";
  auto r = run("G90 G00 X0. Y0. Z10.\n" + holes);
  expect_moves(r, 2, {{2, R, 10, 10, 10}, {2, R, 10, 10, 2}, {2, L, 10, 10, -5}, {2, R, 10, 10, 2},
                      {3, R, 20, 10, 2}, {3, L, 20, 10, -5}, {3, R, 20, 10, 2},
                      {3, R, 30, 10, 2}, {3, L, 30, 10, -5}, {3, R, 30, 10, 2},
                      {3, R, 40, 10, 2}, {3, L, 40, 10, -5}, {3, R, 40, 10, 2}});
  for (const auto& w : r.result.warnings) EXPECT_NE(w.code, "NC2001") << nc::format(w);
  auto mixed = run("G90 G00 X0. Y0. Z10.\nG90 G99 G81 X10 Y10. Z-5. R2. F200.\nG91 X10. R-8. Z-7. K3\nG80\nM30\n");
  ASSERT_EQ(mixed.result.warnings.size(), 1u);
  EXPECT_EQ(mixed.result.warnings[0].code, "NC2001");
  EXPECT_NE(mixed.result.warnings[0].message.find("X10 is read as 0.01 mm"), std::string::npos)
      << mixed.result.warnings[0].message;
  // the cycle ends with G80 and with a group 01 code: K3 after either is no repeat count
  for (const char* end : {"G80\nG00 X20. K3\n", "G00 X20. K3\n"}) {
    auto after = run(std::string("G90 G00 X0. Y0. Z10.\nG99 G81 X10. Y10. Z-5. R2. F200.\n") + end + "M30\n");
    bool warned = false;
    for (const auto& w : after.result.warnings)
      warned |= w.code == "NC2001" && w.message.find("K3 is read as 0.003 mm") != std::string::npos;
    EXPECT_TRUE(warned) << end;
  }
  // each program of a file is read from out of cycle mode: O0002's K3 is no repeat count, though
  // O0001 ends in it
  auto two = run("O0001\nG90 G00 X0. Y0. Z10.\nG99 G81 X10. Y10. Z-5. R2. F200.\nM30\nO0002\nX20. K3\nM99\n");
  bool warned = false;
  for (const auto& w : two.result.warnings)
    warned |= w.code == "NC2001" && w.message.find("K3 is read as 0.003 mm") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(CannedCycles, K0StoresTheDataAndDrillsNothing) {
  auto r = run("G90 G00 X0. Y0. Z20.\nG98 G81 X10. Z-5. R2. K0 F100.\nX20.\nM30\n");
  expect_moves(r, 2, {{3, R, 20, 0, 20}, {3, R, 20, 0, 2}, {3, L, 20, 0, -5}, {3, R, 20, 0, 20}});
}

// G83 Z-10 Q3 from R2 with d = No.5115 = 0.5: 2 -> -1 -> 2 -> -0.5 -> -4 -> 2 -> -3.5 -> -7 -> 2 -> -6.5 -> -10.
TEST(CannedCycles, G83PecksBackToR) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "5115", 500);
  auto r = run("G90 G00 X0. Y0. Z10.\nG98 G83 X5. Z-10. R2. Q3. F100.\nM30\n", p);
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 2}, {2, L, 5, 0, -1}, {2, R, 5, 0, 2}, {2, R, 5, 0, -0.5},
                      {2, L, 5, 0, -4}, {2, R, 5, 0, 2}, {2, R, 5, 0, -3.5}, {2, L, 5, 0, -7}, {2, R, 5, 0, 2},
                      {2, R, 5, 0, -6.5}, {2, L, 5, 0, -10}, {2, R, 5, 0, 10}});
}

// G73 Z-7 Q3 from R1 with d = No.5114 = 0.4: 1 -> -2 -> -1.6 -> -5 -> -4.6 -> -7, back to R (G99).
TEST(CannedCycles, G73RetractsByD) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "5114", 400);
  auto r = run("G90 G00 X0. Y0. Z10.\nG99 G73 X5. Z-7. R1. Q3. F100.\nM30\n", p);
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 1}, {2, L, 5, 0, -2}, {2, R, 5, 0, -1.6}, {2, L, 5, 0, -5},
                      {2, R, 5, 0, -4.6}, {2, L, 5, 0, -7}, {2, R, 5, 0, 1}});
  EXPECT_DOUBLE_EQ(p.peck_retract, 0.4);
}

TEST(CannedCycles, G82AndG89DwellAtTheBottom) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG98 G82 X5. Z-3. R1. P500 F100.\nG89 X8. P250\nM30\n");
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 1}, {2, L, 5, 0, -3}, {2, D, 5, 0, -3}, {2, R, 5, 0, 10},
                      {3, R, 8, 0, 10}, {3, R, 8, 0, 1}, {3, L, 8, 0, -3}, {3, D, 8, 0, -3}, {3, L, 8, 0, 1},
                      {3, R, 8, 0, 10}});
  std::vector<double> dwells;
  for (const auto& m : r.moves)
    if (m.kind == MoveKind::dwell) dwells.push_back(m.seconds);
  ASSERT_EQ(dwells.size(), 2u);
  EXPECT_DOUBLE_EQ(dwells[0], 0.5);
  EXPECT_DOUBLE_EQ(dwells[1], 0.25);
}

TEST(CannedCycles, G85FeedsOutToR) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG99 G85 X5. Z-3. R1. F100.\nM30\n");
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 1}, {2, L, 5, 0, -3}, {2, L, 5, 0, 1}});
}

TEST(CannedCycles, G86StopsTheSpindleAtTheBottom) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG98 G86 X5. Z-3. R1. F100.\nM30\n");
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 1}, {2, L, 5, 0, -3}, {2, S, 5, 0, -3}, {2, R, 5, 0, 10},
                      {2, S, 5, 0, 10}});
  std::vector<int> codes;
  for (const auto& m : r.moves)
    if (m.kind == MoveKind::spindle) codes.push_back(m.code);
  EXPECT_EQ(codes, (std::vector<int>{5, 3}));
}

namespace {
// Codes of the spindle events of a run, in order.
std::vector<int> spindle_codes(const test::Ran& r) {
  std::vector<int> codes;
  for (const auto& m : r.moves)
    if (m.kind == MoveKind::spindle) codes.push_back(m.code);
  return codes;
}
}  // namespace

// G84: dwell P at Z, M05 (No.5101#6 M5T = 0), M04, feed out to R, dwell P, M05, M03, rapid back.
TEST(CannedCycles, G84ReversesTheSpindleToBackOut) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG98 G84 X5. Z-3. R1. P300 F100.\nM30\n");
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 1}, {2, L, 5, 0, -3}, {2, D, 5, 0, -3}, {2, S, 5, 0, -3},
                      {2, S, 5, 0, -3}, {2, L, 5, 0, 1}, {2, D, 5, 0, 1}, {2, S, 5, 0, 1}, {2, S, 5, 0, 1},
                      {2, R, 5, 0, 10}});
  EXPECT_EQ(spindle_codes(r), (std::vector<int>{5, 4, 5, 3}));
  auto left = run("G90 G00 X0. Y0. Z10.\nG98 G74 X5. Z-3. R1. F100.\nM30\n");
  EXPECT_EQ(spindle_codes(left), (std::vector<int>{5, 3, 5, 4}));
  auto m5t = machine::default_mill();
  machine::set_parameter(m5t, "5101#6", 1);  // M5T = 1: no M05 before the reversal
  EXPECT_EQ(spindle_codes(run("G90 G00 X0. Y0. Z10.\nG98 G84 X5. Z-3. R1. F100.\nM30\n", m5t)),
            (std::vector<int>{4, 3}));
}

// No.5200#0 = 1: G84 taps rigidly without M29; the moves are feeds at F with the spindle synchronised.
TEST(CannedCycles, G84IsRigidWithParameter5200Bit0) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "5200#0", 1);
  auto r = run("G90 G00 X0. Y0. Z10. S500\nG99 G84 X5. Z-3. R1. F750.\nM30\n", p);
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 1}, {2, S, 5, 0, 1}, {2, L, 5, 0, -3}, {2, S, 5, 0, -3},
                      {2, S, 5, 0, -3}, {2, L, 5, 0, 1}, {2, S, 5, 0, 1}});
  EXPECT_EQ(spindle_codes(r), (std::vector<int>{3, 5, 4, 5}));
  for (const auto& m : r.motions()) {
    if (m.kind == MoveKind::line) {
      EXPECT_DOUBLE_EQ(m.feed, 750);
    }
  }
  // without the parameter the same block is a tapping cycle with a floating holder
  EXPECT_EQ(spindle_codes(run("G90 G00 X0. Y0. Z10. S500\nG99 G84 X5. Z-3. R1. F750.\nM30\n")),
            (std::vector<int>{5, 4, 5, 3}));
}

// Ending rigid tapping clears its S (as S0): the next rigid tapping needs S again (PS0200). F0 is PS0201.
TEST(CannedCycles, RigidTappingNeedsSAndF) {
  auto r = run("G90 G00 Z10.\nM29 S500\nG84 X5. Z-3. R1. F100.\nG80\nM29\nG84 X8. Z-3. R1.\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0200");
  EXPECT_EQ(r.alarm_line(), 6u);
  EXPECT_EQ(run("G90 G00 Z10.\nM29 S500\nG84 X5. Z-3. R1.\nM30\n").alarm_code(), "PS0201");
  // a block without axis words between M29 and G84 is allowed
  EXPECT_TRUE(run("G90 G00 Z10. F100.\nM29 S500\nG04 P10\nG84 X5. Z-3. R1.\nM30\n").result.ok());
}

// No.5101#0 FXY = 0 (factory): Z drills whatever the plane.
TEST(CannedCycles, FactoryFxyDrillsAlongZInEveryPlane) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG19 G98 G81 X5. Y2. Z-3. R1. F100.\nM30\n");
  expect_moves(r, 2, {{2, R, 5, 2, 10}, {2, R, 5, 2, 1}, {2, L, 5, 2, -3}, {2, R, 5, 2, 10}});
}

// G18 with FXY = 1: Y drills, X Z position; the Y word is the bottom.
TEST(CannedCycles, G18DrillsAlongYWithFxy) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "5101#0", 1);
  auto r = run("G90 G18 G00 X0. Y20. Z0.\nG99 G81 X5. Z-4. Y-3. R2. F100.\nM30\n", p);
  expect_moves(r, 2, {{2, R, 5, 20, -4}, {2, R, 5, 2, -4}, {2, L, 5, -3, -4}, {2, R, 5, 2, -4}});
  // G76 in G18: RD2 RD1 = 0 0 shifts +Z
  auto b = run("G90 G18 G00 X0. Y20. Z0.\nG98 G76 X5. Z-4. Y-3. R2. Q0.5 F100.\nM30\n", p);
  expect_moves(b, 2, {{2, R, 5, 20, -4}, {2, R, 5, 2, -4}, {2, L, 5, -3, -4}, {2, S, 5, -3, -4},
                      {2, R, 5, -3, -3.5}, {2, R, 5, 20, -3.5}, {2, R, 5, 20, -4}, {2, S, 5, 20, -4}});
}

// A cycle under G41: the holes are drilled at the programmed points (the vector cancelled as for
// G28), and the next move after G80 starts the offset again.
TEST(CannedCycles, CutterCompensationIsSuspendedInACycle) {
  auto r = run("G10 L11 P1 R5.\nG90 G17 G00 X0. Y0. Z10.\nG41 G01 X20. Y0. D1 F100.\nG98 G81 X30. Y10. Z-3. R1.\n"
               "G80\nG01 X40. Y0.\nG40 X50.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  bool drilled = false;
  for (const auto& m : r.moves)
    if (m.line == 4 && m.kind == MoveKind::line) {
      EXPECT_NEAR(m.end[0], 30, 1e-9);
      EXPECT_NEAR(m.end[1], 10, 1e-9);
      EXPECT_NEAR(m.end[2], -3, 1e-9);
      drilled = true;
    }
  EXPECT_TRUE(drilled);
}

// A profile whose control counts repeats with L (cycle_repeat = "L"); K is then an alarm.
TEST(CannedCycles, RepeatsWithL) {
  auto p = machine::parse_profile("[machine]\ncycle_repeat = \"L\"\n", "l.toml");
  auto r = run("G90 G00 X0. Y0. Z20.\nG91 G99 G81 X10. Z-7. R-18. L2 F100.\nM30\n", p);
  expect_moves(r, 2, {{2, R, 10, 0, 20}, {2, R, 10, 0, 2}, {2, L, 10, 0, -5}, {2, R, 10, 0, 2},
                      {2, R, 20, 0, 2}, {2, L, 20, 0, -5}, {2, R, 20, 0, 2}});
  EXPECT_EQ(run("G90 G00 Z20.\nG91 G99 G81 X10. Z-7. R-18. K2 F100.\nM30\n", p).alarm_code(), "PS0009");
}

// G91 K2 with G76: the shift and its return at each hole, the hole stepping by the increment.
TEST(CannedCycles, G76RepeatsShiftAtEachHole) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG91 G99 G76 X10. Z-5. R-8. Q1. K2 F100.\nM30\n");
  expect_moves(r, 2, {{2, R, 10, 0, 10}, {2, R, 10, 0, 2}, {2, L, 10, 0, -3}, {2, S, 10, 0, -3},
                      {2, R, 11, 0, -3}, {2, R, 11, 0, 2}, {2, R, 10, 0, 2}, {2, S, 10, 0, 2},
                      {2, R, 20, 0, 2}, {2, L, 20, 0, -3}, {2, S, 20, 0, -3}, {2, R, 21, 0, -3},
                      {2, R, 21, 0, 2}, {2, R, 20, 0, 2}, {2, S, 20, 0, 2}});
  EXPECT_EQ(spindle_codes(r), (std::vector<int>{19, 3, 19, 3}));
}

TEST(CannedCycles, G80AndG01Cancel) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG99 G81 X5. Z-3. R1. F100.\nG80 X20.\nG81 X30. Z-3. R1.\nG01 X40.\nX50.\nM30\n");
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 1}, {2, L, 5, 0, -3}, {2, R, 5, 0, 1},
                      {3, R, 20, 0, 1},
                      {4, R, 30, 0, 1}, {4, L, 30, 0, -3}, {4, R, 30, 0, 1},
                      {5, L, 40, 0, 1}, {6, L, 50, 0, 1}});
  // after G80 the data are gone: Z is cleared, "Z = 0 in incremental mode", a hole without depth
  auto again = run("G90 G00 X0. Y0. Z10.\nG81 X5. Z-3. R1. F100.\nG80\nG81 X10. R1.\nM30\n");
  expect_moves(again, 4, {{4, R, 10, 0, 10}, {4, R, 10, 0, 1}, {4, R, 10, 0, 10}});
}

// R, F and P alone change the kept data but drill nothing; Z is an axis word and drills where the tool is.
TEST(CannedCycles, ABlockWithoutAxisWordsDoesNotDrill) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG98 G81 X5. Z-3. R1. F100.\nR2.\nF200.\nX8.\nZ-4.\nM30\n");
  expect_moves(r, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 1}, {2, L, 5, 0, -3}, {2, R, 5, 0, 10},
                      {5, R, 8, 0, 10}, {5, R, 8, 0, 2}, {5, L, 8, 0, -3}, {5, R, 8, 0, 10},
                      {6, R, 8, 0, 2}, {6, L, 8, 0, -4}, {6, R, 8, 0, 10}});
  EXPECT_DOUBLE_EQ(r.motions().at(7).feed, 200);
}

// The manual on G80: "Point R and point Z are cleared. This means that R = 0 and Z = 0 in
// incremental mode." A hole without R starts at the initial level; without Z it has no depth.
TEST(CannedCycles, ClearedRAndZAreZeroIncremental) {
  auto no_z = run("G00 Z10.\nG81 X5. R2. F100.\nM30\n");
  expect_moves(no_z, 2, {{2, R, 5, 0, 10}, {2, R, 5, 0, 2}, {2, R, 5, 0, 10}});
  ASSERT_EQ(no_z.result.warnings.size(), 1u);
  EXPECT_EQ(no_z.result.warnings[0].code, "NC2017");
  auto no_r = run("G00 Z10.\nG81 X5. Z-2. F100.\nM30\n");
  expect_moves(no_r, 2, {{2, R, 5, 0, 10}, {2, L, 5, 0, -2}, {2, R, 5, 0, 10}});
  // corpus O0061: G99 without R after G80 returns to point R, which is the initial level
  auto g99 = run("G90 G00 X0. Y0. Z1.455\nG81 G99 X1. Z0.3 F42.\nX2. Z-1.1\nG80\nM30\n");
  expect_moves(g99, 2, {{2, R, 1, 0, 1.455}, {2, L, 1, 0, 0.3}, {2, R, 1, 0, 1.455},
                        {3, R, 2, 0, 1.455}, {3, L, 2, 0, -1.1}, {3, R, 2, 0, 1.455}});
}

TEST(CannedCycles, MissingDataAlarms) {
  auto q = run("G00 Z10.\nG83 X5. Z-10. R2. F100.\nM30\n");
  EXPECT_EQ(q.alarm_code(), "PS0045");
  EXPECT_EQ(q.alarm_line(), 2u);
  EXPECT_EQ(run("G00 Z10.\nG73 X5. Z-10. R2. Q0 F100.\nM30\n").alarm_code(), "PS0045");
}

TEST(CannedCycles, ModalInformation) {
  auto r = run("G00 Z10.\nG99 G83 Z-3. R1. Q1. F100.\n#100=#4009\n#101=#4010\nG98 G80\n#102=#4009\n#103=#4010\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 83);
  EXPECT_DOUBLE_EQ(r.var(101), 99);
  EXPECT_DOUBLE_EQ(r.var(102), 80);
  EXPECT_DOUBLE_EQ(r.var(103), 98);
}

// Q and P are stored only from a block that drills: P1000 alone on line 3 is not kept, so the hole of
// line 4 dwells the 500 ms of line 2 (FANUC: "specify Q and P in a block that performs drilling").
TEST(CannedCycles, QAndPOnlyFromADrillingBlock) {
  auto r = run("G90 G00 X0. Y0. Z10.\nG99 G82 X5. Z-5. R2. P500 F100.\nP1000\nX10.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  std::vector<double> dwells;
  for (const auto& m : r.moves)
    if (m.kind == MoveKind::dwell) dwells.push_back(m.seconds);
  ASSERT_EQ(dwells.size(), 2u);
  EXPECT_DOUBLE_EQ(dwells[0], 0.5);
  EXPECT_DOUBLE_EQ(dwells[1], 0.5);
}
