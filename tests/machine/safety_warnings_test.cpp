// The shipped mill's setup (reference position 1 at machine zero above the table, G54 below it) and
// the mistakes a control accepts without an alarm that ruin the part or the tool: a reference
// return towards the part (NC2074), a first cut after a tool change with no tool length
// compensation (NC2075), peck drilling whose d is 0 (NC2076), a spindle speed over the machine's
// limit (NC2090). Every expected value is worked by hand from the manuals' rules in the comment
// beside it.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
int count(const test::Ran& r, const std::string& code) {
  int n = 0;
  for (const auto& w : r.result.warnings) n += w.code == code;
  return n;
}
const nc::Diagnostic* first(const test::Ran& r, const std::string& code) {
  for (const auto& w : r.result.warnings)
    if (w.code == code) return &w;
  return nullptr;
}
std::string text(const test::Ran& r, const std::string& code) {
  const nc::Diagnostic* w = first(r, code);
  return w ? w->message : "";
}
bool has(const std::string& message, const std::string& part) { return message.find(part) != std::string::npos; }

// The lathe of profiles/fanuc-lathe.toml: reference position 1 at machine X150 (radius: 300 on the
// diameter) Z250, G54 at machine zero on the spindle centre line.
machine::MachineProfile lathe_with_home() {
  machine::MachineProfile p = machine::default_lathe();
  p.reference_points[0] = {150, 0, 250, 0, 0, 0};
  return p;
}
}  // namespace

// ---- the shipped mill ----

// Reference position 1 is machine zero; G54 (G55..G59 too) is machine X-250 Y-200 Z-400, so the machine powers on
// with the tool at X250 Y200 Z400 of G54 (0 - (-250), 0 - (-200), 0 - (-400)).
TEST(ShippedMill, PowersOnAtMachineZeroAboveAndBesideTheWorkZero) {
  const machine::MachineProfile mill = machine::default_mill();
  EXPECT_EQ(mill.reference_points[0], (machine::AxisVector{0, 0, 0, 0, 0, 0}));
  const machine::MachineProfile file = machine::load_profile(NCURVE_SOURCE_DIR "/profiles/fanuc-mill.toml");
  EXPECT_EQ(file.reference_points[0], mill.reference_points[0]);
  for (int g = 1; g <= 6; ++g) {  // G54..G59 at one place below machine zero, in both
    EXPECT_EQ(mill.work_offsets[g], (machine::AxisVector{-250, -200, -400, 0, 0, 0})) << "G" << 53 + g;
    EXPECT_EQ(file.work_offsets[g], mill.work_offsets[g]) << "G" << 53 + g;
  }
  // #5021..#5023 the machine position, #5041..#5043 the work position, before any move
  auto r = run("#101=#5021\n#102=#5022\n#103=#5023\n#104=#5041\n#105=#5042\n#106=#5043\nG90 G00 X0 Y0\nM30\n", mill);
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.var(101), 0.0);
  EXPECT_EQ(r.var(102), 0.0);
  EXPECT_EQ(r.var(103), 0.0);
  EXPECT_EQ(r.var(104), 250.0);
  EXPECT_EQ(r.var(105), 200.0);
  EXPECT_EQ(r.var(106), 400.0);
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].start, (machine::AxisVector{250, 200, 400, 0, 0, 0}));
  EXPECT_EQ(m[0].end, (machine::AxisVector{0, 0, 400, 0, 0, 0}));  // Z not named: it stays at the top
}

// ---- NC2074: a reference return towards the part ----

// The program on the shipped mill: after a cut at Z-5, G91 G28 Z0 goes through the point
// where the tool is (an incremental 0) to machine Z0, which is Z400 of G54: 405 mm up. Clean.
TEST(ReturnTowardsThePart, G91G28Z0GoesUpOnTheShippedMill) {
  auto r = run("G90 G54 G00 X0 Y0 Z5.\nG01 Z-5. F100.\nG91 G28 Z0\nM30\n", machine::default_mill());
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(count(r, "NC2074"), 0);
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[2].end, (machine::AxisVector{0, 0, -5, 0, 0, 0}));   // the intermediate point: where the tool is
  EXPECT_EQ(m[3].end, (machine::AxisVector{0, 0, 400, 0, 0, 0}));  // machine Z0 = G54 Z400
}

