// NC2077: a lathe's feed that ends at or passes through X < 0, the tool beyond the spindle centre
// line. The X of each message is worked by hand from the block (a diameter on the default lathe).
#include <gtest/gtest.h>

#include <string>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
int count(const test::Ran& r) {
  int n = 0;
  for (const auto& w : r.result.warnings) n += w.code == "NC2077";
  return n;
}
const nc::Diagnostic* first(const test::Ran& r) {
  for (const auto& w : r.result.warnings)
    if (w.code == "NC2077") return &w;
  return nullptr;
}
bool has(const std::string& message, const std::string& part) { return message.find(part) != std::string::npos; }
}  // namespace

// Facing from X42 down to X0 stops on the centre line, and on to X-2. (a diameter: 1 mm beyond) is
// the overshoot that leaves no pip: clean; a rapid beyond it cuts nothing.
TEST(BeyondTheCentreLine, FacingToX0OrJustPastAndRapidsAreClean) {
  auto r = run("G00 X42. Z0.5\nG01 Z0 F0.2\nG01 X0\nG00 Z5.\nG00 X-10.\nG00 X50.\nM30\n", machine::default_lathe());
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(count(r), 0);
  auto past = run("G00 X42. Z0\nG01 X-2. F0.2\nG00 Z5.\nM30\n", machine::default_lathe());
  ASSERT_TRUE(past.result.ok());
  EXPECT_EQ(count(past), 0);
}

// Facing on to X-2.2 (a diameter) ends 1.1 mm beyond the centre, past the 1 mm of a facing cut:
// warned at the block, at its X word.
TEST(BeyondTheCentreLine, AFeedEndingBeyondX0Warns) {
  auto r = run("G00 X42. Z0\nG01 X-2.2 F0.2\nG00 Z5.\nM30\n", machine::default_lathe());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r), 1);
  const nc::Diagnostic& w = *first(r);
  EXPECT_EQ(w.span.line, 2u);
  EXPECT_EQ(w.span.column, 5u);  // "G01 F0.2": X is the fifth character
  EXPECT_TRUE(has(w.message, "X-2.2 (a diameter)")) << w.message;
  EXPECT_TRUE(has(w.message, "spindle centre line")) << w.message;
}

// An arc of radius 5 from X4 Z0 to X4 Z-10 (radius 2 on both ends, centre X4 Z-5): G02, clockwise
// seen from +Y (X up, Z to the right), goes from the centre's +Z side through its -X side, down to
// radius 2 - 5 = -3, a diameter of -6, though both its ends are at X4; G03 goes over the top
// (X4 + 10 = X14) and is clean.
TEST(BeyondTheCentreLine, AnArcPassingBeyondX0Warns) {
  auto cw = run("G00 X4. Z1.\nG01 Z0 F0.2\nG18 G02 X4. Z-10. R5.\nG00 X50.\nM30\n", machine::default_lathe());
  ASSERT_TRUE(cw.result.ok());
  ASSERT_EQ(count(cw), 1);
  EXPECT_EQ(first(cw)->span.line, 3u);
  EXPECT_TRUE(has(first(cw)->message, "X-6 (a diameter)")) << first(cw)->message;
  auto ccw = run("G00 X4. Z1.\nG01 Z0 F0.2\nG18 G03 X4. Z-10. R5.\nG00 X50.\nM30\n", machine::default_lathe());
  ASSERT_TRUE(ccw.result.ok());
  EXPECT_EQ(count(ccw), 0);
}

// Once each time beyond: lines 2 and 3 stay beyond (3 starts at X-3), line 4 passes through it,
// line 5 is wholly on the tool's side, line 6 goes beyond again.
TEST(BeyondTheCentreLine, OnceEachTimeTheToolGoesBeyond) {
  auto r = run("G00 X42. Z0\nG01 X-3. F0.2\nG01 X-4.\nG01 X20.\nG01 X30.\nG01 X-5.\nG00 Z5.\nM30\n", machine::default_lathe());
  ASSERT_TRUE(r.result.ok());
  std::vector<std::uint32_t> lines;
  for (const auto& w : r.result.warnings)
    if (w.code == "NC2077") lines.push_back(w.span.line);
  EXPECT_EQ(lines, (std::vector<std::uint32_t>{2, 6}));
}

// Programmed as a radius (No.1006#3 = 1), X-1.5 is 1.5 mm beyond and said so, not as a diameter; a
// nose radius of 2 allows a facing cut 2 mm beyond; a mill's X below 0 is a place on the table, not warned.
TEST(BeyondTheCentreLine, RadiusProgrammingAndAMill) {
  machine::MachineProfile p = machine::default_lathe();
  p.diameter_x = false;
  auto r = run("G00 X21. Z0\nG01 X-1.5 F0.2\nG00 Z5.\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r), 1);
  EXPECT_TRUE(has(first(r)->message, "X-1.5, beyond")) << first(r)->message;
  auto nose = run("G10 P1 R2.\nT0101\nG00 X21. Z0\nG01 X-1.9 F0.2\nG01 X-2.1\nG00 Z5.\nM30\n", p);
  ASSERT_TRUE(nose.result.ok());
  ASSERT_EQ(count(nose), 1);
  EXPECT_EQ(first(nose)->span.line, 5u);
  auto mill = run("G00 X0 Y0 Z1.\nG01 Z-1. F100.\nG01 X-10.\nM30\n");
  ASSERT_TRUE(mill.result.ok());
  EXPECT_EQ(count(mill), 0);
}

// An inch program's X is said in inches: X-.5 on a diameter is 6.35 mm beyond the centre.
TEST(BeyondTheCentreLine, AnInchProgramIsToldInInches) {
  auto r = run("G20\nG00 X1.5 Z0\nG01 X-.5 F.004\nG00 Z.2\nM30\n", machine::default_lathe());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r), 1);
  EXPECT_TRUE(has(first(r)->message, "X-0.5 (a diameter)")) << first(r)->message;
}
