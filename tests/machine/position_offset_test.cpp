// Tool position offset G45..G48 of a mill: what the FANUC 0i-MF / 30i-B operator's manual says
// besides the moves (tests/programs/coordinates/position_offset_g45_g48.*): H by No.5001#5 TPH,
// PS0042 in cutter compensation, ignored in canned cycle mode, arcs only as 1/4 and 3/4 circles by
// I J K.
#include <gtest/gtest.h>

#include <algorithm>

#include "machine/profile.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
bool warned(const test::Ran& r, const std::string& code) {
  return std::ranges::any_of(r.result.warnings, [&](const nc::Diagnostic& d) { return d.code == code; });
}
}  // namespace

// D1 = 2 (a radius), H1 = 5 on memory C: TPH = 1 reads H, and H1 only selects the value.
TEST(PositionOffset, HAddressByParameter5001Bit5) {
  const std::string text = "G10 L10 P1 R5.\nG10 L12 P1 R2.\nG90 G00 X0. Y0. Z0.\nG91 G45 X10. D1 H1\nM30\n";
  auto profile = machine::default_mill();
  profile.offset_memory = machine::OffsetMemory::C;
  auto by_d = run(text, profile);
  ASSERT_TRUE(by_d.result.ok()) << nc::format(*by_d.result.alarm);
  EXPECT_NEAR(by_d.motions().back().end[0], 12.0, 1e-9);  // 10 + D1 (2)
  machine::set_parameter(profile, "5001#5", 1);
  auto by_h = run(text, profile);
  ASSERT_TRUE(by_h.result.ok()) << nc::format(*by_h.result.alarm);
  EXPECT_NEAR(by_h.motions().back().end[0], 15.0, 1e-9);  // 10 + H1 (5)
}

// "G45 to G48 are ignored in canned cycle mode": the hole is at the programmed X, with a warning.
TEST(PositionOffset, IgnoredInCannedCycleMode) {
  auto r = run("G10 L10 P1 R2.\nG90 G00 X0. Y0. Z10. D1\nG81 X10. Z-5. R2. F100.\nG45 X20.\nG80\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  const auto m = r.motions();
  const auto hole = std::ranges::find_if(m, [](const machine::Move& mv) { return mv.line == 4; });
  ASSERT_NE(hole, m.end());
  EXPECT_NEAR(hole->end[0], 20.0, 1e-9);
  EXPECT_TRUE(warned(r, "NC2014"));
}

// Alarm PS0042 (G45/G48 NOT ALLOWED IN CRC): G45..G48 in cutter compensation mode.
TEST(PositionOffset, CutterCompensationIsPs0042) {
  auto r = run("G10 L10 P1 R2.\nG90 G00 X0. Y0. Z0.\nG41 G01 X10. D1 F100.\nG45 X20.\nG40 X30.\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0042");
  EXPECT_EQ(r.alarm_line(), 4u);
}

// Arcs: only 1/4 and 3/4 circles given by I, J, K take the offset; R or a half circle stop the run.
TEST(PositionOffset, ArcsOtherThanQuarterCirclesStop) {
  auto half = run("G10 L10 P1 R2.\nG90 G00 X0. Y0. Z0. D1\nG91 G01 G45 G03 X-6. I-3. F100.\nM30\n");
  EXPECT_EQ(half.alarm_code(), "NC9002");
  auto by_r = run("G10 L10 P1 R2.\nG90 G00 X0. Y0. Z0. D1\nG91 G01 G45 G03 X-3. Y3. R3. F100.\nM30\n");
  EXPECT_EQ(by_r.alarm_code(), "NC9002");
  // a 3/4 circle: from (0, 0) about (0, 3) counterclockwise to (-3, 3); G47 grows each travel by 4
  auto three = run("G10 L10 P1 R2.\nG90 G00 X0. Y0. Z0. D1\nG91 G01 G47 G03 X-3. Y3. J3. F100.\nM30\n");
  ASSERT_TRUE(three.result.ok()) << nc::format(*three.result.alarm);
  const auto arc = three.motions().back();
  EXPECT_NEAR(arc.end[0], -7.0, 1e-9);
  EXPECT_NEAR(arc.end[1], 7.0, 1e-9);
  EXPECT_NEAR(arc.center[1], 7.0, 1e-9);
  EXPECT_NEAR(arc.sweep, 1.5 * 3.14159265358979, 1e-9);  // 3/4 of a turn, counterclockwise
}

// A lathe has no G45..G48.
TEST(PositionOffset, LatheHasNoG45) {
  auto r = run("G00 X20. Z5.\nG45 U2.\nM30\n", machine::default_lathe());
  EXPECT_EQ(r.alarm_code(), "PS0010");
}