// G28 Z-100. under G90: the intermediate point is Z-100 of G54, 95 mm below the tool at Z-5; then up
// to Z400. The first leg warns.
TEST(ReturnTowardsThePart, AnAbsoluteIntermediatePointBelowTheToolWarns) {
  auto r = run("G90 G54 G00 X0 Y0 Z5.\nG01 Z-5. F100.\nG28 Z-100.\nM30\n", machine::default_mill());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r, "NC2074"), 1);
  const nc::Diagnostic* w = first(r, "NC2074");
  EXPECT_EQ(w->span.line, 3u);
  EXPECT_EQ(w->span.column, 1u);
  EXPECT_TRUE(has(w->message, "G28 rapids 95.000 mm down (-Z) towards the part to its intermediate point Z-100.000"))
      << w->message;
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[2].end[2], -100.0);
  EXPECT_EQ(m[3].end[2], 400.0);
}

// A profile whose work offsets are 0 puts the work zero at the reference point (machine zero): the
// tool at Z50 returns 50 mm down, onto the work zero.
TEST(ReturnTowardsThePart, AReferencePointAtTheWorkZeroWarns) {
  auto r = run("G90 G00 X0 Y0 Z50.\nG91 G28 Z0\nM30\n", test::zero_offset_mill());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r, "NC2074"), 1);
  const nc::Diagnostic* w = first(r, "NC2074");
  EXPECT_EQ(w->span.line, 2u);
  EXPECT_EQ(w->span.column, 5u);  // the G28 word
  EXPECT_TRUE(has(w->message, "G28 rapids 50.000 mm down (-Z) towards the part to reference position 1: the "
                              "reference point is below the tool: the profile puts it at machine Z0.000"))
      << w->message;
  EXPECT_TRUE(has(w->message, "which is Z0.000 in the work coordinates in force, and the tool stood at Z50.000"))
      << w->message;
  EXPECT_EQ(r.motions().back().end[2], 0.0);  // the control makes the move: ncurve only warns
}

// Both legs down (Z50 -> Z20 -> Z0 on the zero-offset mill): one warning for the block, naming both.
TEST(ReturnTowardsThePart, BothLegsDownWarnOnceNamingBoth) {
  auto r = run("G90 G00 X0 Y0 Z50.\nG28 Z20.\nM30\n", test::zero_offset_mill());
  ASSERT_EQ(count(r, "NC2074"), 1);
  const std::string w = text(r, "NC2074");
  EXPECT_TRUE(has(w, "G28 rapids 30.000 mm down (-Z) towards the part to its intermediate point Z20.000")) << w;
  EXPECT_TRUE(has(w, "then it rapids 20.000 mm down (-Z) towards the part to reference position 1")) << w;
}

