// FANUC limits on computed values and on the words of a block: PS0111 (calculated data overflow),
// PS0003 (too many digits), PS0006 (minus sign), PS0073/PS0074 (program numbers), PS5074 (address
// duplication, No.3403#6 AD2) and No.3404#7 M3B; the run limits --max-steps and --max-seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <chrono>
#include <limits>

#include "support/run_program.hpp"

using namespace ncurve;
using test::run;

namespace {

std::vector<machine::Move> of_kind(const test::Ran& r, machine::MoveKind k) {
  std::vector<machine::Move> out;
  for (const auto& m : r.moves)
    if (m.kind == k) out.push_back(m);
  return out;
}

bool warned(const test::Ran& r, const std::string& code) {
  for (const auto& w : r.result.warnings)
    if (w.code == code) return true;
  return false;
}

}  // namespace

// The range of a macro value is -1e47 .. 1e47 (0i manual, custom macro, range of variable values);
// a result beyond it at any step is PS0111. 99999999^5 = 9.9999995e39; times 99999999 it is
// 9.9999994e47 > 1e47; times 9999999 (7 digits) it is 9.9999985e46 < 1e47.
TEST(Limits, AResultBeyond1e47IsPS0111AtTheOperator) {
  const std::string five = "99999999*99999999*99999999*99999999*99999999";
  auto over = run("#1=" + five + "*99999999\nM30\n");
  EXPECT_EQ(over.alarm_code(), "PS0111");
  EXPECT_EQ(over.result.alarm->span.column, 48u);  // the fifth '*', before the sixth factor: 3 + 8 + 1 + 4 * 9
  auto under = run("#1=" + five + "*9999999\nM30\n");
  ASSERT_TRUE(under.result.ok());
  EXPECT_NEAR(under.var(1), 9.9999985e46, 1e40);
  // an intermediate result counts though the final one would fit: 1e48 / 100 = 1e46
  EXPECT_EQ(run("#1=[" + five + "*99999999]/100\nM30\n").alarm_code(), "PS0111");
  // below -1e47, by a subtraction and by a division (1e40 / 1e-8 = 1e48)
  EXPECT_EQ(run("#2=" + five + "*9999999\n#1=-#2-#2-#2\nM30\n").alarm_code(), "PS0111");
  EXPECT_EQ(run("#1=[" + five + "]/.00000001\nM30\n").alarm_code(), "PS0111");
  // in a condition, an NC word and a GOTO target alike
  EXPECT_EQ(run("IF [" + five + "*99999999 GT 0] GOTO 5\nN5 M30\n").alarm_code(), "PS0111");
  EXPECT_EQ(run("WHILE [" + five + "*99999999 GT 0] DO1\nEND1\nM30\n").alarm_code(), "PS0111");
  EXPECT_EQ(run("G00 X[" + five + "*99999999]\nM30\n").alarm_code(), "PS0111");
}

// Infinity never arises, so inf - inf cannot make a NaN; a NaN read from anywhere is refused, and a
// WHILE never takes one as true.
TEST(Limits, NaNIsNeverAConditionResult) {
  struct NanVars {
    nc::Value read(int, std::uint16_t) { return nc::Value::of(std::numeric_limits<double>::quiet_NaN()); }
  } vars;
  const nc::Instr code[] = {{nc::Op::var, 3, 1, 0}, {nc::Op::konst, 7, 0, 0}, {nc::Op::gt, 5, 0, 0}};
  const nc::EvalResult r = nc::evaluate(code, code + 3, vars, nc::EvalOptions{});
  EXPECT_EQ(r.fault, nc::EvalFault::overflow);
  EXPECT_EQ(r.column, 3u);
  // EXP[200] = 7e86 is already out of range: no inf to subtract from itself
  EXPECT_EQ(run("#1=EXP[200]-EXP[200]\nM30\n").alarm_code(), "PS0111");
  EXPECT_EQ(run("WHILE [EXP[200]-EXP[200] NE 0] DO1\n#100=1\nEND1\nM30\n").alarm_code(), "PS0111");
}

