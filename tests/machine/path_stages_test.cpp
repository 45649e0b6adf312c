// The path stages at the chain's tail (src/machine/path/) alone, without an Interpreter: hand-made
// moves in, what reaches a recording sink out, against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "machine/path/developed_conversion.hpp"
#include "machine/path/nose_centre.hpp"
#include "machine/path/statistics.hpp"
#include "machine/path/stroke_check.hpp"
#include "path_stages_support.hpp"

using namespace ncurve::machine;
using namespace ncurve::machine::path_test;

namespace {

// Machine = work + shift; positions shown in mm as they are; check 2 on or off (G22/G23).
struct ShiftedFrame final : StrokeFrame {
  AxisVector shift{};
  bool area_on = false;
  AxisVector machine_shift() const override { return shift; }
  double program_units(int, double mm) const override { return mm; }
  bool area_check_on() const override { return area_on; }
};

constexpr double kInf = std::numeric_limits<double>::infinity();

// No limit 1, no area: nothing in force.
StrokeLimits no_limits() {
  StrokeLimits l;
  l.limit1_plus.fill(kInf);
  l.limit1_minus.fill(-kInf);
  l.area_axes = 0b111;
  l.update(false);
  return l;
}

// G12.1 on a machine X Y Z A B C: X the linear axis, C the rotary axis, the hypothetical axis in
// Y's slot, the G17 plane; C was at 30 degrees when G12.1 was given, Y at 5.
DevelopedMode polar_x_c() {
  DevelopedMode d;
  d.polar = true;
  d.linear = 0;
  d.rotary = 5;
  d.slot = 1;
  d.p = 0;
  d.q = 1;
  d.held = 5;
  d.angle0 = 30;
  return d;
}

}  // namespace

// A rapid of 30-40-50 mm, a 50 mm plunge at F1000 (3 s), a quarter arc of radius 40 about (30, 0)
// from (30, 40) to (-10, 0) at F100 (20 pi mm, 12 pi s) and a 2 s dwell.
TEST(PathStatistics, CountsLengthsTimeAndExtent) {
  RunStats stats;
  FixedSetup setup;
  Recorder out;
  Statistics stage(stats, setup);
  stage.link(out);
  stage.on_move(motion(MoveKind::rapid, {0, 0, 50}, {30, 40, 50}, 50, 0.1));
  stage.on_move(motion(MoveKind::line, {30, 40, 50}, {30, 40, 0}, 50, 3));
  Move arc = motion(MoveKind::arc, {30, 40, 0}, {-10, 0, 0}, 20 * kPi, 12 * kPi);
  arc.center = {30, 0, 0};
  arc.sweep = kPi / 2;
  stage.on_move(arc);
  Move dwell = motion(MoveKind::dwell, {-10, 0, 0}, {-10, 0, 0}, 0, 2);
  stage.on_move(dwell);

  EXPECT_EQ(stats.motions, 3u);
  EXPECT_EQ(stats.by_kind[static_cast<int>(MoveKind::rapid)], 1u);
  EXPECT_EQ(stats.by_kind[static_cast<int>(MoveKind::line)], 1u);
  EXPECT_EQ(stats.by_kind[static_cast<int>(MoveKind::arc)], 1u);
  EXPECT_EQ(stats.by_kind[static_cast<int>(MoveKind::dwell)], 1u);
  EXPECT_DOUBLE_EQ(stats.rapid_length, 50);
  EXPECT_DOUBLE_EQ(stats.feed_length, 50 + 20 * kPi);
  EXPECT_DOUBLE_EQ(stats.seconds, 0.1 + 3 + 12 * kPi + 2);
  ASSERT_TRUE(stats.has_extent);
  EXPECT_EQ(stats.min, (AxisVector{-10, 0, 0}));
  EXPECT_EQ(stats.max, (AxisVector{30, 40, 50}));
  ASSERT_EQ(out.moves.size(), 4u);
  EXPECT_EQ(out.moves[2].end, arc.end);
  EXPECT_EQ(out.moves[2].sweep, arc.sweep);
}