// G30 P2 to a second reference position the profile puts at machine Z-450, Z-50 of G54: from Z10
// the return goes 60 mm down.
TEST(ReturnTowardsThePart, G30ToAReferencePositionBelowTheToolWarns) {
  machine::MachineProfile p = machine::default_mill();
  p.reference_points[1] = {0, 0, -450, 0, 0, 0};
  auto r = run("G90 G00 X0 Y0 Z10.\nG91 G30 P2 Z0\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r, "NC2074"), 1);
  const std::string w = text(r, "NC2074");
  EXPECT_TRUE(has(w, "G30 P2 rapids 60.000 mm down (-Z) towards the part to reference position 2")) << w;
  EXPECT_TRUE(has(w, "machine Z-450.000 ([reference_points] \"2\"), which is Z-50.000 in the work coordinates")) << w;
  EXPECT_EQ(r.motions().back().end[2], -50.0);
}

// G30.1 to a floating reference position the operator set at machine Z-450 (Z-50 of G54): 60 mm
// down from Z10. Under G20 the distances are in inches: G28 Z-1. from Z-0.1 goes 0.9 in down.
TEST(ReturnTowardsThePart, FloatingReferenceAndInchesToo) {
  machine::MachineProfile p = machine::default_mill();
  p.floating_reference = machine::AxisVector{0, 0, -450, 0, 0, 0};
  auto floating = run("G90 G00 X0 Y0 Z10.\nG91 G30.1 Z0\nM30\n", p);
  ASSERT_TRUE(floating.result.ok());
  ASSERT_EQ(count(floating, "NC2074"), 1);
  EXPECT_TRUE(has(text(floating, "NC2074"), "G30.1 rapids 60.000 mm down (-Z) towards the part to the floating "
                                            "reference position"))
      << text(floating, "NC2074");
  EXPECT_TRUE(has(text(floating, "NC2074"), "machine Z-450.000 ([reference_points] floating)")) << text(floating, "NC2074");
  auto inch = run("G20 G90 G54 G00 X0 Y0 Z2.\nG01 Z-0.1 F10.\nG28 Z-1.\nM30\n", machine::default_mill());
  ASSERT_EQ(count(inch, "NC2074"), 1);
  EXPECT_TRUE(has(text(inch, "NC2074"), "G28 rapids 0.900 in down (-Z) towards the part to its intermediate point "
                                        "Z-1.000"))
      << text(inch, "NC2074");
}

// Not warned: a return of X and Y alone (Z stays), G53 (a positioning in machine coordinates, not a
// return), a return with the tool length offset in force (G43 H1 = 100: the tool at Z-5 is machine
// -5 - 400 + 100 = -305; the return takes the spindle to machine Z0, which is Z300 of G54 with the
// offset: up).
TEST(ReturnTowardsThePart, ReturnsThatGoUpOrSidewaysAreClean) {
  const machine::MachineProfile mill = machine::default_mill();
  auto xy = run("G90 G00 X0 Y0 Z-5.\nG28 X0 Y0\nG53 Z-450.\nM30\n", mill);
  ASSERT_TRUE(xy.result.ok());
  EXPECT_EQ(count(xy, "NC2074"), 0);
  const auto m = xy.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[2].end, (machine::AxisVector{250, 200, -5, 0, 0, 0}));  // machine X0 Y0, Z where it was
  EXPECT_EQ(m[3].end[2], -50.0);                                      // G53 Z-450.: 50 mm below G54 Z0
  auto g43 = run("G10 L11 P1 R100.\nG90 G00 G43 X0 Y0 Z50. H1\nG01 Z-5. F100.\nG91 G28 Z0\nM30\n", mill);
  ASSERT_TRUE(g43.result.ok());
  EXPECT_EQ(count(g43, "NC2074"), 0);
  EXPECT_EQ(g43.motions().back().end[2], 300.0);
}

// A lathe: X up, the tool on the +X side of the spindle centre line (work X0), the chuck towards -Z.
// From X40 (diameter) Z-20, G28 U0 W0 on the lathe of fanuc-lathe.toml goes out to X300 Z250: clean.
// With the reference point at the work zero (a profile without one) it goes 40 mm (diameter) in X
// onto the centre line and 5 mm towards the chuck from Z5.
TEST(ReturnTowardsThePart, ALatheReturnIntoThePartWarns) {
  auto home = run("G00 X40. Z5.\nG01 Z-20. F0.2\nG28 U0 W0\nM30\n", lathe_with_home());
  ASSERT_TRUE(home.result.ok());
  EXPECT_EQ(count(home, "NC2074"), 0);
  EXPECT_EQ(home.motions().back().end, (machine::AxisVector{150, 0, 250, 0, 0, 0}));  // radius 150 = X300
  auto zero = run("G00 X40. Z5.\nG28 U0 W0\nM30\n", machine::default_lathe());
  ASSERT_TRUE(zero.result.ok());
  ASSERT_EQ(count(zero, "NC2074"), 1);
  const std::string w = text(zero, "NC2074");
  EXPECT_TRUE(has(w, "G28 rapids 40.000 mm on the diameter in X towards the spindle centre line and 5.000 mm in -Z "
                     "towards the chuck to reference position 1"))
      << w;
  EXPECT_TRUE(has(w, "machine X0.000 Z0.000")) << w;
}

