// Motion and modes: decimal point rule, units, coordinates, arcs against closed-form geometry, lathe.
#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <numbers>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;
using machine::MoveKind;

TEST(Motion, DecimalPointRule) {
  auto r = run("G00 X10 Y10. Z.5\nM30\n");
  ASSERT_TRUE(r.result.ok());
  auto m = r.motions().at(0);
  EXPECT_DOUBLE_EQ(m.end[0], 0.010);  // ten least input increments
  EXPECT_DOUBLE_EQ(m.end[1], 10.0);
  EXPECT_DOUBLE_EQ(m.end[2], 0.5);
  bool warned = false;
  for (const auto& w : r.result.warnings) warned |= w.code == "NC2001";
  EXPECT_TRUE(warned);
  auto calc = run("G00 X10 Y10.\nM30\n", ncurve::test::calculator_mill());
  EXPECT_DOUBLE_EQ(calc.motions().at(0).end[0], 10.0);
  auto isc = machine::default_mill();
  isc.increment = 0.0001;
  EXPECT_DOUBLE_EQ(run("G00 X10\nM30\n", isc).motions().at(0).end[0], 0.001);
  // M98's Q is a sequence number, no dimension: a program of decimal points with it is not mixed
  auto seq = run("G00 X10.\nM98 Q102\nM30\nN102 G00 Y5.\nM99\n");
  ASSERT_TRUE(seq.result.ok()) << seq.result.alarm->message;
  for (const auto& w : seq.result.warnings) EXPECT_NE(w.code, "NC2001") << nc::format(w);
  // a lathe's G73 R is the number of divisions (a count, not a length): R3 beside decimal points is not mixed
  auto g73 = run("G00 X60. Z2.\nG73 U5. W0.5 R3\nG73 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X40.\nG01 Z-20.\n"
                 "N20 X60.\nM30\n", machine::default_lathe());
  ASSERT_TRUE(g73.result.ok()) << g73.result.alarm->message;
  for (const auto& w : g73.result.warnings) EXPECT_NE(w.code, "NC2001") << nc::format(w);
}

// The warning quotes the number as the control shows it (118 increments of 0.001 mm = 0.118) and
// calls a macro call's word an argument, not an axis word in mm.
TEST(Motion, DecimalPointWarningShowsTheNumberAsTheControlDoes) {
  auto r = run("G00 X1.5 Y118\nM30\n");
  ASSERT_EQ(r.result.warnings.size(), 1u);
  EXPECT_NE(r.result.warnings[0].message.find("Y118 is read as 0.118 mm (118 least input increments"),
            std::string::npos) << r.result.warnings[0].message;
  auto call = run("G65 P9000 B30\nG01 X1.5 F100.\nM30\n", machine::default_mill(), {}, {{"O9000.nc", "O9000\nM99\n"}});
  ASSERT_EQ(call.result.warnings.size(), 1u);
  EXPECT_NE(call.result.warnings[0].message.find("argument B30 of a macro call is read as 0.03 (30 least input"),
            std::string::npos) << call.result.warnings[0].message;
  EXPECT_EQ(call.result.warnings[0].message.find(" mm "), std::string::npos);
}

// An integer G code the control lacks: without any of O9010..O9019 the hint gives the mapping
// No.6050..6059 -> O9010..O9019 with the first free parameter.
TEST(Motion, UnknownGCodeNamesTheCustomGCodeParameter) {
  auto r = run("G102 X10. Y0. F100.\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0010");
  EXPECT_NE(r.result.alarm->message.find("parameters No.6050..6059 make G codes that call O9010..O9019, and none of "
                                         "these programs is in the file or a --lib folder: --param 6050=102 makes "
                                         "G102 call O9010"),
            std::string::npos)
      << r.result.alarm->message;
  auto p = machine::default_mill();
  p.g_code_macros[0] = 103;  // No.6050 taken: the next free one is named
  auto taken = run("G102 X10. Y0. F100.\nM30\n", p);
  EXPECT_NE(taken.result.alarm->message.find("--param 6051=102 makes G102 call O9011"), std::string::npos)
      << taken.result.alarm->message;
  auto fraction = run("G102.5 X10.\nM30\n");
  EXPECT_EQ(fraction.result.alarm->message.find("--param"), std::string::npos);
}