// IS-B, 8 digits (0i): a dimension counts in 0.001 mm increments, so |X| <= 99999.999 mm; an inch
// dimension in 0.0001 in, |X| <= 9999.9999 in; other addresses count whole units, |S| <= 99999999.
TEST(Limits, AComputedWordBeyondTheDigitsIsPS0003) {
  auto big = run("G91 G01 X[99999999*9999999] F100.\nM30\n");
  EXPECT_EQ(big.alarm_code(), "PS0003");
  EXPECT_EQ(big.result.alarm->span.column, 9u);
  EXPECT_TRUE(big.motions().empty());
  EXPECT_EQ(run("G00 X[100000]\nM30\n").alarm_code(), "PS0003");
  EXPECT_EQ(run("G00 Y[-100000]\nM30\n").alarm_code(), "PS0003");
  auto edge = run("G00 X[99999.999]\nM30\n");
  ASSERT_TRUE(edge.result.ok()) << nc::format(*edge.result.alarm);
  EXPECT_NEAR(edge.motions().back().end[0], 99999.999, 1e-9);
  EXPECT_EQ(run("G20\nG00 X[10000]\nM30\n").alarm_code(), "PS0003");
  EXPECT_TRUE(run("G20\nG00 X[9999.9999]\nM30\n").result.ok());
  EXPECT_EQ(run("S[100000000] M03\nM30\n").alarm_code(), "PS0003");
  EXPECT_TRUE(run("S[99999999] M03\nM30\n").result.ok());
  // a 9-digit control (number_digits = 9) takes 100000 mm
  auto p = machine::default_mill();
  p.number_digits = 9;
  EXPECT_TRUE(run("G00 X[100000]\nM30\n", p).result.ok());
  EXPECT_EQ(run("G00 X[1000000]\nM30\n", p).alarm_code(), "PS0003");
}

// M, S, T, H and D take no minus sign (PS0006); as macro arguments they carry any value.
TEST(Limits, AMinusSignOnMSTHDIsPS0006) {
  for (const char* block : {"T#1 M06", "S#1 M03", "M#1", "G43 Z10. H#1", "G41 G01 X10. D#1 F100."}) {
    SCOPED_TRACE(block);
    auto r = run(std::string("#1=-1\n") + block + "\nM30\n");
    EXPECT_EQ(r.alarm_code(), "PS0006");
    EXPECT_EQ(r.alarm_line(), 2u);
    EXPECT_TRUE(of_kind(r, machine::MoveKind::tool_change).empty());
  }
  auto call = run("G65 P9100 T-1. S-2. M-3.\nM30\n", machine::default_mill(), {},
                  {{"O9100.nc", "O9100\n#100=#20+#19+#13\nM99\n"}});
  ASSERT_TRUE(call.result.ok()) << nc::format(*call.result.alarm);
  EXPECT_EQ(call.var(100), -6.0);
}

// Program numbers are 1 to 99999999 (8 digits): O0 is PS0074, nine digits PS0003; the program
// alarms where it starts, at its O word.
TEST(Limits, ProgramNumbersOutOfRange) {
  auto zero = run("O0\nG00 X1.\nM30\n");
  EXPECT_EQ(zero.alarm_code(), "PS0074");
  EXPECT_EQ(zero.alarm_line(), 1u);
  EXPECT_TRUE(zero.motions().empty());
  auto nine = run("O123456789\nG00 X1.\nM30\n");
  EXPECT_EQ(nine.alarm_code(), "PS0003");
  EXPECT_EQ(nine.alarm_line(), 1u);
  ASSERT_EQ(nine.parse.size(), 1u);
  EXPECT_TRUE(run("O99999999\nG00 X1.\nM30\n").result.ok());
  // a called program with a bad number alarms when it is reached
  auto called = run("O1\nG00 X1.\nM30\nO00000\nM99\n");
  ASSERT_TRUE(called.result.ok());
  EXPECT_EQ(called.parse.size(), 1u);
}