// In front of the face (Z > 0) the tool is clear of the part: from X320 Z76 the return's X comes
// 20 mm (diameter) nearer the centre line, to X300, but ends at Z250: clean. A second reference
// position behind the face (machine X150 radius Z-30): from X40 Z5 the return goes 35 mm towards
// the chuck to Z-30 (and out in X): warned for Z alone.
TEST(ReturnTowardsThePart, ALatheReturnInFrontOfTheFaceIsClean) {
  auto front = run("G00 X320. Z76.\nG28 U0 W0\nM30\n", lathe_with_home());
  ASSERT_TRUE(front.result.ok());
  EXPECT_EQ(count(front, "NC2074"), 0);
  EXPECT_EQ(front.motions().back().end, (machine::AxisVector{150, 0, 250, 0, 0, 0}));
  machine::MachineProfile p = lathe_with_home();
  p.reference_points[1] = {150, 0, -30, 0, 0, 0};
  auto behind = run("G00 X40. Z5.\nG30 P2 U0 W0\nM30\n", p);
  ASSERT_TRUE(behind.result.ok());
  ASSERT_EQ(count(behind, "NC2074"), 1);
  const std::string w = text(behind, "NC2074");
  EXPECT_TRUE(has(w, "G30 P2 rapids 35.000 mm in -Z towards the chuck to reference position 2")) << w;
  EXPECT_FALSE(has(w, "centre line")) << w;
}

// ---- NC2075: the first cut after a tool change, with no G43 H ----

// T1 M06, then down to Z5 and a cut to Z-5 with G49 (the power-on mode): the spindle's gauge line
// goes to Z-5, the tool's tip its length below. Warned at the cut (line 4), naming the change's line.
TEST(ToolChangeWithoutLengthOffset, TheFirstCutWithoutG43Warns) {
  auto r = run("T1 M06\nG90 G54 G00 X0 Y0\nZ5.\nG01 Z-5. F100.\nX10.\nM30\n", machine::default_mill());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r, "NC2075"), 1);  // the first cut only
  const nc::Diagnostic* w = first(r, "NC2075");
  EXPECT_EQ(w->span.line, 4u);
  EXPECT_EQ(w->span.column, 1u);
  EXPECT_TRUE(has(w->message, "T1 cuts with no G43 H: the programmed Z is the spindle's gauge line, not the tool tip"))
      << w->message;
  EXPECT_TRUE(has(w->message, "no tool length compensation (G49) is in force since the tool change (M06) at line 1"))
      << w->message;
  EXPECT_TRUE(has(w->message, "give G43 H1")) << w->message;
}

// G43 H0: offset number 0 is always 0, so the gauge line is programmed as without G43.
TEST(ToolChangeWithoutLengthOffset, G43WithH0Warns) {
  auto r = run("T4 M06\nG90 G00 G43 X0 Y0 Z5. H0\nG01 Z-5. F100.\nM30\n", machine::default_mill());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r, "NC2075"), 1);
  EXPECT_TRUE(has(text(r, "NC2075"), "T4 cuts with no G43 H")) << text(r, "NC2075");
  EXPECT_TRUE(has(text(r, "NC2075"), "G43 with H0 (offset number 0 is always 0)")) << text(r, "NC2075");
}

// A drilling cycle's feed is a cut: G81 after T3 M06 warns at its block (line 3).
TEST(ToolChangeWithoutLengthOffset, ACycleFeedIsACut) {
  auto r = run("T3 M06\nG90 G00 X10. Y10. Z20.\nG81 Z-10. R2. F100.\nG80\nM30\n", machine::default_mill());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r, "NC2075"), 1);
  EXPECT_EQ(first(r, "NC2075")->span.line, 3u);
}

// Each tool change is checked: T1 and T2 both cut without G43, two warnings (lines 3 and 7).
TEST(ToolChangeWithoutLengthOffset, EachChangeIsCheckedAgain) {
  auto r = run("T1 M06\nG90 G00 X0 Y0 Z5.\nG01 Z-1. F100.\nG00 Z50.\nT2 M06\nG00 Z5.\nG01 Z-2.\nM30\n",
               machine::default_mill());
  ASSERT_EQ(count(r, "NC2075"), 2);
  std::vector<std::uint32_t> lines;
  for (const auto& w : r.result.warnings)
    if (w.code == "NC2075") lines.push_back(w.span.line);
  EXPECT_EQ(lines, (std::vector<std::uint32_t>{3, 7}));
}

