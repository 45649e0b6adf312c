// The drilling cycles' expanders (src/machine/cycles/hole_cycles.*) alone, without an interpreter:
// hole data given by hand, the moves recorded and compared with the cycle descriptions of the FANUC
// 0i-MF / 0i-TF / 30i-B operator's manuals ("Canned cycle for drilling", "Rigid tapping"), worked
// out by hand.
#include "machine/cycles/hole_cycles.hpp"

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <vector>

using namespace ncurve::machine;

namespace {

// Records each output as a line: "R x y z" rapid, "F x y z" feed, "D s" dwell, "S m" spindle,
// "M m", "STOP", "HAND x y z" (the operator's return), "AT" (positioned).
struct Recorder final : CycleOutput {
  AxisVector at{};
  std::vector<std::string> got;

  static std::string xyz(const AxisVector& v) { return fmt::format("{:g} {:g} {:g}", v[0], v[1], v[2]); }
  AxisVector position() const override { return at; }
  void rapid(const AxisVector& to) override { got.push_back("R " + xyz(at = to)); }
  void feed(const AxisVector& to) override { got.push_back("F " + xyz(at = to)); }
  void dwell(double s) override { got.push_back(fmt::format("D {:g}", s)); }
  void spindle(int m) override { got.push_back(fmt::format("S {}", m)); }
  void m_code(int m) override { got.push_back(fmt::format("M {}", m)); }
  void program_stop() override { got.push_back("STOP"); }
  void manual_return(const AxisVector& to) override { got.push_back("HAND " + xyz(at = to)); }
  void positioned() override { got.push_back("AT"); }
};

// A hole drilled along Z at X10 Y20 from the tool at X0 Y0 Z50: R2, Z-10.
drill::Hole hole(int code) {
  drill::Hole h;
  h.code = code;
  h.at = {10, 20, 0, 0, 0, 0};
  h.axis = 2;
  h.initial = 50;
  h.r = 2;
  h.z = -10;
  return h;
}

std::vector<std::string> mill(const drill::Hole& h, const drill::Parameters& p = {}, AxisVector from = {0, 0, 50}) {
  Recorder out;
  out.at = from;
  drill::mill_hole(h, p, out);
  return out.got;
}

using Lines = std::vector<std::string>;

}  // namespace

// G81: positioning to X Y, rapid to R, feed to Z, rapid out (G98: the initial level).
TEST(DrillExpander, G81G98) {
  EXPECT_EQ(mill(hole(81)), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "R 10 20 50"}));
}

TEST(DrillExpander, G81G99EndsAtPointR) {
  auto h = hole(81);
  h.return_initial = false;
  EXPECT_EQ(mill(h), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "R 10 20 2"}));
}

// Already over the hole and at point R (G99, second hole of a row): no positioning, no rapid to R.
TEST(DrillExpander, NoMoveWhereTheToolIs) {
  auto h = hole(81);
  h.return_initial = false;
  EXPECT_EQ(mill(h, {}, {10, 20, 2}), (Lines{"AT", "F 10 20 -10", "R 10 20 2"}));
}

// G82 and G89: a dwell at the bottom; G89 then feeds back out to R.
TEST(DrillExpander, G82G89DwellAtTheBottom) {
  auto h = hole(82);
  h.p = 1.5;
  EXPECT_EQ(mill(h), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "D 1.5", "R 10 20 50"}));
  h.code = 89;
  EXPECT_EQ(mill(h), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "D 1.5", "F 10 20 2", "R 10 20 50"}));
}

// G85: feed in and feed out to R; G86: the spindle stops at the bottom, starts again when out.
TEST(DrillExpander, G85G86) {
  EXPECT_EQ(mill(hole(85)), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "F 10 20 2", "R 10 20 50"}));
  EXPECT_EQ(mill(hole(86)),
            (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "S 5", "R 10 20 50", "S 3"}));
}

