// Subprograms, macro calls, argument specification, modal and custom-code calls, nesting limits.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
// A macro that echoes its locals #1..#33 into #501..#533.
const std::string kEcho =
    "O9100\n#30=1\nWHILE [#30 LE 29] DO1\n#[500+#30]=#[#30]\n#30=#30+1\nEND1\n#531=#31\n#532=#32\n#533=#33\nM99\n";
}  // namespace

TEST(Calls, ArgumentSpecificationI) {
  auto r = run("G65 P9100 A1. B2. C3. I4. J5. K6. D7. E8. F9. H11. M13. Q17. R18. S19. T20. U21. V22. W23. X24. "
               "Y25. Z26.\nM30\n" + kEcho);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  for (int n : {1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 13, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26})
    EXPECT_EQ(r.var(500 + n), n) << "#" << n;
  for (int n : {10, 12, 14, 15, 16}) EXPECT_TRUE(r.vacant(500 + n)) << "#" << n;
}

TEST(Calls, ArgumentSpecificationII) {
  auto r = run("G65 P9100 A1. B2. C3. I4. J5. K6. I7. J8. K9. I10. K12. J14.\nM30\n" + kEcho);
  ASSERT_TRUE(r.result.ok());
  for (int n = 1; n <= 10; ++n) EXPECT_EQ(r.var(500 + n), n) << "#" << n;
  EXPECT_TRUE(r.vacant(511));  // the J of the third group was skipped
  EXPECT_EQ(r.var(512), 12.0);
  EXPECT_EQ(r.var(514), 14.0);  // J after K starts the fourth group: #14
}

TEST(Calls, MixedSpecificationsLaterWordWins) {
  // I J K I: the second I is group 2's I, i.e. #7, which D also names; the later one wins
  auto r = run("G65 P9100 D1. I4. J5. K6. I7.\nM30\n" + kEcho);
  EXPECT_EQ(r.var(507), 7.0);
  auto r2 = run("G65 P9100 I4. J5. K6. I7. D1.\nM30\n" + kEcho);
  EXPECT_EQ(r2.var(507), 1.0);
}

TEST(Calls, ArgumentsWithoutDecimalPointAreIncrements) {
  auto r = run("G65 P9100 X10 Y10. S10 A1\nM30\n" + kEcho);
  EXPECT_DOUBLE_EQ(r.var(524), 0.010);
  EXPECT_DOUBLE_EQ(r.var(525), 10.0);
  EXPECT_DOUBLE_EQ(r.var(519), 10.0);  // S is not a dimension
  EXPECT_DOUBLE_EQ(r.var(501), 0.001);
}

