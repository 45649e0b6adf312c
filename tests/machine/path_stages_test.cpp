// The path stages (src/machine/path/) alone, without an Interpreter: hand-made moves in, what
// reaches a recording sink out, against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "machine/path/nose_centre.hpp"
#include "machine/path/statistics.hpp"
#include "machine/path/stroke_check.hpp"

using namespace ncurve::machine;

namespace {

constexpr double kPi = std::numbers::pi;

// What reaches the end of the chain, in order: "setup" or the move's kind.
struct Recorder final : MoveSink {
  std::vector<Move> moves;
  std::vector<Setup> setups;
  std::vector<std::string> order;
  void on_move(const Move& m) override {
    moves.push_back(m);
    order.push_back(to_string(m.kind));
  }
  void on_setup(const Setup& s) override {
    setups.push_back(s);
    order.push_back("setup");
  }
};

// The control's setup the statistics read.
struct FixedSetup {
  Setup now;
  operator SetupView() const { return {&now.work, &now.origin, &now.length_comp, &now.h}; }
};

Move motion(MoveKind kind, AxisVector from, AxisVector to, double length, double seconds, std::uint32_t line = 1) {
  Move m;
  m.kind = kind;
  m.start = from;
  m.end = to;
  m.length = length;
  m.seconds = seconds;
  m.line = line;
  return m;
}

// The alarm callback of a stage: records the alarm, then stops the run as the Executor's does.
struct Raised {
  std::string code, message;
  std::uint32_t line = 0;
};
struct Stopped : std::runtime_error {
  Stopped() : std::runtime_error("alarm") {}
};
MoveAlarm recording_alarm(Raised& raised) {
  return [&raised](const Move& at, const std::string& code, const std::string& message) {
    raised = {code, message, at.line};
    throw Stopped();
  };
}

// Machine = work + shift; positions shown in mm as they are.
struct ShiftedFrame final : StrokeFrame {
  AxisVector shift{};
  AxisVector machine_shift() const override { return shift; }
  double program_units(int, double mm) const override { return mm; }
};

constexpr double kInf = std::numeric_limits<double>::infinity();

// No limit 1, no area: nothing in force.
StrokeLimits no_limits() {
  StrokeLimits l;
  l.limit1_plus.fill(kInf);
  l.limit1_minus.fill(-kInf);
  l.area_axes = 0b111;
  l.switch_area(false);
  return l;
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
  limits.switch_area(false);
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
  limits.switch_area(false);
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
  limits.switch_area(true);
  ASSERT_TRUE(limits.in_force);
  ShiftedFrame frame;
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
  limits.switch_area(true);
  ShiftedFrame frame;
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
  limits.switch_area(false);
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
  limits.switch_area(true);
  EXPECT_FALSE(limits.in_force);
}

// The profile's limits at power-on: limit 1 where plus >= minus, on the machine's axes; the area
// with its corners in order; check 2 on unless No.3402#7 turns it off.
TEST(PathStrokeCheck, PowerOnLimits) {
  MachineProfile p;
  p.stroke1_plus = {200, 100, 0, 0, 0, 0};
  p.stroke1_minus = {-200, 300, 0, 0, 0, 0};  // Y: plus below minus, no limit
  p.stroke2_plus = {-10, 0, 0, 0, 0, 0};
  p.stroke2_minus = {10, 0, 0, 0, 0, 0};
  std::array<bool, kAxes> has{true, true, true, false, false, false};
  const StrokeLimits l = StrokeLimits::power_on(p, has);
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