// G73, Q4, d = 0.5 (No.5114): cuts of q, each followed by a retraction of d.
// 2 -> -2, back to -1.5, -> -6, back to -5.5, -> -10 (the last cut is shorter).
TEST(DrillExpander, G73HighSpeedPeck) {
  auto h = hole(73);
  h.q = 4;
  drill::Parameters p;
  p.peck_retract = 0.5;
  p.peck_clearance = 9;  // G83's: not used
  EXPECT_EQ(mill(h, p), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -2", "R 10 20 -1.5", "F 10 20 -6",
                               "R 10 20 -5.5", "F 10 20 -10", "R 10 20 50"}));
}

// G83, Q4, d = 1 (No.5115): after each cut out to R, then a rapid down to d short of the depth reached.
TEST(DrillExpander, G83PeckOutToR) {
  auto h = hole(83);
  h.q = 4;
  drill::Parameters p;
  p.peck_clearance = 1;
  p.peck_retract = 9;  // G73's: not used
  EXPECT_EQ(mill(h, p), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -2", "R 10 20 2", "R 10 20 -1",
                               "F 10 20 -6", "R 10 20 2", "R 10 20 -5", "F 10 20 -10", "R 10 20 50"}));
}

// Drilling upwards (Z above R: the drilling axis's other direction) pecks the same way.
TEST(DrillExpander, G73Upwards) {
  auto h = hole(73);
  h.initial = -50;
  h.r = -2;
  h.z = 5;
  h.q = 4;
  drill::Parameters p;
  p.peck_retract = 1;
  EXPECT_EQ(mill(h, p, {0, 0, -50}), (Lines{"R 10 20 -50", "AT", "R 10 20 -2", "F 10 20 2", "R 10 20 1",
                                            "F 10 20 5", "R 10 20 -50"}));
}

// G76: at the bottom an oriented spindle stop (M19), a shift of Q away from the tool tip, out, the
// shift back, the spindle on. No.5101 RD2 RD1 = 00: +X in G17; 01: -X; 10: +Y; 11: -Y.
TEST(DrillExpander, G76ShiftsOffTheWall) {
  auto h = hole(76);
  h.q = 0.5;
  h.return_initial = false;
  EXPECT_EQ(mill(h), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "S 19", "R 10.5 20 -10",
                            "R 10.5 20 2", "R 10 20 2", "S 3"}));
  drill::Parameters p;
  p.drilling.shift_direction = 1;
  EXPECT_EQ(mill(h, p)[5], "R 9.5 20 -10");
  p.drilling.shift_direction = 2;
  EXPECT_EQ(mill(h, p)[5], "R 10 20.5 -10");
  p.drilling.shift_direction = 3;
  EXPECT_EQ(mill(h, p)[5], "R 10 19.5 -10");
  h.p = 2;  // a dwell at the bottom before the stop
  EXPECT_EQ(mill(h)[4], "D 2");
}

// G18: Y drills; the shift is along the plane's first axis, Z (+Z for RD2 RD1 = 00).
TEST(DrillExpander, G76ShiftInG18) {
  drill::Hole h;
  h.code = 76;
  h.axis = 1;
  h.at = {10, 0, 30, 0, 0, 0};
  h.initial = 50;
  h.r = 2;
  h.z = -10;
  h.q = 1;
  EXPECT_EQ(mill(h, {}, {10, 50, 30}),
            (Lines{"AT", "R 10 2 30", "F 10 -10 30", "S 19", "R 10 -10 31", "R 10 50 31", "R 10 50 30", "S 3"}));
}

// G87 back boring: oriented stop and shift at the initial level, rapid down to R (below the work),
// shift back, spindle on, feed up to Z, oriented stop, shift, out to the initial level (G99 too),
// shift back, spindle on.
TEST(DrillExpander, G87BacksThroughTheHole) {
  auto h = hole(87);
  h.r = -20;
  h.z = -5;
  h.q = 1;
  h.return_initial = false;
  EXPECT_EQ(mill(h), (Lines{"R 10 20 50", "AT", "S 19", "R 11 20 50", "R 11 20 -20", "R 10 20 -20", "S 3",
                            "F 10 20 -5", "S 19", "R 11 20 -5", "R 11 20 50", "R 10 20 50", "S 3"}));
}