TEST(Calls, LocalsAreFreshPerLevelAndRestoredOnReturn) {
  auto r = run("#1=5\nG65 P9200 A7.\n#100=#1\nM30\nO9200\n#101=#1\n#2=3\nG65 P9201\nM99\nO9201\n#102=#1\n#103=#2\nM99\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.var(100), 5.0);
  EXPECT_EQ(r.var(101), 7.0);
  EXPECT_TRUE(r.vacant(102));
  EXPECT_TRUE(r.vacant(103));
}

TEST(Calls, SubprogramSharesLocalsAndRepeats) {
  auto r = run("#1=0\nM98 P2000 L3\n#100=#1\nM98 P42000\n#101=#1\nM30\nO2000\n#1=#1+1\nM99\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 3.0);
  EXPECT_EQ(r.var(101), 7.0);  // P42000: four times O2000
}

TEST(Calls, M99WithSequenceNumber) {
  auto r = run("M98 P2000\n#100=1\nN50 #101=1\nM30\nO2000\nM99 P50\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_TRUE(r.vacant(100));
  EXPECT_EQ(r.var(101), 1.0);
}

TEST(Calls, MissingProgramIsPS0076) {
  auto r = run("G65 P1234\n");
  EXPECT_EQ(r.alarm_code(), "PS0076");
}

TEST(Calls, MacroNestingLimitByProfile) {
  std::string recursive = "#100=#100+1\nG65 P3000\nM30\nO3000\n#100=#100+1\nG65 P3000\nM99\n";
  auto r = run(recursive);
  EXPECT_EQ(r.alarm_code(), "PS0122");
  EXPECT_EQ(r.var(100), 5.0);  // main + 4 levels on a 0i
  auto p = machine::default_mill();
  p.control = machine::Control::fanuc_30i;
  p.macro_nesting = 5;
  EXPECT_EQ(run(recursive, p).var(100), 6.0);
  auto sub = run("M98 P4000\nO4000\n#100=#100+1\nM98 P4000\nM99\n");
  EXPECT_EQ(sub.alarm_code(), "PS0077");
  EXPECT_EQ(sub.var(100), 10.0);
}

TEST(Calls, ModalCallAfterEachMove) {
  auto r = run("G91 G00 X1.\nG66 P5000 A2.\nG00 X1.\nX1.\n#100=#100\nG67\nX1.\nM30\nO5000\n#100=#100+#1\n#[110+#100]=#5001\nM99\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 4.0);  // two calls
  EXPECT_EQ(r.var(112), 2.0);  // called after the move to X2
  EXPECT_EQ(r.var(114), 3.0);
}

TEST(Calls, CustomGCodeCallsO9010ByParameter) {
  auto p = machine::default_mill();
  p.g_code_macros[0] = 102;
  p.g_code_macros[3] = 120;
  auto r = run("G102 A1. X5.\nG120 B3.\nM30\nO9010\n#100=#1+#24\nM99\nO9013\n#101=#2\nM99\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 6.0);
  EXPECT_EQ(r.var(101), 3.0);
  // without the parameter G102 is just an unknown G code
  EXPECT_EQ(run("G102 A1.\nM30\nO9010\nM99\n").alarm_code(), "PS0010");
}

TEST(Calls, CustomCodeInsideItsOwnMacroIsOrdinary) {
  auto p = machine::default_mill();
  p.m_code_macros[0] = 50;  // M50 calls O9020
  auto r = run("M50 A1.\nM30\nO9020\n#100=#100+#1\nM50\nM99\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 1.0);  // the inner M50 is an ordinary M code, not a second call
}

TEST(Calls, MCodeSubprogramAndTCode) {
  auto p = machine::default_mill();
  p.m_code_subprograms[0] = 60;  // M60 calls O9001
  p.t_code_calls_o9000 = true;
  auto r = run("#1=4\nM60\nT12\nM30\nO9001\n#100=#1\nM99\nO9000\n#101=#149\nM99\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 4.0);  // a subprogram call: same locals
  EXPECT_EQ(r.var(101), 12.0);
}

TEST(Calls, GIsNotAnArgument) {
  EXPECT_EQ(run("G65 P9100 G01 X1.\nM30\n" + kEcho).alarm_code(), "PS0129");
}

TEST(Calls, LibraryFolder) {
  auto p = machine::default_mill();
  p.g_code_macros[0] = 102;
  auto r = ncurve::test::run("G00 X10. Y0.\nG102 X20. Y0. I-10. J0. Q10. A10. F100.\nM30\n", p, {}, {},
                             {NCURVE_SOURCE_DIR "/macros"});
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.motions().size(), 1u + 36u);
}

// A control holds programs by O number: a library file is read whatever its name, if its extension
// is one part programs are kept under (.cnc here); a README beside it is not read.
TEST(Calls, LibraryFilesFoundByTheirNumberWhateverTheirName) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "ncurve_calls_library_names";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "gauge_tool_o1002.cnc") << "%\nO1002 (POCKET)\nG91 G01 X1. F100.\nM99\n%\n";
  std::ofstream(dir / "README.md") << "Only the O1002 subprogram; P1002 calls it.\n";
  auto r = ncurve::test::run("O1001\nM98 P1002 L4\nM30\n", ncurve::test::zero_offset_mill(), {}, {}, {dir.string()});
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  ASSERT_EQ(r.motions().size(), 4u);
  EXPECT_DOUBLE_EQ(r.motions().back().end[0], 4.0);
  fs::remove_all(dir);
}

TEST(Calls, SubprogramInsideAMacroUsesTheMacrosLocals) {
  auto r = run("#1=1.\nG65 P9300 A5.\n#100=#1\nM30\nO9300\nM98 P9301\n#101=#1\nM99\nO9301\n#1=#1*2\nM99\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 1.0);   // main level untouched
  EXPECT_EQ(r.var(101), 10.0);  // the subprogram doubled the macro's #1
}

TEST(Calls, MovesInsideTheModalMacroDoNotCallItAgain) {
  auto r = run("G66 P5100\nG91 G00 X1.\nG67\nM30\nO5100\n#100=#100+1\nG00 Y1.\nM99\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 1.0);
}

// Line ends of every kind and a byte-order mark: CR alone, LF and CRLF end a block; a UTF-8 BOM is
// not part of the first block.
TEST(Calls, LineEndsAndByteOrderMark) {
  for (const char* text : {"\xEF\xBB\xBFG90 G01 X1. F100.\rY2.\rM30\r", "G90 G01 X1. F100.\r\nY2.\r\nM30\r\n",
                           "G90 G01 X1. F100.\nY2.\nM30\n"}) {
    auto r = ncurve::test::run(text);
    ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
    auto ms = r.motions();
    ASSERT_EQ(ms.size(), 2u);
    EXPECT_DOUBLE_EQ(ms[1].end[1], 2.0);
    EXPECT_EQ(ms[1].line, 2u);
  }
}

// M98 Q: the block N(q) of the program being run is called as a subprogram; M99 returns after the
// M98 block; L repeats it. Here the routine after M30 moves X by 10 (G91), called twice then once.
TEST(Calls, M98QCallsASequenceNumberOfThisProgram) {
  auto r = run("O0100\nG90 G00 X0 Y0\nM98 Q500 L2\nG90 G00 Y5.\nM98 Q500\nM30\nN500 G91 G00 X10.\nG90\nM99\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto ms = r.motions();
  ASSERT_EQ(ms.size(), 5u);
  EXPECT_DOUBLE_EQ(ms[1].end[0], 10.0);
  EXPECT_DOUBLE_EQ(ms[2].end[0], 20.0);
  EXPECT_DOUBLE_EQ(ms[3].end[1], 5.0);
  EXPECT_DOUBLE_EQ(ms[4].end[0], 30.0);
  EXPECT_EQ(ms[4].line, 7u);
  auto missing = run("O0100\nM98 Q600\nM30\nN500 M99\n");
  EXPECT_EQ(missing.alarm_code(), "PS0078");
}