// The extent takes the points the Executor adds (an arc's quadrant points) besides the moves' ends.
TEST(PathStatistics, ExtentTakesNotedPoints) {
  RunStats stats;
  FixedSetup setup;
  Recorder out;
  Statistics stage(stats, setup);
  stage.link(out);
  stage.note_extent({0, -40, 0});  // the arc below passes the bottom of its circle
  Move arc = motion(MoveKind::arc, {-40, 0, 0}, {40, 0, 0}, 40 * kPi, 1);
  arc.sweep = kPi;
  stage.on_move(arc);
  EXPECT_EQ(stats.min, (AxisVector{-40, -40, 0}));
  EXPECT_EQ(stats.max, (AxisVector{40, 0, 0}));
}

// The sink hears the Setup before the first move, again when it changes, and after restart().
TEST(PathStatistics, SetupBeforeTheFirstMoveAndEachChange) {
  RunStats stats;
  FixedSetup setup;
  Recorder out;
  Statistics stage(stats, setup);
  stage.link(out);
  const Move line = motion(MoveKind::line, {}, {3, 4, 0}, 5, 1);
  stage.on_move(line);
  stage.on_move(line);
  setup.now.work = 2;
  setup.now.origin[2] = -100;
  stage.on_move(line);
  stage.on_move(line);
  stage.restart();
  stage.on_move(line);
  EXPECT_EQ(out.order, (std::vector<std::string>{"setup", "line", "line", "setup", "line", "line", "setup", "line"}));
  ASSERT_EQ(out.setups.size(), 3u);
  EXPECT_EQ(out.setups[0].work, 1);
  EXPECT_EQ(out.setups[1].work, 2);
  EXPECT_EQ(out.setups[1].origin[2], -100);
  EXPECT_EQ(out.setups[2], out.setups[1]);
  EXPECT_DOUBLE_EQ(stats.feed_length, 25);
}

// Limit 1 at X+100 (machine); the work zero is at machine X-50, so X160. goes to machine X110:
// OT0500 at the block of the move, naming the machine position and the limit; nothing reaches the sink.
TEST(PathStrokeCheck, Limit1AlarmsAtTheMovesBlock) {
  StrokeLimits limits = no_limits();
  limits.limit1_plus[0] = 100;
  limits.update(false);
  ASSERT_TRUE(limits.in_force);
  ShiftedFrame frame;
  frame.shift[0] = -50;
  Raised raised;
  Recorder out;
  StrokeCheck stage(limits, frame, recording_alarm(raised));
  stage.link(out);
  stage.on_move(motion(MoveKind::line, {0, 0, 0}, {150, 0, 0}, 150, 1, 6));  // machine X100: on the limit
  EXPECT_THROW(stage.on_move(motion(MoveKind::line, {150, 0, 0}, {160, 0, 0}, 10, 1, 7)), Stopped);
  EXPECT_EQ(raised.code, "OT0500");
  EXPECT_EQ(raised.line, 7u);
  EXPECT_NE(raised.message.find("X 110.0000"), std::string::npos) << raised.message;
  EXPECT_NE(raised.message.find("limit 100.0000"), std::string::npos) << raised.message;
  ASSERT_EQ(out.moves.size(), 1u);
  EXPECT_EQ(out.moves[0].line, 6u);
}

// A half circle of radius 10 about the zero from (10, 0) to (-10, 0), counter-clockwise, passes
// (0, 10): past a Y+ limit of 5 though both ends are at Y0. Clockwise it passes (0, -10) and stays in.
TEST(PathStrokeCheck, AnArcsQuadrantPointIsChecked) {
  StrokeLimits limits = no_limits();
  limits.limit1_plus[1] = 5;
  limits.update(false);
  ShiftedFrame frame;
  Raised raised;
  Recorder out;
  StrokeCheck stage(limits, frame, recording_alarm(raised));
  stage.link(out);
  Move cw = motion(MoveKind::arc, {10, 0, 0}, {-10, 0, 0}, 10 * kPi, 1, 3);
  cw.sweep = -kPi;
  cw.clockwise = true;
  stage.on_move(cw);
  Move ccw = cw;
  ccw.sweep = kPi;
  ccw.clockwise = false;
  ccw.line = 4;
  EXPECT_THROW(stage.on_move(ccw), Stopped);
  EXPECT_EQ(raised.code, "OT0500");
  EXPECT_EQ(raised.line, 4u);
  EXPECT_NE(raised.message.find("Y 10.0000"), std::string::npos) << raised.message;
  EXPECT_EQ(out.moves.size(), 1u);
}