// Not warned: G43 H after the change and before the cut; G43 H1 in force from before the change
// (the control keeps the mode and its H across M06: ncurve follows it); a CAM system's G01 X Y at
// the height the change left the tool, before its G43 Z; a program with no M06; a lathe, whose T
// word indexes the turret with its offset.
TEST(ToolChangeWithoutLengthOffset, LengthCompensationInForceIsClean) {
  const machine::MachineProfile mill = machine::default_mill();
  for (const char* program : {"T1 M06\nG90 G54 G00 G43 X0 Y0 Z5. H1\nG01 Z-5. F100.\nM30\n",
                              "T1 M06\nG43 H1 G00 Z50.\nG01 Z-5. F100.\nG00 Z50.\nT2 M06\nG00 X10.\nG01 Z-5.\nM30\n",
                              "T9 M06\nG01 X10. Y10. F500.\nG00 G43 Z15. H9\nG01 Z-1.\nM30\n",
                              "G90 G00 X0 Y0 Z5.\nG01 Z-5. F100.\nM30\n"}) {
    auto r = run(program, mill);
    ASSERT_TRUE(r.result.ok()) << program;
    EXPECT_EQ(count(r, "NC2075"), 0) << program;
  }
  auto lathe = run("T0101\nM06\nG00 X40. Z5.\nG01 Z-20. F0.2\nM30\n", machine::default_lathe());
  ASSERT_TRUE(lathe.result.ok());
  EXPECT_EQ(count(lathe, "NC2075"), 0);
}

// ---- NC2076: G73 / G83 with a d of 0 ----

// G83 Z-20. R2. Q5.: cuts to -3, -8, -13, -18, -20 (22 mm in cuts of 5). After each cut but the last
// the drill goes out to R2 and rapids back down to d = No.5115 short of the depth reached; with
// d = 0 (the profile's) exactly to it: to -3 after the first. Warned once for the cycle mode, at the
// G83 word (column 5), not again at the second hole (line 3).
TEST(PeckDrillingWithoutD, G83WithAClearanceOfZeroWarns) {
  auto r = run("G90 G00 X10. Y10. Z20.\nG99 G83 Z-20. R2. Q5. F100.\nX20.\nG80\nM30\n", machine::default_mill());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r, "NC2076"), 1);
  const nc::Diagnostic* w = first(r, "NC2076");
  EXPECT_EQ(w->span.line, 2u);
  EXPECT_EQ(w->span.column, 5u);
  EXPECT_TRUE(has(w->message, "G83 (peck drilling): its clearance d is 0 (No.5115 = 0 in the profile): after each "
                              "retraction to point R the drill rapids back down to the very depth the last cut reached"))
      << w->message;
  EXPECT_TRUE(has(w->message, "--param 5115=1000 (1 mm)")) << w->message;
  // the first hole: rapid to X10 Y10 (Z20), rapid to R2, feed to -3, rapid to R2, rapid to -3, feed to -8
  const auto m = r.motions();
  ASSERT_GE(m.size(), 7u);
  EXPECT_EQ(m[2].kind, machine::MoveKind::line);
  EXPECT_EQ(m[2].end[2], -3.0);
  EXPECT_EQ(m[3].end[2], 2.0);
  EXPECT_EQ(m[4].kind, machine::MoveKind::rapid);
  EXPECT_EQ(m[4].end[2], -3.0);  // d = 0: onto the bottom at rapid
  EXPECT_EQ(m[5].end[2], -8.0);
}