// A number defined twice in one file or one folder: PS0073 (program number already in use) when
// read and when called; the file run and earlier folders come before later folders.
TEST(Limits, AProgramNumberDefinedTwiceIsPS0073) {
  auto twice = run("O1000\nM98 P1234\nM30\nO1234\nG00 X1.\nM99\nO1234\nG00 X2.\nM99\n");
  ASSERT_EQ(twice.parse.size(), 1u);
  EXPECT_EQ(twice.parse[0].code, "PS0073");
  EXPECT_EQ(twice.parse[0].span.line, 7u);
  EXPECT_EQ(twice.alarm_code(), "PS0073");
  EXPECT_EQ(twice.alarm_line(), 2u);
  EXPECT_TRUE(twice.motions().empty());

  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "ncurve_limits_twice";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "a.nc") << "O9100\n#100=1\nM99\n";
  std::ofstream(dir / "b.nc") << "O9100\n#100=2\nM99\n";
  auto folder = run("G65 P9100\nM30\n", machine::default_mill(), {}, {}, {dir.string()});
  EXPECT_EQ(folder.alarm_code(), "PS0073");
  fs::remove(dir / "b.nc");
  auto main_first = run("G65 P9100\nM30\nO9100\n#100=3\nM99\n", machine::default_mill(), {}, {}, {dir.string()});
  ASSERT_TRUE(main_first.result.ok());
  EXPECT_EQ(main_first.var(100), 3.0);
  fs::remove_all(dir);
}

// No.3403#6 AD2 = 0 (factory): an address given twice counts once, the last (NC2005 says so);
// AD2 = 1: PS5074. G codes of one group likewise.
TEST(Limits, AnAddressTwiceInABlock) {
  auto last = run("G00 X1. X2.\nM30\n");
  ASSERT_TRUE(last.result.ok());
  ASSERT_EQ(last.motions().size(), 1u);
  EXPECT_NEAR(last.motions()[0].end[0], 2.0, 1e-12);
  EXPECT_TRUE(warned(last, "NC2005"));
  auto group = run("G01 G00 X10. F100.\nM30\n");
  ASSERT_EQ(group.motions().size(), 1u);
  EXPECT_EQ(group.motions()[0].kind, machine::MoveKind::rapid);
  EXPECT_TRUE(warned(group, "NC2005"));
  EXPECT_FALSE(warned(run("G90 G54 G00 G17 G21 G40 G49 G80 X1.\nM30\n"), "NC2005"));
  auto loop = run("#1=0\nWHILE [#1 LT 5] DO1\nG00 X1. X2.\n#1=#1+1\nEND1\nM30\n");  // warned once a block
  EXPECT_EQ(std::count_if(loop.result.warnings.begin(), loop.result.warnings.end(),
                          [](const nc::Diagnostic& w) { return w.code == "NC2005"; }),
            1);

  auto strict = machine::default_mill();
  strict.address_duplicate_alarm = true;
  for (const char* block : {"G00 X1. X2.", "G01 G00 X10. F100.", "G90 G91 X1.", "G17 G18 X1.", "F100. F200. G01 X1.",
                            "M03 M08"}) {
    SCOPED_TRACE(block);
    auto r = run(std::string(block) + "\nM30\n", strict);
    EXPECT_EQ(r.alarm_code(), "PS5074");
    EXPECT_TRUE(r.motions().empty());
  }
  // argument specification II repeats I, J, K in a macro call
  auto args = run("G65 P9100 I1. J2. I3. J4.\nM30\n", strict, {},
                  {{"O9100.nc", "O9100\n#100=#4+#5+#7+#8\nM99\n"}});
  ASSERT_TRUE(args.result.ok()) << nc::format(*args.result.alarm);
  EXPECT_EQ(args.var(100), 10.0);
}

