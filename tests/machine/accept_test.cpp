// What controls accept that ncurve must too: programs after the closing '%', the call stack of an
// alarm, library files checked only where they run, hints at the wrong profile, look-ahead modes.
#include <gtest/gtest.h>

#include <sstream>

#include "report/writers.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
std::size_t count_code(const machine::RunResult& r, const std::string& code) {
  std::size_t n = 0;
  for (const auto& w : r.warnings) n += w.code == code;
  return n;
}
const nc::Diagnostic* warning_of(const machine::RunResult& r, const std::string& code) {
  for (const auto& w : r.warnings)
    if (w.code == code) return &w;
  return nullptr;
}
}  // namespace

TEST(Accept, CalledProgramAfterTheClosingPercent) {
  // line 4 is the closing '%'; O2 on line 5 is never read, so M98 P2 finds no program
  auto r = run("O1\nM98 P2\nM30\n%\nO2\nM99\n");
  ASSERT_EQ(r.alarm_code(), "PS0076");
  EXPECT_EQ(r.alarm_line(), 2u);
  const std::string& m = r.result.alarm->message;
  EXPECT_NE(m.find("test.nc at line 5, after the '%' of line 4"), std::string::npos) << m;
  // the same in a library file, and the ISO form of the number
  auto l = run("G65 P9001\nM30\n", machine::default_mill(), {}, {{"lib.nc", "%\n:9000\nM99\n%\n:9001\nM99\n"}});
  ASSERT_EQ(l.alarm_code(), "PS0076");
  EXPECT_NE(l.result.alarm->message.find("lib.nc at line 5, after the '%' of line 4"), std::string::npos);
  // a program before the '%' runs; one nowhere gets the usual message
  auto ok = run("M98 P9000\nM30\n", machine::default_mill(), {}, {{"lib.nc", "%\n:9000\nM99\n%\n"}});
  EXPECT_TRUE(ok.result.ok());
  auto none = run("M98 P7\nM30\n");
  EXPECT_NE(none.result.alarm->message.find("in this file or the --lib folders"), std::string::npos);
}

