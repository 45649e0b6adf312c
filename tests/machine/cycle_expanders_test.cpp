// The cycles' expanders (src/machine/cycles/hole_cycles.*, turning.*) alone, without an interpreter:
// the cycle's data given by hand, the moves recorded and compared with the cycle descriptions of the
// FANUC 0i-MF / 0i-TF / 30i-B operator's manuals ("Canned cycle for drilling", "Rigid tapping",
// "Single cutting cycle", "Multiple threading cycle"), worked out by hand.
#include "machine/cycles/hole_cycles.hpp"
#include "machine/cycles/turning.hpp"

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace ncurve::machine;

namespace {

// Records each output as a line: "R x y z" rapid, "F x y z" feed, "T x y z lead angle" thread cut,
// "D s" dwell, "S m" spindle, "M m", "STOP", "HAND x y z" (the operator's return), "AT"
// (positioned), "RET" (returning).
struct Recorder : CycleOutput {
  AxisVector at{};
  std::vector<std::string> got;

  static std::string xyz(const AxisVector& v) { return fmt::format("{:g} {:g} {:g}", v[0], v[1], v[2]); }
  AxisVector position() const override { return at; }
  void rapid(const AxisVector& to) override { got.push_back("R " + xyz(at = to)); }
  void feed(const AxisVector& to) override { got.push_back("F " + xyz(at = to)); }
  void thread(const AxisVector& to, double lead, double angle) override {
    got.push_back(fmt::format("T {} {:g} {:g}", xyz(at = to), lead, angle));
  }
  void dwell(double s) override { got.push_back(fmt::format("D {:g}", s)); }
  void spindle(int m) override { got.push_back(fmt::format("S {}", m)); }
  void m_code(int m) override { got.push_back(fmt::format("M {}", m)); }
  void program_stop() override { got.push_back("STOP"); }
  void manual_return(const AxisVector& to) override { got.push_back("HAND " + xyz(at = to)); }
  void positioned() override { got.push_back("AT"); }
  void returning() override { got.push_back("RET"); }
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

// A C axis with roll-over given back within one turn after each move, as the control keeps it: the
// moves after the positioning are made from where the output says the tool is.
TEST(DrillExpander, RotaryRollOverIsReadBack) {
  struct Rolling : Recorder {
    std::vector<double> c;
    void rapid(const AxisVector& to) override {
      Recorder::rapid(to);
      at[5] = std::fmod(at[5], 360.0);
      c.push_back(at[5]);
    }
    void feed(const AxisVector& to) override {
      Recorder::feed(to);
      c.push_back(to[5]);
    }
  } out;
  drill::Hole h;
  h.code = 83;
  h.axis = 2;
  h.at = {0, 0, 0, 0, 0, 370};
  h.initial = 20;
  h.r = 2;
  h.z = -10;
  out.at = {0, 0, 20, 0, 0, 0};
  drill::lathe_hole(h, {}, out);
  EXPECT_EQ(out.got, (Lines{"R 0 0 20", "R 0 0 2", "F 0 0 -10", "R 0 0 20"}));
  EXPECT_EQ(out.c, (std::vector<double>{10, 10, 10, 10}));
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

namespace {
// A lathe cycle from A at X30 (a radius) Z5.
std::vector<std::string> turned(const turn::SingleCycle& c, AxisVector a = {30, 0, 5}) {
  Recorder out;
  out.at = a;
  turn::single_cycle(c, out);
  return out.got;
}
turn::SingleCycle single(int code, double x, double z, double r = 0) {
  turn::SingleCycle c;
  c.code = code;
  c.end = {x, 0, z, 0, 0, 0};
  c.r = r;
  return c;
}
}  // namespace

// G90 X20 Z-30: (1) rapid X to 20, (2) feed Z to -30, (3) feed X back to 30, (4) rapid Z back to 5.
// With R-5 the cut starts 5 below the end's X: a taper.
TEST(TurningExpander, G90) {
  EXPECT_EQ(turned(single(90, 20, -30)), (Lines{"R 20 0 5", "F 20 0 -30", "F 30 0 -30", "RET", "R 30 0 5"}));
  EXPECT_EQ(turned(single(90, 20, -30, -5)), (Lines{"R 15 0 5", "F 20 0 -30", "F 30 0 -30", "RET", "R 30 0 5"}));
}

// G94 X10 Z-2: (1) rapid Z to -2, (2) feed X to 10, (3) feed Z back to 5, (4) rapid X back to 30;
// the face cut starts 3 below the end's Z.
TEST(TurningExpander, G94) {
  EXPECT_EQ(turned(single(94, 10, -2)), (Lines{"R 30 0 -2", "F 10 0 -2", "F 10 0 5", "RET", "R 30 0 5"}));
  EXPECT_EQ(turned(single(94, 10, -2, -3)), (Lines{"R 30 0 -5", "F 10 0 -2", "F 10 0 5", "RET", "R 30 0 5"}));
}

// A at the end point's X: (1) makes no move.
TEST(TurningExpander, NoMoveWhereTheToolIs) {
  EXPECT_EQ(turned(single(90, 30, -30)), (Lines{"F 30 0 -30", "RET", "R 30 0 5"}));
}

// G92 X9 Z-20 F1.5 from X15: (2) a thread cut at the lead, (3) a rapid out to A's X. With a chamfer
// of 1.0 lead (r = 10) at F2: the thread leaves 2 mm before Z-20 and reaches Z-20 2 * tan 45 = 2 out
// (No.5131 = 60: 2 * tan 60 = 3.4641 out); the spindle angle Q is the first cut's alone.
TEST(TurningExpander, G92Threading) {
  auto c = single(92, 9, -20);
  c.thread.lead = 1.5;
  EXPECT_EQ(turned(c, {15, 0, 5}), (Lines{"R 9 0 5", "T 9 0 -20 1.5 0", "R 15 0 -20", "RET", "R 15 0 5"}));
  c.thread = {2, 10, 0};
  c.start_angle = 90;
  EXPECT_EQ(turned(c, {15, 0, 5}),
            (Lines{"R 9 0 5", "T 9 0 -18 2 90", "T 11 0 -20 2 -1", "R 15 0 -20", "RET", "R 15 0 5"}));
  c.thread.chamfer_angle = 60;
  EXPECT_EQ(turned(c, {15, 0, 5})[2], "T 12.4641 0 -20 2 -1");
}

// The side of the first cut that A lies on, for the cycle's own nose radius offset: turning an outer
// diameter towards the chuck (-Z) from above is G42 (right), facing towards the centre G41 (left).
TEST(TurningExpander, StartSide) {
  EXPECT_EQ(turn::start_side(single(90, 20, -30), {30, 0, 5}), -1);
  EXPECT_EQ(turn::start_side(single(94, 10, -2), {30, 0, 5}), 1);
  EXPECT_EQ(turn::start_side(single(90, 20, 5), {30, 0, 5}), 0);
}

// G76 depths, k = 1, Δd = 0.35, dmin = 0.1, d = 0.05, m = 2: Δd * sqrt(n) while each cut is at least
// dmin: 0.35, 0.49497 (sqrt 2), 0.60622 (sqrt 3), then dmin steps 0.70622, 0.80622, 0.90622, the
// next (1.00622) stopped at k - d = 0.95; two finishing passes at k.
TEST(TurningExpander, G76Depths) {
  turn::MultipleThreading c;
  c.height = 1;
  c.first = 0.35;
  c.min_depth = 0.1;
  c.allowance = 0.05;
  c.finish_count = 2;
  const std::vector<double> want = {0.35, 0.494975, 0.606218, 0.706218, 0.806218, 0.906218, 0.95, 1, 1};
  const auto got = turn::thread_depths(c);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-6) << i;
  c.first = 1e-9;
  c.min_depth = 0;
  EXPECT_THROW(turn::thread_depths(c), turn::TooManyPasses);
}

// G76 passes from A X12 Z5 to the root X8.8 Z-20, k = 1, tool angle 60: a pass at depth d starts
// (k - d) above the root and (k - d) * tan 30 back along Z (single edge cutting along the flank),
// cuts, rapids out to A's X and back to A. Depth 0.5: X9.3, Z shift 0.288675.
TEST(TurningExpander, G76Passes) {
  turn::MultipleThreading c;
  c.end = {8.8, 0, -20, 0, 0, 0};
  c.height = 1;
  c.tool_angle = 60;
  c.thread.lead = 1.5;
  Recorder out;
  out.at = {12, 0, 5};
  turn::multiple_threading(c, {0.5, 1}, out);
  EXPECT_EQ(out.got, (Lines{"R 9.3 0 5.28868", "T 9.3 0 -19.7113 1.5 0", "R 12 0 -19.7113", "R 12 0 5",
                            "R 8.8 0 5", "T 8.8 0 -20 1.5 0", "R 12 0 -20", "R 12 0 5"}));
  c.taper = -1;  // R(i): the start of each cut 1 lower
  out.got.clear();
  turn::multiple_threading(c, {1}, out);
  EXPECT_EQ(out.got, (Lines{"R 7.8 0 5", "T 8.8 0 -20 1.5 0", "R 12 0 -20", "R 12 0 5"}));
}