// Two G codes of one group in a block, named with the group of the control's G code list: the
// lathe's (0i-F / 30i-B, systems A, B, C) differs from the machining center's.
TEST(Limits, GCodesOfOneGroupFollowTheControlsTable) {
  auto lathe = [](char system) {
    auto p = machine::default_lathe();
    p.gcode_system = system;
    return p;
  };
  struct Case {
    machine::MachineProfile profile;
    const char* block;
    const char* names;  // the two codes and their group, as the warning gives them
  };
  const Case cases[] = {
      {lathe('A'), "G17 G18", "G17 and G18 of group 16"},
      {lathe('B'), "G18 G19", "G18 and G19 of group 16"},
      {lathe('A'), "G96 G97 S500", "G96 and G97 of group 02"},
      {lathe('C'), "G97 G96 S100", "G97 and G96 of group 02"},
      {lathe('A'), "G90 G00 X20. Z1.", "G90 and G00 of group 01"},
      {lathe('A'), "G92 G00 X20. Z1.", "G92 and G00 of group 01"},
      {lathe('A'), "G94 G00 X20. Z1.", "G94 and G00 of group 01"},
      {lathe('A'), "G98 G99", "G98 and G99 of group 05"},
      {lathe('A'), "G26 G25", "G26 and G25 of group 08"},
      {lathe('A'), "G22 G23", "G22 and G23 of group 09"},
      {lathe('A'), "G83 G80", "G83 and G80 of group 10"},
      {lathe('B'), "G98 G99", "G98 and G99 of group 11"},
      {lathe('C'), "G98 G99", "G98 and G99 of group 11"},
      {lathe('A'), "G61 G64", "G61 and G64 of group 15"},
      {lathe('A'), "G12.1 G13.1", "G12.1 and G13.1 of group 21"},
      {lathe('C'), "G70 G71", "G70 and G71 of group 06"},
      {machine::default_mill(), "G12.1 G13.1", "G12.1 and G13.1 of group 21"},
      {machine::default_mill(), "G17 G18", "G17 and G18 of group 02"},
      {machine::default_mill(), "G96 G97 S500", "G96 and G97 of group 13"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.block);
    auto r = run(std::string(c.block) + "\nM30\n", c.profile);
    const auto w = std::find_if(r.result.warnings.begin(), r.result.warnings.end(),
                                [](const nc::Diagnostic& d) { return d.code == "NC2005"; });
    ASSERT_NE(w, r.result.warnings.end());
    EXPECT_NE(w->message.find(c.names), std::string::npos) << w->message;
    auto strict = c.profile;
    strict.address_duplicate_alarm = true;
    auto s = run(std::string(c.block) + "\nM30\n", strict);
    EXPECT_EQ(s.alarm_code(), "PS5074");
    if (s.result.alarm) EXPECT_NE(s.result.alarm->message.find(c.names), std::string::npos) << s.result.alarm->message;
  }
  // different groups on a lathe: G18 (16) with G96 (02), G00 (01) with G99 (05) on system A
  EXPECT_FALSE(warned(run("G18 G96 S100\nM30\n", lathe('A')), "NC2005"));
  EXPECT_FALSE(warned(run("G00 G99 X20. Z1.\nM30\n", lathe('A')), "NC2005"));
  EXPECT_FALSE(warned(run("G90 G94 G00 X20. Z1.\nM30\n", lathe('B')), "NC2005"));  // 03, 05, 01
}

// One M code a block (No.3404#7 M3B = 0): the last one counts; M3B = 1 takes up to three.
TEST(Limits, MCodesInOneBlockFollowM3B) {
  auto one = run("M03 M08\nM30\n");
  ASSERT_EQ(of_kind(one, machine::MoveKind::coolant).size(), 1u);
  EXPECT_TRUE(of_kind(one, machine::MoveKind::spindle).empty());
  EXPECT_TRUE(warned(one, "NC2005"));
  auto p = machine::default_mill();
  p.multiple_m_codes = true;
  auto three = run("M03 M08 M19\nM30\n", p);
  EXPECT_EQ(of_kind(three, machine::MoveKind::spindle).size(), 2u);
  EXPECT_EQ(of_kind(three, machine::MoveKind::coolant).size(), 1u);
  EXPECT_FALSE(warned(three, "NC2005"));
  auto four = run("M03 M08 M19 M09\nM30\n", p);  // the first drops: M08 M19 M09
  EXPECT_EQ(of_kind(four, machine::MoveKind::spindle).size(), 1u);
  EXPECT_EQ(of_kind(four, machine::MoveKind::coolant).size(), 2u);
  EXPECT_TRUE(warned(four, "NC2005"));
}