// O9011 in the file is called through No.6051 (No.6050 calls O9010, which is not there): the hint
// names No.6051, and following it runs O9011.
TEST(Motion, UnknownGCodeNamesTheParameterOfTheProgramThatExists) {
  const std::string macro = "O9011\nG01 X#24 Y#25 F100.\nM99\n";
  auto r = run("O0001\nG103 X10. Y5.\nM30\n" + macro);
  ASSERT_EQ(r.alarm_code(), "PS0010");
  EXPECT_NE(r.result.alarm->message.find("calling O9011, set parameter No.6051 = 103: --param 6051=103)"),
            std::string::npos)
      << r.result.alarm->message;
  auto p = machine::default_mill();
  p.g_code_macros[1] = 103;
  auto followed = run("O0001\nG103 X10. Y5.\nM30\n" + macro, p);
  ASSERT_TRUE(followed.result.ok()) << followed.result.alarm->message;
  ASSERT_EQ(followed.motions().size(), 1u);
  EXPECT_DOUBLE_EQ(followed.motions()[0].end[0], 10.0);
  EXPECT_DOUBLE_EQ(followed.motions()[0].end[1], 5.0);
  // several present (a library like macros/): the one ncurve's macros give G103, O9011, is named
  auto lib = run("G103 X10.\nM30\n", machine::default_mill(), {},
                 {{"O9010.nc", "O9010\nM99\n"}, {"O9011.nc", "O9011\nM99\n"}, {"O9012.nc", "O9012\nM99\n"}});
  EXPECT_NE(lib.result.alarm->message.find("calling O9011, set parameter No.6051 = 103: --param 6051=103; "
                                           "No.6050..6059 call O9010..O9019, and O9010, O9012 are here too)"),
            std::string::npos)
      << lib.result.alarm->message;
}

TEST(Motion, VariableValuesAreMillimetresAndRoundToTheIncrement) {
  auto r = run("#1=10\n#2=1.23456\nG00 X#1 Y#2\nM30\n");
  auto m = r.motions().at(0);
  EXPECT_DOUBLE_EQ(m.end[0], 10.0);
  EXPECT_NEAR(m.end[1], 1.235, 1e-12);
}

// A literal rounds to the least input increment (IS-B: 0.001 mm, 0.0001 inch) whatever its decimals;
// one already on the grid is exactly the decimal written, and -0. is zero.
TEST(Motion, LiteralsRoundToTheIncrement) {
  auto r = run("G00 X1.2346 Y-7.0004 Z-0.\nX0.125 Y-12345.678 Z1.23449\nG20 X1.23456 Y0.0001 Z-2.5\nM30\n");
  ASSERT_TRUE(r.result.ok()) << r.result.alarm->message;
  auto m = r.motions();
  EXPECT_EQ(m.at(0).end[0], 1235 / 1000.0);
  EXPECT_EQ(m.at(0).end[1], -7000 / 1000.0);
  EXPECT_EQ(m.at(0).end[2], 0.0);
  EXPECT_FALSE(std::signbit(m.at(0).end[2]));
  EXPECT_EQ(m.at(1).end[0], 0.125);
  EXPECT_EQ(m.at(1).end[1], -12345678 / 1000.0);
  EXPECT_EQ(m.at(1).end[2], 1234 / 1000.0);
  EXPECT_EQ(m.at(2).end[0], 12346 / 10000.0 * 25.4);
  EXPECT_EQ(m.at(2).end[1], 1 / 10000.0 * 25.4);
  EXPECT_EQ(m.at(2).end[2], -25000 / 10000.0 * 25.4);
  auto isc = machine::default_mill();  // IS-C: 0.0001 mm
  isc.increment = 0.0001;
  auto c = run("G00 X1.23456 Y1.2345\nM30\n", isc);
  EXPECT_EQ(c.motions().at(0).end[0], 12346 / 10000.0);
  EXPECT_EQ(c.motions().at(0).end[1], 12345 / 10000.0);
}

