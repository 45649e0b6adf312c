// The lane of plain G00/G01 blocks (machine/plain_motion.cpp) against the general path: random
// programs of plain blocks mixed with the states that must turn them away (cycles, compensation,
// transforms, G91, inches, tool changes, macro calls, arcs, comma corners, parameter input) run
// both ways and give the same moves, field by field, and the same summary, warnings and alarm.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cstring>
#include <random>

#include "support/run_program.hpp"

using namespace ncurve;

namespace {

std::string random_program(std::mt19937& rng) {
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  auto coord = [&] { return fmt::format("{:.{}f}", (pick(40001) - 20000) / 1000.0, pick(4)); };
  const char* state[] = {
      "G91", "G90", "G20", "G21", "G17", "G18", "G19", "T2 M06", "G43 H1 Z10.", "G49",
      "G41 D1 X5. Y5.", "G42 D2 X0 Y-5.", "G41 D1", "G42 D2", "G40", "G40 X0 Y0", "G81 X1. Y1. Z-3. R1. F200.", "G80",
      "G68 X0 Y0 R30.", "G69", "G51 X0 Y0 P1500", "G50", "G51.1 X0", "G50.1 X0", "G52 X5. Y5.", "G52 X0 Y0",
      "G55", "G54", "G02 X10. Y0 R5. F300.", "G03 X0 Y0 R5.", "G61", "G64", "G09 G01 X3. Y3.",
      "G01 X5. ,C1.", "G01 Y8. ,R1.", "G01 X0 Y0", "M03 S1000", "M05", "G94", "G95", "G65 P9001 A1.",
      "G66 P9001 A2.", "G67", "G16", "G15", "X1 Y2", "G01 X2", "#1=#1+1", "G28 Z0", "G04 P100",
      "G01 F-5.", "G01 X1. X2.", "F0", "G1. X1.", "G01 G00 X3.", "G10 L52\nN6050 R1\nG11",
  };
  std::string s = "O1000\nG21 G90 G17 G54 G40 G80 G49\nG10 L11 P1 R2.\nG10 L11 P2 R1.5\nG10 L10 P1 R50.\n";
  for (int n = 20 + pick(60); n > 0; --n) {
    if (pick(4) == 0) {
      s += state[pick(static_cast<int>(std::size(state)))];
    } else {
      const char* g[] = {"", "G00 ", "G01 ", "G0 ", "G1 "};
      s += g[pick(5)];
      for (char a : {'X', 'Y', 'Z'})
        if (pick(3) != 0) s += fmt::format("{}{} ", a, coord());
      if (pick(4) == 0) s += fmt::format("F{}", 50 + pick(2000));
    }
    s += "\n";
  }
  return s + "M30\n";
}

void expect_same(const test::Ran& lane, const test::Ran& general) {
  EXPECT_EQ(lane.alarm_code(), general.alarm_code());
  EXPECT_EQ(lane.alarm_line(), general.alarm_line());
  ASSERT_EQ(lane.moves.size(), general.moves.size());
  for (std::size_t i = 0; i < lane.moves.size(); ++i) {
    const machine::Move& a = lane.moves[i];
    const machine::Move& b = general.moves[i];
    SCOPED_TRACE(fmt::format("move {} line {}", i, b.line));
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.line, b.line);
    EXPECT_EQ(a.start, b.start);
    EXPECT_EQ(a.end, b.end);
    EXPECT_EQ(a.programmed_end, b.programmed_end);
    EXPECT_EQ(a.feed, b.feed);
    EXPECT_EQ(a.seconds, b.seconds);
    EXPECT_EQ(a.length, b.length);
    EXPECT_EQ(a.exact_stop, b.exact_stop);
    EXPECT_EQ(a.nc_blocks, b.nc_blocks);
    EXPECT_EQ(a.macro_statements, b.macro_statements);
  }
  EXPECT_EQ(lane.result.stats.blocks, general.result.stats.blocks);
  EXPECT_EQ(lane.result.stats.seconds, general.result.stats.seconds);
  EXPECT_EQ(lane.result.stats.feed_length, general.result.stats.feed_length);
  ASSERT_EQ(lane.result.warnings.size(), general.result.warnings.size());
  for (std::size_t i = 0; i < lane.result.warnings.size(); ++i) {
    EXPECT_EQ(lane.result.warnings[i].code, general.result.warnings[i].code);
    EXPECT_EQ(lane.result.warnings[i].message, general.result.warnings[i].message);
    EXPECT_EQ(lane.result.warnings[i].span.line, general.result.warnings[i].span.line);
    EXPECT_EQ(lane.result.warnings[i].span.column, general.result.warnings[i].span.column);
  }
}

}  // namespace

TEST(PlainLane, RandomProgramsRunAsByTheGeneralPath) {
  const std::map<std::string, std::string> macros = {{"O9001.nc", "O9001\nG91 G01 X#1 F100.\nG90\nM99\n"},
                                                      {"O9010.nc", "O9010\nG01 X[#24+1] F300.\nM99\n"}};
  std::mt19937 rng(11);
  std::uint64_t laned = 0;
  for (int k = 0; k < 2000; ++k) {
    const std::string text = random_program(rng);
    SCOPED_TRACE(text);
    machine::RunOptions on, off;
    off.plain_lane = false;
    const test::Ran lane = test::run(text, test::zero_offset_mill(), on, macros);
    laned += lane.interp->plain_lane_blocks();
    const test::Ran general = test::run(text, test::zero_offset_mill(), off, macros);
    expect_same(lane, general);
    if (HasFailure()) return;
  }
  EXPECT_GT(laned, 10000u);  // the lane was taken, not only turned away
}

// An expanded program's blocks take the lane; the values are the program's own literals.
TEST(PlainLane, AnExpandedProgramTakesIt) {
  const test::Ran r = test::run("O1\nG21 G90 G17\nG01 X1.5 Y-2.25 Z-0.125 F500\nX3. Y4.\nG00 Z10.\nG1 X0 Y0 Z0\nM30\n");
  EXPECT_EQ(r.interp->plain_lane_blocks(), 4u);
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[0].end[0], 1.5);
  EXPECT_EQ(m[0].end[1], -2.25);
  EXPECT_EQ(m[0].end[2], -0.125);
  EXPECT_EQ(m[0].feed, 500);
  EXPECT_EQ(m[1].end[0], 3);
  EXPECT_EQ(m[1].end[1], 4);
  EXPECT_EQ(m[2].kind, machine::MoveKind::rapid);
  EXPECT_EQ(m[2].end[2], 10);
  EXPECT_EQ(m[3].kind, machine::MoveKind::line);
}