// G88: at the bottom a dwell, the spindle stops, the program stops; the operator brings the tool to R
// by hand, cycle start turns the spindle on and the tool goes to the return level.
TEST(DrillExpander, G88StopsForTheOperator) {
  auto h = hole(88);
  h.p = 1;
  EXPECT_EQ(mill(h), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "D 1", "S 5", "STOP", "HAND 10 20 2",
                            "S 3", "R 10 20 50"}));
}

// G84 with a floating holder: feed to Z, dwell, M05, M04, feed out to R, dwell, M05, M03, rapid out.
// No.5101#6 M5T = 1: no M05 before the reversal. G74 turns the other way.
TEST(DrillExpander, G84G74Tapping) {
  auto h = hole(84);
  h.p = 0.5;
  h.return_initial = false;
  EXPECT_EQ(mill(h), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "D 0.5", "S 5", "S 4", "F 10 20 2",
                            "D 0.5", "S 5", "S 3"}));
  h.code = 74;
  h.p = 0;
  drill::Parameters p;
  p.drilling.tap_without_m05 = true;
  EXPECT_EQ(mill(h, p), (Lines{"R 10 20 50", "AT", "R 10 20 2", "F 10 20 -10", "S 3", "F 10 20 2", "S 4"}));
}

// Rigid G84: spindle forward, feed to Z, stop, dwell, reverse, feed out to R, stop, dwell, rapid out.
TEST(DrillExpander, RigidTapping) {
  auto h = hole(84);
  h.rigid = true;
  h.p = 0.25;
  EXPECT_EQ(mill(h), (Lines{"R 10 20 50", "AT", "R 10 20 2", "S 3", "F 10 20 -10", "S 5", "D 0.25", "S 4",
                            "F 10 20 2", "S 5", "D 0.25", "R 10 20 50"}));
}

// Peck rigid tapping, Q5, d = 1 (No.5213). High-speed (No.5200#5 PCP = 0): back by d after each cut
// (2 -> -3, back to -2, -> -8, back to -7, -> -10). Peck (PCP = 1): out to R, down to d short.
TEST(DrillExpander, PeckRigidTapping) {
  auto h = hole(74);
  h.rigid = true;
  h.q = 5;
  h.return_initial = false;
  drill::Parameters p;
  p.drilling.rigid_return = 1;
  EXPECT_EQ(mill(h, p), (Lines{"R 10 20 50", "AT", "R 10 20 2", "S 4", "F 10 20 -3", "S 3", "F 10 20 -2", "S 4",
                               "F 10 20 -8", "S 3", "F 10 20 -7", "S 4", "F 10 20 -10", "S 5", "S 3",
                               "F 10 20 2", "S 5"}));
  p.drilling.peck_to_r = true;
  EXPECT_EQ(mill(h, p), (Lines{"R 10 20 50", "AT", "R 10 20 2", "S 4", "F 10 20 -3", "S 3", "F 10 20 2", "S 4",
                               "F 10 20 -2", "F 10 20 -8", "S 3", "F 10 20 2", "S 4", "F 10 20 -7",
                               "F 10 20 -10", "S 5", "S 3", "F 10 20 2", "S 5"}));
}

// K3 under G91 X10: three holes 10 apart in X; under G90 (no step) the same hole three times.
TEST(DrillExpander, RepeatsUnderG91AndG90) {
  auto h = hole(81);
  h.at = {10, 0, 0, 0, 0, 0};
  h.return_initial = false;
  Recorder out;
  out.at = {0, 0, 20};
  h.initial = 20;
  drill::mill_holes(h, 3, {10, 0, 0, 0, 0, 0}, {}, out);
  EXPECT_EQ(out.got, (Lines{"R 10 0 20", "AT", "R 10 0 2", "F 10 0 -10", "R 10 0 2", "R 20 0 2", "AT",
                            "F 20 0 -10", "R 20 0 2", "R 30 0 2", "AT", "F 30 0 -10", "R 30 0 2"}));
  Recorder same;
  same.at = {0, 0, 20};
  drill::mill_holes(h, 2, {}, {}, same);
  EXPECT_EQ(same.got, (Lines{"R 10 0 20", "AT", "R 10 0 2", "F 10 0 -10", "R 10 0 2", "AT", "F 10 0 -10",
                             "R 10 0 2"}));
}