// Check 2 with the inside forbidden (No.1300#0 = 0), the area X0..10 Y0..10 Z-1..1: a line along
// Y5 from X-5 enters it through its X- face moving +X (OT0502, X+); a line along Y20 passes by.
TEST(PathStrokeCheck, EnteringTheForbiddenArea) {
  StrokeLimits limits = no_limits();
  limits.area_minus = {0, 0, -1};
  limits.area_plus = {10, 10, 1};
  limits.update(true);
  ASSERT_TRUE(limits.in_force);
  ShiftedFrame frame;
  frame.area_on = true;
  Raised raised;
  Recorder out;
  StrokeCheck stage(limits, frame, recording_alarm(raised));
  stage.link(out);
  stage.on_move(motion(MoveKind::line, {-5, 20, 0}, {15, 20, 0}, 20, 1, 2));
  EXPECT_THROW(stage.on_move(motion(MoveKind::line, {-5, 5, 0}, {15, 5, 0}, 20, 1, 3)), Stopped);
  EXPECT_EQ(raised.code, "OT0502");
  EXPECT_EQ(raised.line, 3u);
  EXPECT_EQ(raised.message.substr(0, 3), "X+ ");
  EXPECT_EQ(out.moves.size(), 1u);
}

// The outside forbidden (No.1300#0 = 1): the tool stays in X0..10 Y0..10 Z-1..1; Y-3 is past Y-.
TEST(PathStrokeCheck, LeavingTheAllowedArea) {
  StrokeLimits limits = no_limits();
  limits.area_minus = {0, 0, -1};
  limits.area_plus = {10, 10, 1};
  limits.area_outside = true;
  limits.update(true);
  ShiftedFrame frame;
  frame.area_on = true;
  Raised raised;
  Recorder out;
  StrokeCheck stage(limits, frame, recording_alarm(raised));
  stage.link(out);
  stage.on_move(motion(MoveKind::line, {1, 1, 0}, {9, 9, 0}, 8 * std::sqrt(2.0), 1, 2));
  EXPECT_THROW(stage.on_move(motion(MoveKind::line, {9, 9, 0}, {5, -3, 0}, 4 * std::sqrt(10.0), 1, 3)), Stopped);
  EXPECT_EQ(raised.code, "OT0503");
  EXPECT_EQ(raised.message.substr(0, 3), "Y- ");
}

// G23 with no limit 1: nothing in force, a move anywhere and events pass unchanged.
TEST(PathStrokeCheck, NothingInForcePassesEverything) {
  StrokeLimits limits = no_limits();
  limits.area_minus = {0, 0, -1};
  limits.area_plus = {10, 10, 1};
  limits.update(false);
  EXPECT_FALSE(limits.in_force);
  ShiftedFrame frame;
  Raised raised;
  Recorder out;
  StrokeCheck stage(limits, frame, recording_alarm(raised));
  stage.link(out);
  stage.on_move(motion(MoveKind::line, {-5, 5, 0}, {15, 5, 0}, 20, 1));
  Move event;
  event.kind = MoveKind::spindle;
  stage.on_move(event);
  ASSERT_EQ(out.moves.size(), 2u);
  EXPECT_EQ(out.moves[0].end, (AxisVector{15, 5, 0}));
  // an area without an inside forbids nothing when its inside is the forbidden part
  limits.area_plus[1] = 0;
  limits.update(true);
  EXPECT_FALSE(limits.in_force);
}

// The profile's limits at power-on: limit 1 where plus >= minus, on the machine's axes; the area
// with its corners in order.
TEST(PathStrokeCheck, PowerOnLimits) {
  MachineProfile p;
  p.stroke1_plus = {200, 100, 0, 0, 0, 0};
  p.stroke1_minus = {-200, 300, 0, 0, 0, 0};  // Y: plus below minus, no limit
  p.stroke2_plus = {-10, 0, 0, 0, 0, 0};
  p.stroke2_minus = {10, 0, 0, 0, 0, 0};
  std::array<bool, kAxes> has{true, true, true, false, false, false};
  StrokeLimits l = StrokeLimits::power_on(p, has);
  l.update(false);
  EXPECT_EQ(l.limit1_plus[0], 200);
  EXPECT_EQ(l.limit1_minus[0], -200);
  EXPECT_EQ(l.limit1_plus[1], kInf);
  EXPECT_EQ(l.limit1_minus[1], -kInf);
  EXPECT_EQ(l.limit1_plus[2], 0);  // Z: 0..0, a limit
  EXPECT_EQ(l.limit1_plus[3], kInf);  // no A axis
  EXPECT_EQ(l.area_plus[0], 10);
  EXPECT_EQ(l.area_minus[0], -10);
  EXPECT_EQ(l.area_axes, 0b111u);
  EXPECT_TRUE(l.in_force);
}