TEST(Accept, AlarmInACalledProgramNamesTheCallSites) {
  auto r = run("G00 X0\nG65 P9010 A1.\nM30\n", machine::default_mill(), {},
               {{"O9010.nc", "O9010\nM98 P9020\nM99\n"}, {"O9020.nc", "O9020\n#2=#1/0\nM99\n"}});
  ASSERT_EQ(r.alarm_code(), "PS0112");
  const nc::Diagnostic& d = *r.result.alarm;
  EXPECT_EQ(d.span.file->name(), "O9020.nc");
  EXPECT_EQ(d.span.line, 2u);
  ASSERT_EQ(d.called_from.size(), 2u);  // innermost first
  EXPECT_EQ(d.called_from[0].file->name(), "O9010.nc");
  EXPECT_EQ(d.called_from[0].line, 2u);
  EXPECT_EQ(d.called_from[1].file->name(), "test.nc");
  EXPECT_EQ(d.called_from[1].line, 2u);
  const std::string text = nc::format(d);
  EXPECT_NE(text.find("called from O9010.nc:2 (M98 P9020)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("called from test.nc:2 (G65 P9010 A1.)"), std::string::npos) << text;
  // the JSON Lines alarm record carries them
  std::ostringstream out;
  report::JsonlWriter w(out, machine::default_mill());
  w.stopped(d);
  EXPECT_NE(out.str().find(R"("called_from":[{"block":"M98 P9020","file":"O9010.nc","line":2},)"
                           R"({"block":"G65 P9010 A1.","file":"test.nc","line":2}])"),
            std::string::npos)
      << out.str();
  // a modal call (G66) names the moving block that called
  auto g66 = run("G66 P9030\nG00 X5.\nM30\n", machine::default_mill(), {}, {{"O9030.nc", "O9030\n#2=1/0\nM99\n"}});
  ASSERT_FALSE(g66.result.ok());
  ASSERT_EQ(g66.result.alarm->called_from.size(), 1u);
  EXPECT_EQ(g66.result.alarm->called_from[0].line, 2u);
  // an alarm in the main program has none
  auto main = run("#1=1/0\nM30\n");
  EXPECT_TRUE(main.result.alarm->called_from.empty());
  EXPECT_EQ(nc::format(*main.result.alarm).find("called from"), std::string::npos);
}

TEST(Accept, LibrarySyntaxProblemsOnlyWhenReached) {
  const std::map<std::string, std::string> lib = {
      {"O9010.nc", "O9010\nG01 X1.. F100.\nM99\n"},        // broken, line 2
      {"O9011.nc", "O9011\nG01 X1. F100.\nM99\n"},         // fine
      {"O9012.nc", "O9012\nG01 X10 F100.\nY10.\nM99\n"}};  // mixed decimal points
  machine::ProgramLibrary library;
  EXPECT_TRUE(library.add_text("O9010.nc", lib.at("O9010.nc")).empty());  // nothing reported on reading
  auto never = run("M98 P9011\nM30\n", machine::default_mill(), {}, lib);
  EXPECT_TRUE(never.result.ok());
  EXPECT_TRUE(never.result.warnings.empty()) << nc::format(never.result.warnings[0]);
  auto reached = run("M98 P9011\nM98 P9010\nM30\n", machine::default_mill(), {}, lib);
  ASSERT_EQ(reached.alarm_code(), "PS0007");
  EXPECT_EQ(reached.result.alarm->span.file->name(), "O9010.nc");
  EXPECT_EQ(reached.result.alarm->span.line, 2u);
  ASSERT_EQ(reached.result.alarm->called_from.size(), 1u);
  EXPECT_EQ(reached.result.alarm->called_from[0].line, 2u);
  // the decimal point warning of a library program comes when it is called, once
  auto mixed = run("M98 P9012\nM98 P9012\nM30\n", machine::default_mill(), {}, lib);
  EXPECT_TRUE(mixed.result.ok());
  EXPECT_EQ(count_code(mixed.result, "NC2001"), 1u);
  // the main file's problems are reported as before, all of them
  auto main = run("G00 X1.\nM30\nO5\nX1..\nM99\n");
  EXPECT_EQ(main.parse.size(), 1u);
}

TEST(Accept, LatheProgramOnAMillGetsOneWarning) {
  const std::string lathe = "O1\nG50 S2000\nG99\nT0101\nG96 S200 M03\nG00 X50. Z2.\nG01 Z-20. F0.2\nM30\n";
  auto r = run(lathe);
  ASSERT_EQ(count_code(r.result, "NC2030"), 1u);
  const nc::Diagnostic* w = warning_of(r.result, "NC2030");
  EXPECT_EQ(w->span.line, 2u);  // the first sign
  EXPECT_NE(w->message.find("(T0101 style) at line 4"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("G50 S (spindle speed clamp) at line 2"), std::string::npos);
  EXPECT_NE(w->message.find("feed below 1 (mm per revolution) at line 7"), std::string::npos);
  EXPECT_NE(w->message.find("--machine fanuc-lathe"), std::string::npos);
  // the same program on a lathe: nothing to say
  EXPECT_EQ(count_code(run(lathe, machine::default_lathe()).result, "NC2030"), 0u);
  // one sign alone is not enough: a mill may use G96, or G99 in a canned cycle with a slow feed
  EXPECT_EQ(count_code(run("G96 S100\nG00 X1.\nM30\n").result, "NC2030"), 0u);
  const std::string mill = "O2\nT01 M06\nG90 G54 G00 X0 Y0\nG43 H1 Z50.\nS1000 M03\nG99 G81 X10. Y10. Z-5. R2. F80.\n"
                           "X20.\nG80\nT12 M06\nG01 Z-1. F0.5\nM30\n";
  EXPECT_EQ(count_code(run(mill).result, "NC2030"), 0u);
  // a T0101 in a macro call is an argument
  EXPECT_EQ(count_code(run("G65 P9 T0101\nG50 S100\nM30\nO9\nM99\n").result, "NC2030"), 0u);
}

TEST(Accept, SystemBProgramOnASystemALatheGetsOneWarning) {
  auto r = run("O1\nG21 G95\nG91 G00 X-2. Z-2.\nG90 G00 X20. Z1.\nM30\n", machine::default_lathe());
  ASSERT_EQ(count_code(r.result, "NC2031"), 1u);
  const nc::Diagnostic* w = warning_of(r.result, "NC2031");
  EXPECT_EQ(w->span.line, 2u);
  EXPECT_NE(w->message.find("G95 (feed per revolution in system B) at line 2"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("G90/G91 as absolute/incremental mode at line 3"), std::string::npos);
  EXPECT_NE(w->message.find("gcode_system = \"B\""), std::string::npos);
  // G77/G78/G79 alone say system B
  EXPECT_EQ(count_code(run("G00 X50. Z2.\nG77 X45. Z-20. F0.2\nM30\n", machine::default_lathe()).result, "NC2031"), 1u);
  // a system-A program: G90 with axes is the turning cycle, U/W are increments
  auto a = run("G99 G00 X50. Z2.\nG90 X45. Z-20. F0.2\nG00 U2. W1.\nM30\n", machine::default_lathe());
  EXPECT_EQ(count_code(a.result, "NC2031"), 0u);
  // on a system-B lathe nothing is said
  auto b = machine::default_lathe();
  b.gcode_system = 'B';
  EXPECT_EQ(count_code(run("G91 G00 X-2. Z-2.\nG95\nM30\n", b).result, "NC2031"), 0u);
}

TEST(Accept, LookAheadModesAreRecordedOnEachMove) {
  auto r = run("G01 X1. F100.\nG05.1 Q0\nX2.\nG08 P1\nX3.\nG08 P0\nX4.\nG05 P10000\nX5.\nG05 P0\nX6.\nG05.1 Q1\n"
               "X7.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 7u);
  const bool expected[] = {true, false, true, false, true, false, true};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(m[i].lookahead, expected[i]) << "move " << i;
  // the profile says which mode power-on gives
  auto p = machine::default_mill();
  p.motion.look_ahead_at_power_on = false;
  auto off = run("G01 X1. F100.\nG05.1 Q1\nX2.\nM30\n", p);
  ASSERT_EQ(off.motions().size(), 2u);
  EXPECT_FALSE(off.motions()[0].lookahead);
  EXPECT_TRUE(off.motions()[1].lookahead);
  // JSON Lines shows the mode of each motion
  std::ostringstream out;
  report::JsonlWriter w(out, machine::default_mill());
  w.on_move(r.motions()[1]);
  EXPECT_NE(out.str().find(R"("lookahead":false)"), std::string::npos) << out.str();
}

TEST(Accept, OtherHighSpeedFormsAlarm) {
  EXPECT_EQ(run("G05.1 Q2 X0 Y0 Z0\nM30\n").alarm_code(), "NC9001");  // smooth interpolation changes the path
  EXPECT_EQ(run("G05.1 Q3\nM30\n").alarm_code(), "NC9001");           // nano smoothing
  EXPECT_EQ(run("G05.1\nM30\n").alarm_code(), "NC9002");
  EXPECT_EQ(run("G08 P2\nM30\n").alarm_code(), "PS0109");  // FORMAT ERROR IN G08
  EXPECT_EQ(run("G08\nM30\n").alarm_code(), "PS0109");
  EXPECT_EQ(run("G05 P3\nM30\n").alarm_code(), "NC9001");
  EXPECT_EQ(run("G05\nM30\n").alarm_code(), "NC9001");
}

TEST(Accept, G61_1OnlyWhereTheProfileTakesIt) {
  auto fanuc = run("G61.1\nM30\n");
  ASSERT_EQ(fanuc.alarm_code(), "PS0010");
  EXPECT_NE(fanuc.result.alarm->message.find("G05.1 Q1"), std::string::npos);
  auto p = machine::default_mill();
  p.motion.g61_1 = true;
  auto r = run("G05.1 Q0\nG61.1\nG01 X1. F100.\n#100=#4015\nG64\nX2.\n#101=#4015\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  ASSERT_EQ(r.motions().size(), 2u);
  EXPECT_TRUE(r.motions()[0].lookahead);   // G61.1 on
  EXPECT_FALSE(r.motions()[1].lookahead);  // G64 ends it: back to G05.1 Q0's mode
  EXPECT_DOUBLE_EQ(r.var(100), 61.1);      // group 15
  EXPECT_DOUBLE_EQ(r.var(101), 64);
}

TEST(Accept, ProfileKeysOfTheLookAheadMode) {
  auto p = machine::parse_profile("[motion]\nlook_ahead_at_power_on = false\ng61_1 = true\n", "p.toml");
  EXPECT_FALSE(p.motion.look_ahead_at_power_on);
  EXPECT_TRUE(p.motion.g61_1);
  EXPECT_TRUE(machine::default_mill().motion.look_ahead_at_power_on);
  EXPECT_FALSE(machine::default_mill().motion.g61_1);
}