// --max-steps counts expression operations with blocks: a statement of 900 operations in an
// endless loop stops after 200000000 / ~900 rounds, not 200 million.
TEST(Limits, MaxStepsCountsExpressionWork) {
  std::string sum = "#1*2";
  for (int i = 1; i < 300; ++i) sum += "+#1*2";  // 300 products, 299 sums: 300*3 + 299 = 1199 operations
  machine::RunOptions o;
  o.max_steps = 1'200'000;
  auto r = run("#1=1\nWHILE [1 EQ 1] DO1\n#2=" + sum + "\nEND1\nM30\n", machine::default_mill(), o);
  EXPECT_EQ(r.alarm_code(), "NC9000");
  EXPECT_NE(r.result.alarm->message.find("--max-steps"), std::string::npos);
  // a round: the WHILE (3 blocks: WHILE, #2=, END; operations 3 + 1199) about 1205 steps
  EXPECT_LT(r.result.stats.blocks, 3 * 1'200'000u / 1000);
  EXPECT_GT(r.result.stats.blocks, 3 * 1'200'000u / 1300);
}

TEST(Limits, MaxSecondsStopsARunaway) {
  machine::RunOptions o;
  o.max_steps = std::numeric_limits<std::uint64_t>::max();
  o.max_seconds = 0.2;
  auto r = run("WHILE [1 EQ 1] DO1\n#1=#1+1\nEND1\nM30\n", machine::default_mill(), o);
  EXPECT_EQ(r.alarm_code(), "NC9000");
  EXPECT_NE(r.result.alarm->message.find("--max-seconds"), std::string::npos);
  EXPECT_EQ(r.alarm_line(), 3u);
}

// A canned cycle's moves count as steps: one G83 block of 10^12 pecks (Q of one increment into a
// depth of 1000 km... 10^9 pecks a hole, K1000 holes) stops at the step bound at once, on its line.
TEST(Limits, MaxStepsCountsTheMovesOfACycle) {
  machine::RunOptions o;
  o.max_steps = 1000;
  o.max_seconds = 0;
  auto r = run("G00 X0 Y0 Z10.\nG91 G83 X1. Z-1000000. R-5. Q0.001 K1000 F100.\nM30\n", machine::default_mill(), o);
  ASSERT_EQ(r.alarm_code(), "NC9000");
  EXPECT_NE(r.result.alarm->message.find("--max-steps"), std::string::npos);
  EXPECT_NE(r.result.alarm->message.find("makes move after move"), std::string::npos);
  EXPECT_EQ(r.alarm_line(), 2u);
  // a peck is three or four moves; the bound stops it within its thousand steps
  EXPECT_LE(r.result.stats.motions, 1000u);
  EXPECT_GT(r.result.stats.motions, 900u);
}

// A loop of short blocks stopped just after a move is named as the loop, not its moving block,
// whatever step the bound falls on (an earlier cycle's extra moves do not change that).
TEST(Limits, ALoopIsNamedNotItsMovingBlock) {
  for (std::uint64_t steps = 5000; steps < 5012; ++steps) {
    machine::RunOptions o;
    o.max_steps = steps;
    auto r = run("G00 X0 Y0 Z10.\nG91 G81 X1. Z-5. R-2. K3 F100.\nG80 G90\nWHILE [1 EQ 1] DO1\nG01 X1. F1000\n"
                 "END1\nM30\n", machine::default_mill(), o);
    ASSERT_EQ(r.alarm_code(), "NC9000");
    EXPECT_NE(r.result.alarm->message.find("keeps looping through test.nc:6"), std::string::npos)
        << steps << ": " << r.result.alarm->message;
  }
}

TEST(Limits, MaxSecondsStopsACycleOfEndlessPecks) {
  machine::RunOptions o;
  o.max_steps = std::numeric_limits<std::uint64_t>::max();
  o.max_seconds = 0.2;
  machine::ProgramLibrary lib;
  lib.add_text("test.nc", "G00 X0 Y0 Z10.\nG91 G83 X1. Z-1000000. R-5. Q0.001 K1000 F100.\nM30\n", true);
  machine::Interpreter interp(machine::default_mill(), lib, o);
  machine::NullSink sink;  // the moves are not kept: millions are made in the time allowed
  const auto started = std::chrono::steady_clock::now();
  const machine::RunResult r = interp.run(sink);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  ASSERT_TRUE(r.alarm);
  EXPECT_EQ(r.alarm->code, "NC9000");
  EXPECT_NE(r.alarm->message.find("--max-seconds"), std::string::npos);
  EXPECT_LT(took, 20.0);  // not a speed measure: the run ends, where it went on for hours
}