// A tip 0.4 below and left of the nose centre (tip 3, an outside turning tool, nose radius 0.4):
// the centre's path is the tip's moved +0.4 in X (radius) and Z; events stay where they are.
TEST(PathNoseCentre, ShiftsMotionsByTheTip) {
  struct Tip final : NoseTipSource {
    ncurve::geom::V2 tip{-0.4, -0.4};  // (Z, X)
    ncurve::geom::V2 nose_tip_now() const override { return tip; }
  } tip;
  Recorder out;
  NoseCentre stage(tip);
  stage.link(out);
  stage.on_move(motion(MoveKind::line, {20, 0, 0}, {20, 0, -30}, 30, 1));
  Move arc = motion(MoveKind::arc, {20, 0, -30}, {30, 0, -40}, 5 * kPi, 1);
  arc.plane = 18;
  arc.center = {30, 0, -30};
  arc.sweep = kPi / 2;
  stage.on_move(arc);
  Move event = motion(MoveKind::tool_change, {30, 0, -40}, {30, 0, -40}, 0, 0);
  stage.on_move(event);
  tip.tip = {};  // G12.1/G07.1, or no nose radius: the moves as they are
  stage.on_move(motion(MoveKind::line, {30, 0, -40}, {40, 0, -40}, 10, 1));
  ASSERT_EQ(out.moves.size(), 4u);
  EXPECT_EQ(out.moves[0].start, (AxisVector{20.4, 0, 0.4}));
  EXPECT_EQ(out.moves[0].end, (AxisVector{20.4, 0, -29.6}));
  EXPECT_EQ(out.moves[1].end, (AxisVector{30.4, 0, -39.6}));
  EXPECT_EQ(out.moves[1].center, (std::array<double, 3>{30.4, 0, -29.6}));
  EXPECT_EQ(out.moves[1].sweep, kPi / 2);
  EXPECT_EQ(out.moves[2].start, (AxisVector{30, 0, -40}));
  EXPECT_EQ(out.moves[3].start, (AxisVector{30, 0, -40}));
}

// Off, the stage passes the moves on as they are.
TEST(PathDevelopedConversion, OffPassesMovesOn) {
  Recorder out;
  DevelopedConversion stage(0.001, 1e9, no_warning());
  stage.link(out);
  EXPECT_FALSE(stage.on());
  const Move line = motion(MoveKind::line, {1, 2, 3}, {4, 5, 6}, std::sqrt(27.0), 1);
  stage.on_move(line);
  ASSERT_EQ(out.moves.size(), 1u);
  EXPECT_EQ(out.moves[0].end, line.end);
}

// G07.1 C20. (the rotary axis C beside Y, No.1022 = 6; the G19 plane Y-Z, no Y axis on the
// machine): 10 pi mm along the developed Y is a quarter of the cylinder's circumference 40 pi,
// C turns 90 degrees; Z moves as programmed. A line is one piece.
TEST(PathDevelopedConversion, CylindricalLineTurnsByArcLengthOverRadius) {
  DevelopedMode d;
  d.polar = false;
  d.rotary = 5;
  d.slot = 1;
  d.p = 1;
  d.q = 2;
  d.radius = 20;
  Recorder out;
  DevelopedConversion stage(0.001, 1e9, no_warning());
  stage.link(out);
  stage.start(d, {0, 0, 0, 0, 0, 0});
  Move line = motion(MoveKind::line, {0, 0, 0}, {0, 10 * kPi, -10}, std::hypot(10 * kPi, 10), 2, 4);
  line.feed = 100;
  stage.on_move(line);
  ASSERT_EQ(out.moves.size(), 1u);
  const Move m = out.moves[0];  // a copy: the next move may grow the vector
  EXPECT_EQ(m.kind, MoveKind::line);
  EXPECT_EQ(m.start, (AxisVector{0, 0, 0, 0, 0, 0}));
  EXPECT_NEAR(m.end[5], 90, 1e-12);
  EXPECT_EQ(m.end[1], 0);  // Y: the slot holds the developed coordinate; the machine has none
  EXPECT_EQ(m.end[2], -10);
  EXPECT_EQ(m.length, line.length);
  EXPECT_EQ(m.seconds, 2);
  EXPECT_EQ(stage.machine(), m.end);
  // an event happens where the machine is
  Move event;
  event.kind = MoveKind::coolant;
  stage.on_move(event);
  ASSERT_EQ(out.moves.size(), 2u);
  EXPECT_EQ(out.moves[1].start, m.end);
  EXPECT_EQ(out.moves[1].end, m.end);
  stage.stop();
  EXPECT_FALSE(stage.on());
}