// G73 with No.5114 = 0: the drill does not back off; the five cuts follow one another (-3, -8, -13,
// -18, -20), with no rapid between them.
TEST(PeckDrillingWithoutD, G73WithARetractionOfZeroWarns) {
  auto r = run("G90 G00 X10. Y10. Z20.\nG73 Z-20. R2. Q5. F100.\nG80\nM30\n", machine::default_mill());
  ASSERT_TRUE(r.result.ok());
  ASSERT_EQ(count(r, "NC2076"), 1);
  const std::string w = text(r, "NC2076");
  EXPECT_TRUE(has(w, "G73 (high-speed peck drilling): its retraction d after each cut of Q is 0 (No.5114 = 0 in the "
                     "profile): the drill does not back off between the cuts"))
      << w;
  EXPECT_TRUE(has(w, "pauses every 5.000 mm")) << w;
  EXPECT_TRUE(has(w, "--param 5114=500 (0.5 mm)")) << w;
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 8u);  // to the hole, to R, five cuts, back to the initial level
  for (int i = 2; i < 7; ++i) EXPECT_EQ(m[i].kind, machine::MoveKind::line) << i;
  EXPECT_EQ(m[6].end[2], -20.0);
}

// Not warned: d set in the profile (G73 backs off 0.5, G83 stops 1 mm short); a hole of one cut
// (R2 to Z-3 is 5 mm, Q5: nothing to back off from); G81.
TEST(PeckDrillingWithoutD, ADGivenOrOneCutIsClean) {
  machine::MachineProfile p = machine::default_mill();
  p.peck_retract = 0.5;
  p.peck_clearance = 1.0;
  auto set = run("G90 G00 X10. Y10. Z20.\nG73 Z-20. R2. Q5. F100.\nG83 X20. Z-20. R2. Q5.\nG80\nM30\n", p);
  ASSERT_TRUE(set.result.ok());
  EXPECT_EQ(count(set, "NC2076"), 0);
  const machine::MachineProfile mill = machine::default_mill();
  for (const char* program : {"G90 G00 X10. Y10. Z20.\nG83 Z-3. R2. Q5. F100.\nG73 X20. Z-3. R2. Q5.\nG80\nM30\n",
                              "G90 G00 X10. Y10. Z20.\nG81 Z-20. R2. F100.\nG80\nM30\n"}) {
    auto r = run(program, mill);
    ASSERT_TRUE(r.result.ok()) << program;
    EXPECT_EQ(count(r, "NC2076"), 0) << program;
  }
}

// A lathe's face drilling G83 with Q: No.5101#2 RTR = 0 pecks at high speed, backing off d =
// No.5114; RTR = 1 goes out to R and back to d = No.5115 short. From Z10, R-7 puts point R at Z3;
// Z-20 in cuts of Q6000 (6 mm): 23 mm, four cuts.
TEST(PeckDrillingWithoutD, ALathePecksByItsRtrBit) {
  const std::string program = "G21 G99 G00 X0. Z10.\nG83 Z-20. R-7. Q6000 F0.1\nG80\nM30\n";
  auto high = run(program, machine::default_lathe());
  ASSERT_TRUE(high.result.ok());
  ASSERT_EQ(count(high, "NC2076"), 1);
  EXPECT_TRUE(has(text(high, "NC2076"), "G83 with Q (high-speed peck drilling, No.5101#2 RTR = 0): its retraction d "
                                        "after each cut of Q is 0 (No.5114 = 0 in the profile)"))
      << text(high, "NC2076");
  machine::MachineProfile to_r = machine::default_lathe();
  to_r.drilling.lathe_peck_to_r = true;
  auto peck = run(program, to_r);
  ASSERT_EQ(count(peck, "NC2076"), 1);
  EXPECT_TRUE(has(text(peck, "NC2076"), "G83 with Q (peck drilling, No.5101#2 RTR = 1): its clearance d is 0 (No.5115"))
      << text(peck, "NC2076");
  to_r.peck_clearance = 1.0;
  EXPECT_EQ(count(run(program, to_r), "NC2076"), 0);
}

// ---- a spindle speed over the machine's limit (NC2090) ----

namespace {
machine::MachineProfile with_parameters(machine::MachineProfile p,
                                        const std::vector<std::pair<std::string, double>>& values) {
  for (const auto& [key, value] : values) machine::set_parameter(p, key, value);
  return p;
}
}  // namespace