TEST(Motion, VacantWordIsOmittedButBracketedArithmeticIsNot) {
  auto r = run("G00 X5. Y5.\nG00 X#1 Y[#1+10.]\nM30\n");
  auto m = r.motions().at(1);
  EXPECT_DOUBLE_EQ(m.end[0], 5.0);
  EXPECT_DOUBLE_EQ(m.end[1], 10.0);
}

TEST(Motion, IntegerAddressesRound) {
  auto r = run("#1=3.5\nM#1\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.moves.at(0).kind, MoveKind::spindle);
  EXPECT_EQ(r.moves.at(0).code, 4);
  EXPECT_EQ(run("M3.\nM30\n").alarm_code(), "PS0007");
}

TEST(Motion, IncrementalAndFeed) {
  auto r = run("G91 G01 X10. Y5. F200.\nX-10.\nM30\n");
  ASSERT_TRUE(r.result.ok());
  auto ms = r.motions();
  EXPECT_DOUBLE_EQ(ms[1].end[0], 0.0);
  EXPECT_DOUBLE_EQ(ms[1].end[1], 5.0);
  EXPECT_DOUBLE_EQ(ms[0].feed, 200.0);
  EXPECT_NEAR(ms[0].seconds, std::hypot(10, 5) / 200 * 60, 1e-12);
}

TEST(Motion, MinusSignOnFeedOrDwellIsPS0006) {
  // PS0006 ILLEGAL USE OF MINUS SIGN: "a minus sign was specified at an NC instruction word ... where
  // no minus sign may be specified"; PS0011 is a feed of zero
  EXPECT_EQ(run("#1=-100.\nG01 X1. F#1\nM30\n").alarm_code(), "PS0006");
  EXPECT_EQ(run("G04 P-100\nM30\n").alarm_code(), "PS0006");
  EXPECT_EQ(run("G04 X-1.\nM30\n").alarm_code(), "PS0006");
  EXPECT_EQ(run("G00 Z10.\nG82 X5. Z-10. R2. P-100 F100.\nM30\n").alarm_code(), "PS0006");
  EXPECT_EQ(run("G00 Z10.\nG81 X5. Z-10. R2. K-1 F100.\nM30\n").alarm_code(), "PS0006");
  EXPECT_EQ(run("G00 Z10.\nG81 X5. Z-10. R2. K10000 F100.\nM30\n").alarm_code(), "PS0003");
}

TEST(Motion, FeedZeroIsPS0011AtTheBlock) {
  auto r = run("G00 X1.\nG01 X2.\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0011");
  EXPECT_EQ(r.alarm_line(), 2u);
  EXPECT_EQ(r.motions().size(), 1u);
}

TEST(Motion, ArcWithRadiusMatchesClosedForm) {
  // quarter circle from (10,0) to (0,10) about the origin, CCW, R10
  auto r = run("G00 X10. Y0.\nG03 X0. Y10. R10. F100.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto a = r.motions().at(1);
  EXPECT_EQ(a.kind, MoveKind::arc);
  EXPECT_NEAR(a.center[0], 0, 1e-12);
  EXPECT_NEAR(a.center[1], 0, 1e-12);
  EXPECT_NEAR(a.sweep, std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(a.length, 10 * std::numbers::pi / 2, 1e-9);
  // negative R: the long way round, centre on the other side
  auto big = run("G00 X10. Y0.\nG03 X0. Y10. R-10. F100.\nM30\n").motions().at(1);
  EXPECT_NEAR(big.center[0], 10, 1e-12);
  EXPECT_NEAR(big.center[1], 10, 1e-12);
  EXPECT_NEAR(big.sweep, 1.5 * std::numbers::pi, 1e-12);
  auto cw = run("G00 X10. Y0.\nG02 X0. Y10. R10. F100.\nM30\n").motions().at(1);
  EXPECT_NEAR(cw.center[0], 10, 1e-12);
  EXPECT_NEAR(cw.center[1], 10, 1e-12);
  EXPECT_NEAR(cw.sweep, -std::numbers::pi / 2, 1e-12);
}

TEST(Motion, FullCircleAndHelix) {
  auto r = run("G00 X10. Y0. Z0.\nG17 G02 I-10. F100.\nG03 X10. Y0. Z-3. I-10. J0.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto full = r.motions().at(1);
  EXPECT_NEAR(full.sweep, -2 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(full.length, 20 * std::numbers::pi, 1e-9);
  auto helix = r.motions().at(2);
  EXPECT_NEAR(helix.length, std::hypot(20 * std::numbers::pi, 3.0), 1e-9);
  EXPECT_DOUBLE_EQ(helix.end[2], -3.0);
  // extents include the arc's quadrant points
  EXPECT_NEAR(r.result.stats.min[0], -10, 1e-9);
  EXPECT_NEAR(r.result.stats.max[1], 10, 1e-9);
}

TEST(Motion, ArcPlanesG18G19) {
  auto zx = run("G18 G00 X0. Z10.\nG03 X10. Z0. R10. F100.\nM30\n").motions().at(1);
  // G18: CCW seen from +Y in the (Z, X) plane: from Z10 to X10 about the origin is +90 degrees
  EXPECT_NEAR(zx.center[0], 0, 1e-12);
  EXPECT_NEAR(zx.center[2], 0, 1e-12);
  EXPECT_NEAR(zx.sweep, std::numbers::pi / 2, 1e-12);
  auto yz = run("G19 G00 Y10. Z0.\nG02 Y0. Z-10. J-10. K0. F100.\nM30\n");
  ASSERT_TRUE(yz.result.ok()) << nc::format(*yz.result.alarm);
  EXPECT_NEAR(yz.motions().at(1).sweep, -std::numbers::pi / 2, 1e-12);
}

TEST(Motion, ArcErrors) {
  EXPECT_EQ(run("G00 X10. Y0.\nG03 X0. Y10.5 I-10. F100.\nM30\n").alarm_code(), "PS0020");
  EXPECT_EQ(run("G00 X10. Y0.\nG03 X-30. Y0. R0 F100.\nM30\n").alarm_code(), "PS0023");
  auto cir = machine::default_mill();
  machine::set_parameter(cir, "3403#5", 1);  // CIR = 1: an arc without R or I J K is PS0022
  EXPECT_EQ(run("G00 X10. Y0.\nG03 X0. Y10. F100.\nM30\n", cir).alarm_code(), "PS0022");
  // within No.3410 the arc is accepted
  EXPECT_TRUE(run("G00 X10. Y0.\nG03 X0. Y10.015 I-10. F100.\nM30\n").result.ok());
}

// No.3403#5 CIR = 0 (factory): G02/G03 without R or I J K is a line to the end point, at F.
TEST(Motion, ArcWithoutCentreIsALine) {
  auto r = run("G00 X10. Y0.\nG03 X0. Y10. F100.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  const auto m = r.motions().back();
  EXPECT_EQ(m.kind, machine::MoveKind::line);
  EXPECT_NEAR(m.end[0], 0, 1e-12);
  EXPECT_NEAR(m.end[1], 10, 1e-12);
  EXPECT_DOUBLE_EQ(m.feed, 100);
  ASSERT_EQ(r.result.warnings.size(), 1u);
  EXPECT_EQ(r.result.warnings[0].code, "NC2015");
}

// R shorter than half the chord: no circle of radius R reaches the end point; the centre falls on
// the chord's midpoint (the square root of R^2 - (d/2)^2 taken as 0), a half circle of radius d/2.
// From (10, 0) to (-30, 0) with R10: centre (-10, 0), radius 20, counterclockwise through (-10, 20).
TEST(Motion, ArcRadiusShorterThanHalfTheChordIsAHalfCircle) {
  auto r = run("G00 X10. Y0.\nG03 X-30. Y0. R10. F100.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  const auto m = r.motions().back();
  EXPECT_EQ(m.kind, machine::MoveKind::arc);
  EXPECT_NEAR(m.center[0], -10, 1e-9);
  EXPECT_NEAR(m.center[1], 0, 1e-9);
  EXPECT_NEAR(m.sweep, std::numbers::pi, 1e-9);
  EXPECT_NEAR(r.result.stats.max[1], 20, 1e-9);
  ASSERT_EQ(r.result.warnings.size(), 1u);
  EXPECT_EQ(r.result.warnings[0].code, "NC2016");
}

TEST(Motion, InchProgramsConvertAtTheEdge) {
  auto r = run("G20 G00 X1. Y1\nG01 X2. F10.\nM30\n");
  auto ms = r.motions();
  EXPECT_DOUBLE_EQ(ms[0].end[0], 25.4);
  EXPECT_NEAR(ms[0].end[1], 0.0001 * 25.4, 1e-12);  // IS-B inch increment
  EXPECT_DOUBLE_EQ(ms[1].feed, 254.0);
  auto v = run("G20 G00 X1.\n#100=#5001\nM30\n");
  EXPECT_DOUBLE_EQ(v.var(100), 1.0);  // position variables in program units
}

TEST(Motion, WorkOffsetsAndPositionVariables) {
  auto p = test::zero_offset_mill();
  p.work_offsets[2] = {-100, -50, 0, 0, 0, 0};  // G55
  auto r = run("G55 G00 X10. Y5.\n#100=#5001\n#101=#5021\n#102=#5222\n#103=#5241\nG54\n#104=#5001\n#5221=1.\n#105=#5001\nM30\n",
               p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 10.0);
  EXPECT_DOUBLE_EQ(r.var(101), -90.0);  // machine position
  EXPECT_DOUBLE_EQ(r.var(102), 0.0);    // G54 Y
  EXPECT_DOUBLE_EQ(r.var(103), -100.0);  // G55 X
  EXPECT_DOUBLE_EQ(r.var(104), -90.0);  // same machine point in G54
  EXPECT_DOUBLE_EQ(r.var(105), -91.0);  // after shifting G54 X by 1 mm
}

TEST(Motion, G92G52AndG10) {
  auto r = run("G00 X10.\nG92 X0.\n#100=#5001\nG00 X5.\n#101=#5021\nG52 X100.\n#102=#5001\nG52 X0.\n"
               "G10 L2 P1 X7.\n#103=#5221\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 0.0);
  EXPECT_DOUBLE_EQ(r.var(101), 15.0);
  EXPECT_DOUBLE_EQ(r.var(102), -95.0);
  EXPECT_DOUBLE_EQ(r.var(103), 7.0);
}

TEST(Motion, ReferenceReturnThroughIntermediatePoint) {
  auto p = machine::default_mill();
  p.reference_points[0] = {0, 0, 0, 0, 0, 0};
  p.work_offsets[1] = {-200, -100, -50, 0, 0, 0};
  auto r = run("G54 G00 X10. Y10. Z10.\nG91 G28 Z5.\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  auto ms = r.motions();
  ASSERT_EQ(ms.size(), 3u);
  EXPECT_DOUBLE_EQ(ms[1].end[2], 15.0);  // intermediate point
  EXPECT_DOUBLE_EQ(ms[2].end[2], 50.0);  // machine zero in G54
  EXPECT_DOUBLE_EQ(ms[2].end[0], 10.0);  // X untouched
}

TEST(Motion, ToolLengthAndOffsetsVariables) {
  auto p = test::zero_offset_mill();
  p.tool_offsets[3].geometry = 120.5;
  auto r = run("#100=#2003\n#2004=7.\n#101=#10004\nG43 H3 G00 Z10.\n#102=#5023\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 120.5);
  EXPECT_DOUBLE_EQ(r.var(101), 7.0);
  EXPECT_DOUBLE_EQ(r.var(102), 130.5);
}

TEST(Motion, ModalInformationVariables) {
  auto r = run("G91 G02 X0 I1. F100.\n#100=#4001\n#101=#4003\n#102=#4109\n#103=#4014\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.var(100), 2.0);
  EXPECT_EQ(r.var(101), 91.0);
  EXPECT_EQ(r.var(102), 100.0);
  EXPECT_EQ(r.var(103), 54.0);
}

TEST(Motion, DwellAndEvents) {
  auto r = run("G04 P1500\nG04 X2.\nT5 M06\nS1000 M03\nM08\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.moves[0].kind, MoveKind::dwell);
  EXPECT_DOUBLE_EQ(r.moves[0].seconds, 1.5);
  EXPECT_DOUBLE_EQ(r.moves[1].seconds, 2.0);
  EXPECT_EQ(r.moves[2].kind, MoveKind::tool_change);
  EXPECT_EQ(r.moves[2].code, 5);
  EXPECT_EQ(r.moves[3].kind, MoveKind::spindle);
  EXPECT_EQ(r.moves[4].kind, MoveKind::coolant);
  EXPECT_EQ(r.moves[5].kind, MoveKind::program_end);
}

// Modes that change how the control accelerates, not the path, and cancels of modes not active.
TEST(Motion, HighSpeedModesAndCancelsLeaveThePath) {
  auto r = run("G05.1 Q1\nG08 P1\nG05 P10000\nG15 G40 G50 G69 G80\nG01 X10. F100.\nG05.1 Q0\nG05 P0\nG08 P0\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  ASSERT_EQ(r.motions().size(), 1u);
  EXPECT_DOUBLE_EQ(r.motions()[0].end[0], 10.0);
}

// A rotary axis word on a machine without that axis is the FANUC alarm, never dropped.
TEST(Motion, AxisWordOfAMissingRotaryAxisAlarms) {
  auto r = run("G00 X5. A10.\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0009");
  EXPECT_TRUE(r.motions().empty());
  EXPECT_EQ(run("G01 B20. F100.\nM30\n").alarm_code(), "PS0009");
}

TEST(Motion, UnsupportedFeaturesStopWithADiagnostic) {
  EXPECT_EQ(run("G02.2\n").alarm_code(), "NC9001");  // involute interpolation
  EXPECT_EQ(run("G07.5 X1.\n").alarm_code(), "PS0010");
}

TEST(Motion, LatheDiameterAndIncrementalAddresses) {
  auto p = machine::default_lathe();
  auto r = run("G00 X100. Z5.\nG01 U-20. W-10. F0.2\n#100=#5001\n#101=#5002\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto ms = r.motions();
  EXPECT_DOUBLE_EQ(ms[0].end[0], 50.0);  // radius inside
  EXPECT_DOUBLE_EQ(ms[1].end[0], 40.0);
  EXPECT_DOUBLE_EQ(ms[1].end[2], -5.0);
  EXPECT_TRUE(ms[1].feed_per_rev);  // lathes start in feed per revolution
  EXPECT_DOUBLE_EQ(r.var(100), 80.0);  // diameter in the variable
  EXPECT_DOUBLE_EQ(r.var(101), -5.0);
  EXPECT_EQ(run("G00 Y1.\n", p).alarm_code(), "PS0009");
  EXPECT_EQ(run("G90 X1. Z1.\n", p).alarm_code(), "PS0011");  // system A: G90 is a turning cycle, cut at F (none)
}

TEST(Motion, LatheArcInZX) {
  auto p = machine::default_lathe();
  // from X0 Z0 (diameter) a G03 quarter arc to X20 (radius 10) Z-10 about Z-10 X0 (I is a radius)
  auto r = run("G00 X0 Z0\nG03 X20. Z-10. K-10. F0.1\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto a = r.motions().at(1);
  EXPECT_NEAR(a.center[2], -10, 1e-12);
  EXPECT_NEAR(a.center[0], 0, 1e-12);
  EXPECT_NEAR(std::fabs(a.sweep), std::numbers::pi / 2, 1e-12);
}

TEST(Motion, LatheCoordinateSettingAndFeedModes) {
  auto p = machine::default_lathe();
  auto r = run("G00 X100. Z50.\nG50 X200. Z0.\n#100=#5001\n#101=#4005\nG98 G01 W-1. F100.\n#102=#4005\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 200.0);
  EXPECT_EQ(r.var(101), 99.0);
  EXPECT_EQ(r.var(102), 98.0);
  auto ms = r.motions();
  EXPECT_FALSE(ms.back().feed_per_rev);
  EXPECT_DOUBLE_EQ(ms.back().end[2], -1.0);
}

TEST(Motion, SecondReferencePoint) {
  auto p = test::zero_offset_mill();
  p.reference_points[1] = {-10, -20, -30, 0, 0, 0};
  auto r = run("G00 X5. Y5. Z5.\nG30 P2 X0 Y0 Z0\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto ms = r.motions();
  ASSERT_EQ(ms.size(), 3u);
  EXPECT_DOUBLE_EQ(ms[1].end[0], 0.0);
  EXPECT_DOUBLE_EQ(ms[2].end[0], -10.0);
  EXPECT_DOUBLE_EQ(ms[2].end[2], -30.0);
}

TEST(Motion, TimerFollowsSimulatedTime) {
  auto r = run("#3001=0\nG01 X100. F6000.\n#100=#3001\nG04 P500\n#101=#3001\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_NEAR(r.var(100), 1000.0, 1e-9);  // 100 mm at 6000 mm/min
  EXPECT_NEAR(r.var(101), 1500.0, 1e-9);
}

TEST(Motion, DateAndTimeFromTheClock) {
  std::time_t before = std::time(nullptr);
  auto r = run("#100=#3011\n#101=#3012\nM30\n");
  ASSERT_TRUE(r.result.ok());
  std::tm t{};
  localtime_r(&before, &t);
  double date = (t.tm_year + 1900) * 10000.0 + (t.tm_mon + 1) * 100 + t.tm_mday;
  EXPECT_GE(r.var(100), date);  // the same day, or the next one if midnight passed
  EXPECT_LE(r.var(100) - date, 8900);  // at most a new year
  int hhmmss = static_cast<int>(r.var(101));
  EXPECT_LT(hhmmss / 10000, 24);
  EXPECT_LT(hhmmss / 100 % 100, 60);
  EXPECT_LT(hhmmss % 100, 61);
}

TEST(Motion, ConstantSurfaceSpeedTime) {
  auto p = machine::default_lathe();
  // S100 m/min at diameter 100 mm is 1000*100/(pi*100) = 318.3 rev/min; 10 mm at 0.1 mm/rev
  auto r = run("G00 X100. Z0.\nG96 S100 M03\nG99 G01 W-10. F0.1\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  double rpm = 1000.0 * 100 / (std::numbers::pi * 100);
  EXPECT_NEAR(r.motions().back().seconds, 10 / (0.1 * rpm) * 60, 1e-9);
  // G50 S200 caps the spindle at 200 rev/min and is not itself a spindle speed
  auto capped = run("G50 S200\nG00 X100. Z0.\nG96 S100 M03\nG99 G01 W-10. F0.1\nM30\n", p);
  ASSERT_TRUE(capped.result.ok()) << nc::format(*capped.result.alarm);
  EXPECT_NEAR(capped.motions().back().seconds, 10 / (0.1 * 200) * 60, 1e-9);
}

// Lathe geometry and wear offsets (FANUC T series layout): the tool tip path in work coordinates is
// as programmed; machine positions (#5021.., G28) carry geometry + wear, X as a diameter.
TEST(Motion, LatheToolOffsetsShiftTheMachinePosition) {
  auto p = machine::parse_profile(
      "[machine]\ntype = \"lathe\"\n[reference_points]\n\"1\" = [150, 250]\n"
      "[tool_offsets]\n\"1\" = { x = 2.0, z = -1.5, x_wear = 0.04, z_wear = 0.01, r = 0.4, tip = 3 }\n",
      "lathe.toml");
  auto r = run(
      "#100=#2701\n#101=#2001\n#102=#2801\n#103=#2101\n#104=#2901\n#105=#2301\n"
      "T0101\nG00 X50. Z10.\n#110=#5021\n#111=#5022\n#112=#5041\n"
      "G10 P1 U0.02\n#113=#2001\nT0101\n#114=#5021\n"
      "T0100\n#115=#5021\n#2801=-3.\nT0101\n#116=#5022\n"
      "G28 U0\n#117=#5021\n#118=#5041\n#119=#5022\n"
      "G10 P10002 X-1. Z2.\n#120=#2702\n#121=#2802\n#122=#2002\nM30\n",
      p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 2.0);
  EXPECT_DOUBLE_EQ(r.var(101), 0.04);
  EXPECT_DOUBLE_EQ(r.var(102), -1.5);
  EXPECT_DOUBLE_EQ(r.var(103), 0.01);
  EXPECT_DOUBLE_EQ(r.var(104), 0.4);
  EXPECT_DOUBLE_EQ(r.var(105), 3.0);
  EXPECT_NEAR(r.var(110), 50 + 2.04, 1e-12);  // machine X (diameter) = work + geometry + wear
  EXPECT_NEAR(r.var(111), 10 - 1.5 + 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(r.var(112), 50.0);  // the tool tip is where the program says
  EXPECT_NEAR(r.var(113), 0.06, 1e-12);  // G10 U adds to the wear
  EXPECT_NEAR(r.var(114), 50 + 2.06, 1e-12);
  EXPECT_DOUBLE_EQ(r.var(115), 50.0);  // T0100 cancels the offset
  EXPECT_NEAR(r.var(116), 10 - 3 + 0.01, 1e-12);
  EXPECT_NEAR(r.var(117), 300.0, 1e-12);  // G28: machine X at the reference point (radius 150)
  EXPECT_NEAR(r.var(118), 300.0 - 2.06, 1e-12);
  EXPECT_NEAR(r.var(119), 10 - 3 + 0.01, 1e-12);  // Z not named in G28: unchanged
  EXPECT_DOUBLE_EQ(r.var(120), -1.0);
  EXPECT_DOUBLE_EQ(r.var(121), 2.0);
  EXPECT_DOUBLE_EQ(r.var(122), 0.0);
  EXPECT_EQ(run("T0165\n", p).alarm_code(), "PS0030");
  EXPECT_EQ(run("G10 P65 X1.\n", p).alarm_code(), "PS0031");
  EXPECT_THROW(machine::parse_profile("[machine]\ntype = \"lathe\"\n[tool_offsets]\n\"1\" = 2.0\n", "l.toml"),
               std::runtime_error);
  EXPECT_THROW(machine::parse_profile("[machine]\ntype = \"lathe\"\n[tool_offsets]\n\"1\" = { y = 2.0 }\n", "l.toml"),
               std::runtime_error);
}