// G12.1 with the tool at X10 C30: the line from (10, 0) to (0, 10) of the polar plane ends at
// radius 10, 90 degrees on: X10, C120. The pieces join, share out the length and the time, and
// the last carries the block's exact stop, the first its block counts.
TEST(PathDevelopedConversion, PolarLineEndsAtRadiusAndAngle) {
  Recorder out;
  DevelopedConversion stage(0.001, 1e9, no_warning());
  stage.link(out);
  stage.start(polar_x_c(), {10, 5, 0, 0, 0, 30});
  Move line = motion(MoveKind::line, {10, 0, 0}, {0, 10, 0}, 10 * std::sqrt(2.0), 6, 8);
  line.feed = 100;
  line.exact_stop = true;
  line.nc_blocks = 1;
  stage.on_move(line);
  ASSERT_GT(out.moves.size(), 2u);
  EXPECT_EQ(out.moves.front().start, (AxisVector{10, 5, 0, 0, 0, 30}));
  const Move& last = out.moves.back();
  EXPECT_NEAR(last.end[0], 10, 1e-12);
  EXPECT_NEAR(last.end[5], 120, 1e-9);
  EXPECT_EQ(last.end[1], 5);  // Y held
  double length = 0, seconds = 0;
  for (std::size_t i = 0; i < out.moves.size(); ++i) {
    const Move& p = out.moves[i];
    if (i > 0) {
      EXPECT_EQ(p.start, out.moves[i - 1].end);
    }
    EXPECT_EQ(p.exact_stop, i + 1 == out.moves.size());
    EXPECT_EQ(p.nc_blocks, i == 0 ? 1u : 0u);
    EXPECT_EQ(p.line, 8u);
    // each piece's end on the line x + y = 10 of the polar plane
    const double a = (p.end[5] - 30) * kPi / 180;
    EXPECT_NEAR(p.end[0] * std::cos(a) + p.end[0] * std::sin(a), 10, 1e-9);
    length += p.length;
    seconds += p.seconds;
  }
  EXPECT_NEAR(length, line.length, 1e-9);
  EXPECT_NEAR(seconds, 6, 1e-12);
}

// Through the centre, from (10, 0) to (-10, 0): the linear axis goes to X-10 and C holds at 30.
TEST(PathDevelopedConversion, PolarLineThroughTheCentreHoldsTheAngle) {
  Recorder out;
  DevelopedConversion stage(0.001, 1e9, no_warning());
  stage.link(out);
  stage.start(polar_x_c(), {10, 5, 0, 0, 0, 30});
  stage.on_move(motion(MoveKind::line, {10, 0, 0}, {-10, 0, 0}, 20, 1));
  ASSERT_FALSE(out.moves.empty());
  EXPECT_NEAR(out.moves.back().end[0], -10, 1e-12);
  for (const Move& p : out.moves) EXPECT_NEAR(p.end[5], 30, 1e-12);
}

// Along X1 from Y-10 to Y10 at F1000 the path passes 1 mm from the centre, where C turns at
// F / L = 1000 rad/min, 57296 deg/min: above a maximum of 1000 deg/min, warned once for the block.
TEST(PathDevelopedConversion, PolarSpeedNearTheCentreIsWarnedOnce) {
  Recorder out;
  std::vector<std::string> warned;
  DevelopedConversion stage(0.001, 1000, [&](const Move& at, const std::string& code, const std::string&) {
    warned.push_back(code + " line " + std::to_string(at.line));
  });
  stage.link(out);
  stage.start(polar_x_c(), {std::hypot(1.0, 10.0), 5, 0, 0, 0, 30});
  Move line = motion(MoveKind::line, {1, -10, 0}, {1, 10, 0}, 20, 1.2, 12);
  line.feed = 1000;
  stage.on_move(line);
  EXPECT_EQ(warned, (std::vector<std::string>{"NC2060 line 12"}));
}