// No.3772 = 4000: S6000 is clamped at 4000 rev/min. G95 X30. F0.1 from X0 then feeds 0.1 mm/rev x
// 4000 rev/min = 400 mm/min, so 30 mm take 30 / 400 min = 4.5 s (3 s at the 6000 programmed). One
// warning, at the S block (line 2), naming the clamp and the parameter.
TEST(SpindleOverTheLimit, AnSOverNo3772IsClampedAndWarned) {
  const auto mill = with_parameters(test::zero_offset_mill(), {{"3772", 4000}});
  auto r = run("G00 X0 Y0\nS6000 M03\nG95 G01 X30. F0.1\nX0\nM30\n", mill);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(count(r, "NC2090"), 1);
  ASSERT_NE(first(r, "NC2090"), nullptr);
  EXPECT_EQ(first(r, "NC2090")->span.line, 2u);
  EXPECT_EQ(first(r, "NC2090")->span.column, 1u);  // the S word
  EXPECT_TRUE(has(text(r, "NC2090"), "clamps the spindle at 4000 rev/min (No.3772")) << text(r, "NC2090");
  EXPECT_TRUE(has(text(r, "NC2090"), "the cut runs slower than programmed, its feed per tooth higher"));
  const auto m = r.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_NEAR(m[1].seconds, 4.5, 1e-9);
  EXPECT_NEAR(m[2].seconds, 4.5, 1e-9);
}

// At the limit exactly (S4000 with No.3772 = 4000) and with no limit set (factory No.3772 = 0 and no
// gear maxima): no warning; 30 mm at 0.1 mm/rev take 30 / 400 min = 4.5 s and 30 / 600 min = 3 s.
TEST(SpindleOverTheLimit, AtTheLimitOrWithNoLimitIsClean) {
  const std::string program = "G00 X0 Y0\nS{} M03\nG95 G01 X30. F0.1\nM30\n";
  auto at = run(fmt::format(fmt::runtime(program), 4000), with_parameters(test::zero_offset_mill(), {{"3772", 4000}}));
  ASSERT_TRUE(at.result.ok());
  EXPECT_EQ(count(at, "NC2090"), 0);
  EXPECT_NEAR(at.motions()[1].seconds, 4.5, 1e-9);
  auto none = run(fmt::format(fmt::runtime(program), 6000));
  ASSERT_TRUE(none.result.ok());
  EXPECT_EQ(count(none, "NC2090"), 0);
  EXPECT_NEAR(none.motions()[1].seconds, 3.0, 1e-9);
}

// Type M gear selection picks the lowest gear whose maximum (No.3741..3744) covers S; an S over the
// top gear's maximum turns at it. Gears 1500 and 4500 rev/min: S2000 runs in gear 2 (clean), S6000 at
// 4500 (No.3742). With No.3772 = 4000 too, the lower of the two, 4000, holds.
TEST(SpindleOverTheLimit, TheTopGearsMaximumClampsWithoutNo3772) {
  const auto gears = with_parameters(test::zero_offset_mill(), {{"3741", 1500}, {"3742", 4500}});
  auto in_gear = run("S2000 M03\nM30\n", gears);
  EXPECT_EQ(count(in_gear, "NC2090"), 0);
  auto over = run("S6000 M03\nM30\n", gears);
  EXPECT_EQ(count(over, "NC2090"), 1);
  EXPECT_TRUE(has(text(over, "NC2090"), "at 4500 rev/min (No.3742, the maximum speed of gear 2)"))
      << text(over, "NC2090");
  auto both = run("S6000 M03\nM30\n", with_parameters(gears, {{"3772", 4000}}));
  EXPECT_TRUE(has(text(both, "NC2090"), "at 4000 rev/min (No.3772")) << text(both, "NC2090");
}