TEST(DrillExpander, CodeWithoutACycle) {
  EXPECT_THROW(mill(hole(80)), std::invalid_argument);
  Recorder out;
  EXPECT_THROW(drill::lathe_hole(hole(81), {}, out), std::invalid_argument);
}

// A lathe's face drilling G83 along Z at X0 C90, from Z20, R to Z2, bottom Z-10, with the C-axis
// clamp M code 68 (No.5110): clamp after the positioning, unclamp (M69) at the end, then the dwell
// No.5111. No positioned(): a lathe's M codes act after the block.
TEST(DrillExpander, LatheFaceDrillingWithClamp) {
  drill::Hole h;
  h.code = 83;
  h.axis = 2;
  h.at = {0, 0, 0, 0, 0, 90};
  h.initial = 20;
  h.r = 2;
  h.z = -10;
  h.clamp_m = 68;
  h.p = 0.5;
  drill::Parameters p;
  p.drilling.c_unclamp_dwell = 0.2;
  Recorder out;
  out.at = {0, 0, 20, 0, 0, 0};
  drill::lathe_hole(h, p, out);
  EXPECT_EQ(out.got, (Lines{"R 0 0 20", "M 68", "R 0 0 2", "F 0 0 -10", "D 0.5", "R 0 0 20", "M 69", "D 0.2"}));
  EXPECT_EQ(out.at[5], 90);
}

// A lathe's G83 with Q: No.5101#2 RTR = 0 pecks as G73 (d = No.5114), 1 as G83 (d = No.5115).
TEST(DrillExpander, LathePecks) {
  drill::Hole h;
  h.code = 87;  // side drilling: along X
  h.axis = 0;
  h.at = {0, 0, -15, 0, 0, 0};
  h.initial = 30;
  h.r = 12;
  h.z = 2;
  h.q = 4;
  h.return_initial = false;
  drill::Parameters p;
  p.peck_retract = 0.5;
  p.peck_clearance = 1;
  Recorder out;
  out.at = {30, 0, -15};
  drill::lathe_hole(h, p, out);
  EXPECT_EQ(out.got, (Lines{"R 12 0 -15", "F 8 0 -15", "R 8.5 0 -15", "F 4 0 -15", "R 4.5 0 -15", "F 2 0 -15",
                            "R 12 0 -15"}));
  p.drilling.lathe_peck_to_r = true;
  out.got.clear();
  out.at = {30, 0, -15};
  drill::lathe_hole(h, p, out);
  EXPECT_EQ(out.got, (Lines{"R 12 0 -15", "F 8 0 -15", "R 12 0 -15", "R 9 0 -15", "F 4 0 -15", "R 12 0 -15",
                            "R 5 0 -15", "F 2 0 -15", "R 12 0 -15"}));
}

// A lathe's G84 taps with M03 and reverses with M04 (M05 before each reversal); G85 feeds out.
TEST(DrillExpander, LatheTappingAndBoring) {
  drill::Hole h;
  h.code = 84;
  h.axis = 2;
  h.initial = 20;
  h.r = 2;
  h.z = -10;
  Recorder out;
  out.at = {0, 0, 20};
  drill::lathe_hole(h, {}, out);
  EXPECT_EQ(out.got, (Lines{"R 0 0 2", "F 0 0 -10", "S 5", "S 4", "F 0 0 2", "S 5", "S 3", "R 0 0 20"}));
  h.code = 85;
  out.got.clear();
  drill::lathe_hole(h, {}, out);
  EXPECT_EQ(out.got, (Lines{"R 0 0 2", "F 0 0 -10", "F 0 0 2", "R 0 0 20"}));
}
