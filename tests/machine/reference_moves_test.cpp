// G27/G29/G30.1, G60, G92.1, G31, the stored stroke checks and the G codes ncurve does not simulate;
// the hand-worked paths are in tests/programs/reference (ref_*, g60_*, skip_*, stroke_*, wcs_preset_*).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
bool warned(const test::Ran& r, const std::string& code) {
  for (const auto& w : r.result.warnings)
    if (w.code == code) return true;
  return false;
}
std::string message(const test::Ran& r) { return r.result.alarm ? r.result.alarm->message : ""; }
}  // namespace

TEST(ReferenceMoves, G27FailsOnTheAxisAwayFromTheReferencePosition) {
  auto r = run("G90 G00 X5. Y0. Z0.\nG27 X1. Y0.\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0092");
  EXPECT_EQ(r.alarm_line(), 2u);
  EXPECT_NE(message(r).find("the X axis is at 1.0000"), std::string::npos) << message(r);
  ASSERT_EQ(r.motions().size(), 2u);  // the positioning is made, then the check fails
  EXPECT_DOUBLE_EQ(r.motions()[1].end[0], 1.0);
}

TEST(ReferenceMoves, G29IncrementalCountsFromTheIntermediatePointOnALathe) {
  // system A: U is incremental. G28 U20. from X40 (diameter): intermediate X 60 diameter (30 radius).
  auto r = run("G00 X40. Z10.\nG28 U20.\nG29 U-10.\nM30\n", machine::default_lathe());
  ASSERT_TRUE(r.result.ok()) << message(r);
  auto m = r.motions();
  ASSERT_EQ(m.size(), 5u);
  EXPECT_DOUBLE_EQ(m[3].end[0], 30.0);  // back to the intermediate point, radius
  EXPECT_DOUBLE_EQ(m[4].end[0], 25.0);  // 60 - 10 = 50 diameter
  EXPECT_DOUBLE_EQ(m[4].end[2], 10.0);  // Z not named: it stays
}

TEST(ReferenceMoves, G30_1NeedsTheFloatingPositionInTheProfile) {
  auto r = run("G30.1 Z10.\nM30\n");
  EXPECT_EQ(r.alarm_code(), "NC9001");
  EXPECT_NE(message(r).find("floating"), std::string::npos);
}

