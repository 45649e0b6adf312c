// A lathe's canned cycles for drilling (G83..G85 face, G87..G89 side) beyond the point lists of
// tests/programs/lathe/lt_drill_*: the C-axis clamp M code, Q in least input increments, R's
// parameters, the return level of system A, what ends the mode, the alarms and tool-nose radius
// compensation. Values worked out by hand from the FANUC 0i-TF / 30i-B lathe operator's manuals.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <string>
#include <vector>

#include "machine/profile.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;
using machine::MoveKind;

namespace {
machine::MachineProfile lathe(char system = 'A') {
  auto p = machine::default_lathe();
  p.gcode_system = system;
  return p;
}

// "line kind X Z" (X as a diameter) or "line kind code" for events, dwells in ms, from `line` on
std::vector<std::string> listing(const test::Ran& r, std::uint32_t line) {
  std::vector<std::string> out;
  for (const auto& m : r.moves) {
    if (m.line < line) continue;
    if (m.is_motion()) out.push_back(fmt::format("{} {} X{:g} Z{:g}", m.line, machine::to_string(m.kind), 2 * m.end[0], m.end[2]));
    else if (m.kind == MoveKind::dwell) out.push_back(fmt::format("{} dwell {:g}", m.line, m.seconds * 1000));
    else out.push_back(fmt::format("{} {} {}", m.line, machine::to_string(m.kind), m.code));
  }
  return out;
}

using Lines = std::vector<std::string>;
}  // namespace

// No.5110 = 31 (clamp), No.5111 = 200 ms: M31 in a drilling block is given out at each hole after
// its positioning, M32 (the unclamp, clamp + 1) and the dwell after the return; not again after the block.
TEST(LatheDrilling, CAxisClampAtEachHoleThenUnclampAndDwell) {
  auto p = lathe();
  machine::set_parameter(p, "5110", 31);
  machine::set_parameter(p, "5111", 200);
  auto r = run("G21 G99\nG00 X50. Z5.\nG83 Z-10. R-2. F0.1 M31\nX40. M31\nG80 M05\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(listing(r, 3), (Lines{"3 m_code 31", "3 rapid X50 Z3", "3 line X50 Z-10", "3 rapid X50 Z5", "3 m_code 32",
                                  "3 dwell 200", "4 rapid X40 Z5", "4 m_code 31", "4 rapid X40 Z3", "4 line X40 Z-10",
                                  "4 rapid X40 Z5", "4 m_code 32", "4 dwell 200", "5 spindle 5", "6 program_end 30"}));
}