// A lathe with No.3772 = 2000 facing X60 -> X10 (radius 30 -> 5) at F0.2 under G96 S100 and no G50 S:
// the speed 1000 x 100 / (2 pi r) reaches 1000 x 100 / (2 pi 5) = 3183 rev/min at the centre end, so
// the control clamps it at 2000 below rc = 100000 / (2 pi 2000) = 25 / pi = 7.9577 mm:
// t = 300 [(7.9577 - 5) / 2000 + pi (30^2 - 7.9577^2) / 100000] = 0.4437 + 7.8855 = 8.3291 s.
// A G50 S3000 over the limit changes nothing (the lower, 2000, holds; warned); G50 S1500 under it is
// the program's own clamp (not warned). A cut that stays above rc (X60 -> X40) is clean.
TEST(SpindleOverTheLimit, SurfaceSpeedPastTheLimitIsClampedAndWarned) {
  const auto lathe = with_parameters(machine::default_lathe(), {{"3772", 2000}});
  const double rc = 25 / std::numbers::pi;
  const double want = 300 * ((rc - 5) / 2000 + std::numbers::pi * (30 * 30 - rc * rc) / 100000);
  EXPECT_NEAR(want, 8.3291, 1e-4);
  auto r = run("G99 G00 X60. Z0\nG96 S100 M03\nG01 X10. F0.2\nM30\n", lathe);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(count(r, "NC2090"), 1);
  ASSERT_NE(first(r, "NC2090"), nullptr);
  EXPECT_EQ(first(r, "NC2090")->span.line, 3u);
  EXPECT_TRUE(has(text(r, "NC2090"), "G96 S100 asks 3183 rev/min here, over the machine's limit")) << text(r, "NC2090");
  EXPECT_NEAR(r.motions()[1].seconds, want, 1e-9);
  auto g50_over = run("G99 G00 X60. Z0\nG50 S3000\nG96 S100 M03\nG01 X10. F0.2\nM30\n", lathe);
  EXPECT_EQ(count(g50_over, "NC2090"), 1);
  EXPECT_NEAR(g50_over.motions()[1].seconds, want, 1e-9);
  auto g50_under = run("G99 G00 X60. Z0\nG50 S1500\nG96 S100 M03\nG01 X10. F0.2\nM30\n", lathe);
  EXPECT_EQ(count(g50_under, "NC2090"), 0);
  auto outside = run("G99 G00 X60. Z0\nG96 S100 M03\nG01 X40. F0.2\nM30\n", lathe);
  EXPECT_EQ(count(outside, "NC2090"), 0);
  auto g97 = run("G97 S2000 M03\nG99 G01 X10. F0.2\nM30\n", lathe);  // at the limit in G97
  EXPECT_EQ(count(g97, "NC2090"), 0);
}

// An arc under G96 from X60 Z0 to Z-50 with R25 (centre at radius 30, Z-25): G02 (clockwise seen from
// +Y, X up and Z right) bows towards the centre line, down to radius 5, where the speed would be
// 3183 rev/min, over No.3772 = 2000: warned. G03 bows away, to radius 55, its nearest point at the
// ends, radius 30: 1000 x 100 / (2 pi 30) = 531 rev/min, clean.
TEST(SpindleOverTheLimit, AnArcIsCheckedWhereItComesNearestTheCentre) {
  const auto lathe = with_parameters(machine::default_lathe(), {{"3772", 2000}});
  auto in = run("G99 G00 X60. Z0\nG96 S100 M03\nG02 Z-50. R25. F0.2\nM30\n", lathe);
  ASSERT_TRUE(in.result.ok()) << nc::format(*in.result.alarm);
  EXPECT_EQ(count(in, "NC2090"), 1);
  EXPECT_TRUE(has(text(in, "NC2090"), "asks 3183 rev/min")) << text(in, "NC2090");
  auto out = run("G99 G00 X60. Z0\nG96 S100 M03\nG03 Z-50. R25. F0.2\nM30\n", lathe);
  ASSERT_TRUE(out.result.ok());
  EXPECT_EQ(count(out, "NC2090"), 0);
}

TEST(SpindleOverTheLimit, TheParametersAreWholeSpeeds) {
  machine::MachineProfile p = machine::default_mill();
  EXPECT_THROW(machine::set_parameter(p, "3772", -1), std::runtime_error);
  EXPECT_THROW(machine::set_parameter(p, "3741", 1500.5), std::runtime_error);
  machine::set_parameter(p, "3744", 8000);
  EXPECT_EQ(p.gear_max_speed[3], 8000);
  EXPECT_EQ(p.spindle_limit(), 8000);
}
