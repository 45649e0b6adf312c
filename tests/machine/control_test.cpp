// Control flow: GOTO, IF, WHILE/DO/END, runaway programs.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

TEST(Control, WhileLoopsNest) {
  auto r = run(
      "#100=0\n#1=0\nWHILE [#1 LT 3] DO1\n#2=0\nWHILE [#2 LT 4] DO2\n#100=#100+1\n#2=#2+1\nEND2\n#1=#1+1\nEND1\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.var(100), 12.0);
}

TEST(Control, WhileFalseSkipsTheBody) {
  auto r = run("#100=1\nWHILE [#100 GT 5] DO1\n#100=99\nEND1\nM30\n");
  EXPECT_EQ(r.var(100), 1.0);
}

TEST(Control, GotoAndIf) {
  auto r = run(
      "#1=0\nN5 #1=#1+1\nIF [#1 LT 10] GOTO 5\n#100=#1\n#2=20\nGOTO #2\n#100=-1\nN20 IF [#1 EQ 10] THEN #101=1\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 10.0);
  EXPECT_EQ(r.var(101), 1.0);
}

TEST(Control, GotoToAMissingSequenceNumberIsPS0128) {
  auto r = run("G00 X1.\nGOTO 77\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0128");
  EXPECT_EQ(r.alarm_line(), 2u);
  EXPECT_EQ(r.motions().size(), 1u);  // moves before the alarm are kept
}

TEST(Control, GotoIntoALoopIsRefused) {
  auto r = run("GOTO 10\nWHILE [1 EQ 1] DO1\nN10 #1=1\nEND1\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0124");
}

TEST(Control, GotoOutOfALoopIsAllowed) {
  auto r = run("#1=0\nWHILE [1 EQ 1] DO1\n#1=#1+1\nIF [#1 GE 5] GOTO 9\nEND1\nN9 #100=#1\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.var(100), 5.0);
}

TEST(Control, DoWithoutWhileIsAnEndlessLoopStoppedByMaxSteps) {
  machine::RunOptions o;
  o.max_steps = 10000;
  auto r = run("G91\nDO1\nG01 X1. F100.\nEND1\nM30\n", machine::default_mill(), o);
  EXPECT_EQ(r.alarm_code(), "NC9000");
  EXPECT_NE(r.result.alarm->message.find("END 1"), std::string::npos);
  EXPECT_EQ(r.alarm_line(), 4u);
  EXPECT_GT(r.motions().size(), 3000u);
}

TEST(Control, M99InTheMainProgramRepeatsIt) {
  machine::RunOptions o;
  o.max_steps = 50;
  auto r = run("#100=#100+1\nM99\n", machine::default_mill(), o);
  EXPECT_EQ(r.alarm_code(), "NC9000");
  // a round is 5 steps: two blocks and the three operations of #100+1 (#100, 1, +)
  EXPECT_EQ(r.var(100), 10.0);
}

TEST(Control, UnreachedSyntaxErrorsDoNotStopTheRun) {
  auto r = run("GOTO 5\nX#1+1\nN5 M30\n");
  EXPECT_TRUE(r.result.ok());
  ASSERT_EQ(r.parse.size(), 1u);  // but the parser reports it
  EXPECT_EQ(r.parse[0].code, "PS0004");
}

TEST(Control, BlockSkipFollowsTheSwitch) {
  auto off = run("#100=1\n/#100=2\nM30\n");
  EXPECT_EQ(off.var(100), 2.0);
  auto p = machine::default_mill();
  p.block_skip = true;
  auto on = run("#100=1\n/#100=2\nM30\n", p);
  EXPECT_EQ(on.var(100), 1.0);
}

TEST(Control, AlarmFromProgramWithMessage) {
  auto r = run("#1=5\nIF [#1 GT 3] THEN #3000=12 (DEPTH TOO BIG)\nM30\n");
  // IF..THEN with #3000 on the THEN side
  EXPECT_EQ(r.alarm_code(), "MC3012");
  EXPECT_EQ(r.result.alarm->message, "DEPTH TOO BIG");
  EXPECT_EQ(r.alarm_line(), 2u);
}

namespace {
std::vector<std::uint32_t> lines_of(const ncurve::test::Ran& r, const std::string& code) {
  std::vector<std::uint32_t> lines;
  for (const auto& w : r.result.warnings)
    if (w.code == code) lines.push_back(w.span.line);
  return lines;
}
}  // namespace

// A vacant variable in an address word: the control ignores a word whose value is vacant and counts
// a vacant variable as 0 in an expression, with no alarm (NC2072 names the word and the variable).
TEST(VacantWords, AreWarnedWhereTheyChangeTheMove) {
  auto r = run("#1=30.\n#2=20.\n#3=45.\nG00 X0 Y0\nG01 X#11 Y5. F100.\nX[#1*COS[#3]] Y[#12*SIN[#3]]\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(lines_of(r, "NC2072"), (std::vector<std::uint32_t>{5, 6}));
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[1].end[0], 0);  // X#11 ignored: X stays
  EXPECT_NEAR(m[2].end[0], 30 * std::cos(std::numbers::pi / 4), 0.0005);  // to the 0.001 mm increment
  EXPECT_EQ(m[2].end[1], 0);  // #12 counted as 0
  // a G65 bolt circle whose Y reads a vacant variable puts every hole on Y0
  auto bolt = run("G65 P9100 R20. K4\nM30\n",
                  machine::default_mill(), {},
                  {{"O9100.nc", "O9100\n#10=0\nWHILE[#10LT#6]DO1\n#11=#10*360/#6\n"
                                "G81 X[#18*COS[#11]] Y[#18*SIN[#13]] Z-5. R2. F100.\n#10=#10+1\nEND1\nG80\nM99\n"}});
  ASSERT_TRUE(bolt.result.ok());
  EXPECT_FALSE(lines_of(bolt, "NC2072").empty());
}

TEST(VacantWords, OptionalMacroArgumentsAndSetVariablesAreNotWarned) {
  // X#24 Y#25 in a macro called with X only: an argument left out is how a macro makes a word optional
  auto r = run("G00 X0 Y0\nG65 P9101 X10.\nG65 P9101 Y5.\nM30\n", machine::default_mill(), {},
               {{"O9101.nc", "O9101\nG01 X#24 Y#25 F100.\nM99\n"}});
  ASSERT_TRUE(r.result.ok());
  EXPECT_TRUE(lines_of(r, "NC2072").empty());
  // the call block's own arguments may be vacant; and variables that are set give no warning
  auto call = run("#1=5.\nG00 X#1 Y[#1*2]\nG65 P9101 X#30\nM30\n", machine::default_mill(), {},
                  {{"O9101.nc", "O9101\nG01 X#24 Y#25 F100.\nM99\n"}});
  ASSERT_TRUE(call.result.ok());
  EXPECT_TRUE(lines_of(call, "NC2072").empty());
}