TEST(ReferenceMoves, G92_1WithAValueWarns) {
  auto r = run("G92 X10.\nG92.1 X5.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << message(r);
  EXPECT_TRUE(warned(r, "NC2041"));
  EXPECT_DOUBLE_EQ(r.var(5041), 0.0);  // back in G54: the tool stands at work X0
}

TEST(ReferenceMoves, G60InACannedCycleIsNotSupported) {
  auto p = machine::default_mill();
  p.g60_overrun[0] = 1;
  auto r = run("G90 G00 Z10.\nG81 X10. Y10. Z-5. R2. F100.\nG60 X20.\nM30\n", p);
  EXPECT_EQ(r.alarm_code(), "NC9001");
  EXPECT_EQ(r.alarm_line(), 3u);
}

TEST(Skip, HoldsTheEndPointAfterLaterMoves) {
  auto r = run("G90 G00 X0. Y0. Z0.\nG31 X12.5 F100.\nG00 X0.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << message(r);
  EXPECT_DOUBLE_EQ(r.var(5061), 12.5);
  EXPECT_TRUE(warned(r, "NC2040"));
  EXPECT_EQ(r.motions().at(1).kind, machine::MoveKind::line);
  EXPECT_EQ(run("G31 P5 X1. F100.\nM30\n").alarm_code(), "NC9002");
  EXPECT_EQ(run("G31 X1.\nM30\n").alarm_code(), "PS0011");  // a feed move: F is needed
}

TEST(StrokeCheck, NoLimitAtTheFactory) {
  auto r = run("G00 X9000. Y-9000. Z9000.\nM30\n");
  EXPECT_TRUE(r.result.ok());
}

TEST(StrokeCheck, LimitOneOnALatheXIsADiameter) {
  auto p = machine::default_lathe();
  machine::set_parameter(p, "1320.X", 200000);  // 200 mm in diameter: radius 100
  EXPECT_TRUE(run("G00 X190. Z0.\nM30\n", p).result.ok());
  auto r = run("G00 X210. Z0.\nM30\n", p);
  EXPECT_EQ(r.alarm_code(), "OT0500");
  EXPECT_NE(message(r).find("X 210.0000"), std::string::npos) << message(r);
}

TEST(StrokeCheck, LimitOneBelowTheMinus) {
  auto p = test::zero_offset_mill();
  machine::set_parameter(p, "1321.Z", -100000);
  auto r = run("G00 Z-99.\nG01 Z-101. F100.\nM30\n", p);
  EXPECT_EQ(r.alarm_code(), "OT0501");
  EXPECT_EQ(r.alarm_line(), 2u);
  EXPECT_EQ(r.motions().size(), 1u);  // ncurve stops before the move
}

TEST(StrokeCheck, G23SwitchesCheckTwoOff) {
  const std::string area = "G22 X50. Y50. Z10. I20. J20. K-10.\n";
  EXPECT_EQ(run(area + "G01 X100. Y60. F500.\nM30\n").alarm_code(), "OT0502");
  EXPECT_TRUE(run(area + "G23\nG01 X100. Y60. F500.\nM30\n").result.ok());
  // entering through the +X face moving -X
  EXPECT_EQ(run(area + "G00 X60.\nY30.\nG01 X0. F500.\nM30\n").alarm_code(), "OT0503");
}

TEST(StrokeCheck, OutsideForbiddenWithOut1) {
  auto p = test::zero_offset_mill();
  machine::set_parameter(p, "1300#0", 1);
  const std::string area = "G22 X100. Y100. Z10. I-100. J-100. K-200.\n";
  EXPECT_TRUE(run(area + "G01 X90. Y-90. F500.\nM30\n", p).result.ok());
  auto r = run(area + "G01 X90. Y-90. F500.\nG03 X90. Y90. R90.\nM30\n", p);  // the arc bulges out to X 180
  EXPECT_EQ(r.alarm_code(), "OT0502");
  EXPECT_EQ(r.alarm_line(), 3u);
}

TEST(GCodes, SpindleSpeedFluctuationDetectionIsAccepted) {
  auto r = run("G26 G00 X1.\nG25\nM30\n");
  ASSERT_TRUE(r.result.ok()) << message(r);
  EXPECT_EQ(r.motions().size(), 1u);
}

// G10.6 sets the tool retract of the retraction signal; a program run gives no signal, so the block
// moves nothing and the next move goes from where the tool was (30i-B: tool retract and recover).
TEST(GCodes, ToolRetractSettingMovesNothing) {
  for (const char* setting : {"G10.6 Z10.", "G91 G10.6 Z5.", "G10.6"}) {
    auto r = run(fmt::format("G90 G00 X1. Y2. Z3.\n{}\nG90 G01 X4. F100.\nM30\n", setting));
    ASSERT_TRUE(r.result.ok()) << setting << ": " << message(r);
    const auto moves = r.motions();
    ASSERT_EQ(moves.size(), 2u) << setting;
    EXPECT_EQ(moves[1].start, (machine::AxisVector{1, 2, 3})) << setting;
    EXPECT_EQ(moves[1].end, (machine::AxisVector{4, 2, 3})) << setting;
  }
  auto lathe = run("G00 X20. Z5.\nG10.6 U2.\nG01 Z-10. F0.2\nM30\n", machine::default_lathe());
  ASSERT_TRUE(lathe.result.ok()) << message(lathe);
  EXPECT_EQ(lathe.motions().size(), 2u);
}

TEST(GCodes, CodesOfTheControlAreNotSupportedYetNotUnknown) {
  for (const char* code : {"G02.2", "G06.2", "G39", "G40.1", "G43.4", "G53.1", "G68.2", "G72.1", "G81.1",
                           "G96.1", "G37"}) {
    auto r = run(fmt::format("{} X10. Z1.\nM30\n", code));
    EXPECT_EQ(r.alarm_code(), "NC9001") << code << ": " << message(r);
    EXPECT_NE(message(r).find(std::string("(") + code + ")"), std::string::npos) << message(r);
  }
  EXPECT_NE(message(run("G37 Z0.\nM30\n")).find("PS0080"), std::string::npos);
  for (const char* code : {"G34", "G36", "G50.2", "G68", "G10.9"}) {
    auto r = run(fmt::format("{} X10. Z1.\nM30\n", code), machine::default_lathe());
    EXPECT_EQ(r.alarm_code(), "NC9001") << code << ": " << message(r);
  }
  EXPECT_NE(message(run("G68\nM30\n", machine::default_lathe())).find("double turrets"), std::string::npos);
  EXPECT_EQ(run("G34 X10.\nM30\n").alarm_code(), "PS0010");  // a lathe code, not a mill's
  EXPECT_EQ(run("G60 X10.\nM30\n", machine::default_lathe()).alarm_code(), "PS0010");
  EXPECT_EQ(run("G99.9\nM30\n").alarm_code(), "PS0010");
}