// Without No.5110 the M code is an ordinary one: after the block's motions, once.
TEST(LatheDrilling, WithoutNo5110AnMCodeIsAnOrdinaryOne) {
  auto r = run("G21 G99\nG00 X50. Z5.\nG83 Z-10. R-2. F0.1 M31\nG80\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(listing(r, 3), (Lines{"3 rapid X50 Z3", "3 line X50 Z-10", "3 rapid X50 Z5", "3 m_code 31", "5 program_end 30"}));
}

// Q is a depth in least input increments: Q2000 under G20 is 0.2 inch; a decimal point is PS0007.
TEST(LatheDrilling, QIsInLeastInputIncrements) {
  auto r = run("G20 G99\nG00 X0. Z.05\nG83 Z-.5 Q2000 F.006\nG80\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_NEAR(r.motions()[1].end[2], (0.05 - 0.2) * 25.4, 1e-9);
  EXPECT_NEAR(r.motions()[2].end[2], (0.05 - 0.4) * 25.4, 1e-9);
  EXPECT_NEAR(r.motions()[3].end[2], -0.5 * 25.4, 1e-9);
  auto d = run("G21 G99\nG00 X0. Z5.\nG83 Z-10. R-2. Q5. F0.1\nM30\n", lathe());
  EXPECT_EQ(d.alarm_code(), "PS0007");
  EXPECT_EQ(d.alarm_line(), 3u);
}

// In system A, G98/G99 are feed per minute/revolution: the hole ends at the initial level either way.
// In system B, G99 returns to R (tests/programs/lathe/lt_drill_g85_g89_b.nc has both).
TEST(LatheDrilling, SystemAReturnsToTheInitialLevel) {
  for (const char* feed : {"G98 G83 Z-10. R-7. F100.", "G99 G83 Z-10. R-7. F0.1"}) {
    auto r = run(fmt::format("G21\nG00 X0. Z10.\n{}\nG80\nM30\n", feed), lathe());
    ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
    EXPECT_EQ(listing(r, 3), (Lines{"3 rapid X0 Z3", "3 line X0 Z-10", "3 rapid X0 Z10", "5 program_end 30"})) << feed;
  }
  auto b = run("G21 G95\nG00 X0. Z10.\nG99 G83 Z-10. R3. F0.1\nG80\nM30\n", lathe('B'));
  ASSERT_TRUE(b.result.ok()) << nc::format(*b.result.alarm);
  EXPECT_EQ(listing(b, 3), (Lines{"3 rapid X0 Z3", "3 line X0 Z-10", "3 rapid X0 Z3", "5 program_end 30"}));
}

// No.5102#6 RDI = 1: R of side drilling is a diameter like X (R-4 from X60: point R at X56, not X52).
// No.5102#7 RAB = 1: system A's R is an absolute level (R3. from Z10: point R at Z3, not Z13).
TEST(LatheDrilling, RadiusOrDiameterAndAbsoluteR) {
  auto p = lathe();
  machine::set_parameter(p, "5102#6", 1);
  auto r = run("G21 G99\nG00 X60. Z-10.\nG87 X20. R-4. F0.1\nG80\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(listing(r, 3), (Lines{"3 rapid X56 Z-10", "3 line X20 Z-10", "3 rapid X60 Z-10", "5 program_end 30"}));
  auto a = lathe();
  machine::set_parameter(a, "5102#7", 1);
  auto s = run("G21 G99\nG00 X0. Z10.\nG83 Z-8. R3. F0.1\nG80\nM30\n", a);
  ASSERT_TRUE(s.result.ok()) << nc::format(*s.result.alarm);
  EXPECT_EQ(listing(s, 3), (Lines{"3 rapid X0 Z3", "3 line X0 Z-8", "3 rapid X0 Z10", "5 program_end 30"}));
  auto i = run("G21 G99\nG00 X0. Z10.\nG83 Z-8. R3. F0.1\nG80\nM30\n", lathe());  // factory: from the initial level
  EXPECT_EQ(listing(i, 3)[0], "3 rapid X0 Z13");
}

// G80 or any group 01 code ends the mode: in system A G90 is then a turning cycle, G01 a cut.
TEST(LatheDrilling, G80OrAGroup01CodeEndsTheMode) {
  auto r = run("G21 G99\nG00 X40. Z5.\nG83 Z-10. R-2. F0.1\nG90 X30. Z-5. F0.2\nM30\n", lathe());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(listing(r, 4), (Lines{"4 rapid X30 Z5", "4 line X30 Z-5", "4 line X40 Z-5", "4 rapid X40 Z5",
                                  "5 program_end 30"}));
  auto g = run("G21 G99\nG00 X40. Z5.\nG87 X10. R-2. F0.1\nG01 Z0.\nG80 X20.\nM30\n", lathe());
  ASSERT_TRUE(g.result.ok()) << nc::format(*g.result.alarm);
  EXPECT_EQ(listing(g, 4), (Lines{"4 line X40 Z0", "5 line X20 Z0", "6 program_end 30"}));
}

TEST(LatheDrilling, Alarms) {
  // a hole without its bottom: PS0045 at the first block that drills
  auto z = run("G21 G99\nG00 X0. Z5.\nG83 R-2. F0.1\nX10.\nM30\n", lathe());
  EXPECT_EQ(z.alarm_code(), "PS0045");
  EXPECT_EQ(z.alarm_line(), 4u);
  // rigid tapping (M29 before G84, or No.5200#0) is not run on a lathe
  EXPECT_EQ(run("G21 G99\nG00 X0. Z5.\nM29 S500\nG84 Z-10. R-2. F1.\nM30\n", lathe()).alarm_code(), "NC9001");
  auto rigid = lathe();
  machine::set_parameter(rigid, "5200#0", 1);
  EXPECT_EQ(run("G21 G99\nG00 X0. Z5.\nG88 X0. R-2. F1.\nM30\n", rigid).alarm_code(), "NC9001");
  // H, system A's incremental C, is not read yet
  EXPECT_EQ(run("G21 G99\nG00 X20. Z5.\nG83 Z-10. R-2. H9000 F0.1\nM30\n", lathe()).alarm_code(), "NC9001");
}

// Under G42 the holes are drilled at the programmed points (the vector cancelled as for G28).
TEST(LatheDrilling, NoseRadiusCompensationIsSuspendedInTheCycle) {
  auto p = lathe();
  p.lathe_offsets[1].r = 0.8;
  p.lathe_offsets[1].tip = 3;
  auto r = run("T0101\nG21 G99 G42 G00 X20. Z5.\nG83 X0. Z-10. R-2. F0.1\nG80\nG40 G00 X50. Z20.\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  int drilled = 0;
  for (const auto& m : r.moves)
    if (m.line == 3 && m.is_motion()) {
      EXPECT_NEAR(m.end[0], 0, 1e-9);
      ++drilled;
      if (m.kind == MoveKind::line) {
        EXPECT_NEAR(m.end[2], -10, 1e-9);
      }
    }
  EXPECT_EQ(drilled, 4);  // to X0, to R, the bottom, back to the initial level
}
