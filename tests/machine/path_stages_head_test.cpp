// The path stages at the chain's head, corner ,C ,R and compensation (src/machine/path/), alone:
// hand-made blocks' moves in, what reaches a recording sink out, against values worked by hand.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "machine/interpreter.hpp"
#include "machine/path/compensation_stage.hpp"
#include "machine/path/corner_stage.hpp"
#include "path_stages_support.hpp"

using namespace ncurve::machine;
using namespace ncurve::machine::path_test;

namespace {
// The control's side of compensation: the modes and the offset, set by the test.
struct FakeOffsets final : CompensationControl {
  int side = 0, plane = 17;
  bool suspended = false, drop = false;
  std::optional<ncurve::geom::V2> cancel;
  double radius = 0;
  OffsetModes modes() { return {&side, &suspended, &drop, &plane, &cancel}; }
  OffsetOfMove offset_of_move(const PlaneAxes&) const override { return {false, radius, std::nullopt}; }
  double rapid_seconds(const AxisVector&, const AxisVector&) const override { return 0; }
};

// The programmed square of the FANUC manual's start-up example: from (0, 0) to (20, 10), round
// (20, 10) (20, 50) (60, 50) (60, 10) clockwise, back to (0, 0) in the G40 block; each its own block.
void square_blocks(FakeOffsets& control, CompensationStage& stage, int side) {
  const AxisVector pts[] = {{0, 0, 0}, {20, 10, 0}, {20, 50, 0}, {60, 50, 0}, {60, 10, 0}, {20, 10, 0}, {0, 0, 0}};
  for (int i = 1; i < 7; ++i) {
    control.side = i == 6 ? 0 : side;
    Move m = motion(MoveKind::line, pts[i - 1], pts[i], line_length(pts[i - 1].data(), pts[i].data()), 1,
                    static_cast<std::uint32_t>(i + 1));
    m.feed = 100;
    stage.on_move(m);
    stage.end_block();
  }
  stage.compensation().finish();
}

void expect_ends(const std::vector<Move>& ms, const std::vector<std::array<double, 2>>& ends) {
  ASSERT_EQ(ms.size(), ends.size());
  for (std::size_t i = 0; i < ms.size(); ++i) {
    EXPECT_NEAR(ms[i].end[0], ends[i][0], 1e-9) << "move " << i;
    EXPECT_NEAR(ms[i].end[1], ends[i][1], 1e-9) << "move " << i;
  }
}
}  // namespace

// Off (G40, no vector), the stage passes the moves on as they are.
TEST(PathCompensation, OffPassesMovesOn) {
  FakeOffsets control;
  Recorder out;
  Raised raised;
  CompensationStage stage({}, control.modes(), control, recording_alarm(raised), no_warning());
  stage.link(out);
  EXPECT_FALSE(stage.active());
  stage.on_move(motion(MoveKind::line, {0, 0, 0}, {3, 4, 0}, 5, 1));
  ASSERT_EQ(out.moves.size(), 1u);
  EXPECT_EQ(out.moves[0].end, (AxisVector{3, 4, 0}));
  EXPECT_FALSE(out.moves[0].compensated);
}

// G41 D5 on the square (the tool outside, type A): start-up perpendicular to the first block's
// direction at its end, outer corners at the offset lines' intersections, the last block before
// G40 ends perpendicular, and the G40 block ends on the programmed point.
TEST(PathCompensation, SquareG41TypeA) {
  FakeOffsets control;
  control.radius = 5;
  Raised raised;
  Recorder out;
  CompensationStage stage({}, control.modes(), control, recording_alarm(raised), no_warning());
  stage.link(out);
  square_blocks(control, stage, 1);
  expect_ends(out.moves, {{15, 10}, {15, 55}, {65, 55}, {65, 5}, {20, 5}, {0, 0}});
  EXPECT_TRUE(out.moves[1].compensated);
  EXPECT_EQ(out.moves[1].programmed_end, (AxisVector{20, 50, 0}));
  EXPECT_EQ(out.moves[1].line, 3u);
  EXPECT_FALSE(stage.active());
}

// G42 D5 puts the tool inside: inner corners at the offset lines' intersections (25, 45), (55, 45),
// (55, 15); before G40, perpendicular to the last block at (20, 10): (20, 15). G41 with D-5 is the same.
TEST(PathCompensation, NegativeOffsetSwapsTheSide) {
  for (const auto& [side, radius] : {std::pair{-1, 5.0}, std::pair{1, -5.0}}) {
    FakeOffsets control;
    control.radius = radius;
    Raised raised;
    Recorder out;
    CompensationStage stage({}, control.modes(), control, recording_alarm(raised), no_warning());
    stage.link(out);
    square_blocks(control, stage, side);
    expect_ends(out.moves, {{25, 10}, {25, 45}, {55, 45}, {55, 15}, {20, 15}, {0, 0}});
  }
}

// In offset mode a Z plunge at (20, 50) between Y50. and X60. (a block without motion in the plane)
// happens where the tool centre is when the corner is known: at the outer corner (15, 55).
TEST(PathCompensation, AMoveOffThePlaneGoesWhereTheToolIs) {
  FakeOffsets control;
  control.radius = 5;
  Raised raised;
  Recorder out;
  CompensationStage stage({}, control.modes(), control, recording_alarm(raised), no_warning());
  stage.link(out);
  control.side = 1;
  auto block = [&](AxisVector from, AxisVector to, std::uint32_t line) {
    Move m = motion(MoveKind::line, from, to, line_length(from.data(), to.data()), 1, line);
    m.feed = 100;
    stage.on_move(m);
    EXPECT_EQ(stage.block_moved_in_plane(), from[0] != to[0] || from[1] != to[1]);
    if (!stage.block_moved_in_plane()) stage.block_without_plane_motion(m, false, false);
    stage.end_block();
  };
  block({0, 0, 0}, {20, 10, 0}, 2);
  block({20, 10, 0}, {20, 50, 0}, 3);
  block({20, 50, 0}, {20, 50, -5}, 4);
  block({20, 50, -5}, {60, 50, -5}, 5);
  stage.compensation().finish();
  ASSERT_EQ(out.moves.size(), 4u);
  EXPECT_EQ(out.moves[2].line, 4u);
  EXPECT_NEAR(out.moves[2].start[0], 15, 1e-9);
  EXPECT_NEAR(out.moves[2].start[1], 55, 1e-9);
  EXPECT_EQ(out.moves[2].start[2], 0);
  EXPECT_NEAR(out.moves[2].end[0], 15, 1e-9);
  EXPECT_NEAR(out.moves[2].end[1], 55, 1e-9);
  EXPECT_EQ(out.moves[2].end[2], -5);
  EXPECT_NEAR(out.moves[3].start[1], 55, 1e-9);
}

namespace {
// The blocks the corner stage sees: each test's moves name them; offsets as the control has them.
struct FakeBlocks final : CornerControl {
  ncurve::nc::Program prog;
  std::vector<ncurve::nc::Block> blocks = std::vector<ncurve::nc::Block>(10);
  std::size_t now = 0;  // the block in hand, line `now`
  int side = 0, d = 0, lathe_offset = 0;
  std::vector<std::pair<int, int>> offsets_set;
  int held = 0;
  FakeBlocks() {
    for (std::size_t i = 0; i < blocks.size(); ++i) blocks[i].line = static_cast<std::uint32_t>(i), blocks[i].column = 3;
  }
  CornerContext corner_context() const override { return {&prog, &blocks[now], now, side, d, lathe_offset}; }
  void set_offset_numbers(int d_now, int offset_now) override {
    d = d_now, lathe_offset = offset_now;
    offsets_set.emplace_back(d_now, offset_now);
  }
  void move_held() override { ++held; }
};

CornerStage::Alarm span_alarm(Raised& raised, ncurve::nc::Span& where) {
  return [&raised, &where](const ncurve::nc::Span& at, const std::string& code, const std::string& message) {
    raised = {code, message, at.line};
    where = at;
    throw Stopped();
  };
}

CornerRequest request(corner::Kind kind, double amount) {
  CornerRequest r;
  r.kind = kind;
  r.amount = amount;
  r.column = 14;
  return r;
}

// Block 1: G01 X50. ,C5 (or ,R10) from (0, 0) at F1000 (3 s); block 2: Y50. (3 s).
void corner_blocks(FakeBlocks& control, CornerStage& stage, const CornerRequest& r) {
  control.now = 1;
  stage.arm(r);
  Move a = motion(MoveKind::line, {0, 0, 0}, {50, 0, 0}, 50, 3, 1);
  a.feed = 1000;
  stage.on_move(a);
  control.now = 2;
  Move b = motion(MoveKind::line, {50, 0, 0}, {50, 50, 0}, 50, 3, 2);
  b.feed = 1000;
  stage.on_move(b);
}
}  // namespace

// Nothing armed or held: the moves pass on.
TEST(PathCorner, NothingArmedPassesMovesOn) {
  FakeBlocks control;
  Raised raised;
  ncurve::nc::Span where;
  Recorder out;
  CornerStage stage(false, control, span_alarm(raised, where));
  stage.link(out);
  stage.on_move(motion(MoveKind::line, {}, {3, 4, 0}, 5, 1));
  ASSERT_EQ(out.moves.size(), 1u);
  EXPECT_EQ(out.moves[0].end, (AxisVector{3, 4, 0}));
}

// ,C5 at the corner (50, 0): the first block ends 5 short, at (45, 0), the chamfer (45, 0)-(50, 5)
// of 5 sqrt 2 mm is the first block's at its rate (3 s / 50 mm), the second block starts at (50, 5).
TEST(PathCorner, ChamferCutsBothBlocksBack) {
  FakeBlocks control;
  Raised raised;
  ncurve::nc::Span where;
  Recorder out;
  CornerStage stage(false, control, span_alarm(raised, where));
  stage.link(out);
  corner_blocks(control, stage, request(corner::Kind::chamfer, 5));
  EXPECT_EQ(control.held, 1);
  ASSERT_EQ(out.moves.size(), 3u);
  EXPECT_NEAR(out.moves[0].end[0], 45, 1e-9);
  EXPECT_NEAR(out.moves[0].length, 45, 1e-9);
  EXPECT_NEAR(out.moves[0].seconds, 2.7, 1e-9);
  EXPECT_EQ(out.moves[1].kind, MoveKind::line);
  EXPECT_EQ(out.moves[1].line, 1u);
  EXPECT_NEAR(out.moves[1].start[0], 45, 1e-9);
  EXPECT_NEAR(out.moves[1].end[0], 50, 1e-9);
  EXPECT_NEAR(out.moves[1].end[1], 5, 1e-9);
  EXPECT_NEAR(out.moves[1].length, 5 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(out.moves[1].seconds, 0.06 * 5 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(out.moves[2].start[1], 5, 1e-9);
  EXPECT_NEAR(out.moves[2].length, 45, 1e-9);
  EXPECT_NEAR(out.moves[2].seconds, 2.7, 1e-9);
  EXPECT_EQ(out.moves[2].line, 2u);
}

// ,R10 at the same corner: the arc about (40, 10) from (40, 0) to (50, 10), counter-clockwise,
// a quarter of a circle, 5 pi mm.
TEST(PathCorner, CornerRIsATangentArc) {
  FakeBlocks control;
  Raised raised;
  ncurve::nc::Span where;
  Recorder out;
  CornerStage stage(false, control, span_alarm(raised, where));
  stage.link(out);
  corner_blocks(control, stage, request(corner::Kind::round, 10));
  ASSERT_EQ(out.moves.size(), 3u);
  EXPECT_NEAR(out.moves[0].end[0], 40, 1e-9);
  const Move& arc = out.moves[1];
  EXPECT_EQ(arc.kind, MoveKind::arc);
  EXPECT_FALSE(arc.clockwise);
  EXPECT_NEAR(arc.center[0], 40, 1e-9);
  EXPECT_NEAR(arc.center[1], 10, 1e-9);
  EXPECT_NEAR(arc.sweep, kPi / 2, 1e-9);
  EXPECT_NEAR(arc.length, 5 * kPi, 1e-9);
  EXPECT_NEAR(arc.end[0], 50, 1e-9);
  EXPECT_NEAR(arc.end[1], 10, 1e-9);
  EXPECT_NEAR(out.moves[2].start[1], 10, 1e-9);
}

// An event after the held move (its block's M08, the next block's T) goes out after the corner,
// and the held block's moves go out with its own D number, the next block's restored after.
TEST(PathCorner, EventsWaitAndTheHeldBlocksOffsetsGoOut) {
  FakeBlocks control;
  Raised raised;
  ncurve::nc::Span where;
  Recorder out;
  CornerStage stage(false, control, span_alarm(raised, where));
  stage.link(out);
  control.d = 1;
  control.now = 1;
  stage.arm(request(corner::Kind::chamfer, 5));
  stage.on_move(motion(MoveKind::line, {0, 0, 0}, {50, 0, 0}, 50, 3, 1));
  Move coolant;
  coolant.kind = MoveKind::coolant;
  coolant.line = 1;
  stage.on_move(coolant);
  EXPECT_TRUE(out.moves.empty());
  control.now = 2;
  control.d = 2;
  stage.on_move(motion(MoveKind::line, {50, 0, 0}, {50, 50, 0}, 50, 3, 2));
  EXPECT_EQ(out.order, (std::vector<std::string>{"line", "line", "coolant", "line"}));
  EXPECT_EQ(control.offsets_set, (std::vector<std::pair<int, int>>{{1, 0}, {2, 0}}));
  EXPECT_EQ(control.d, 2);
}

// A rapid after the chamfering block is PS0052 at the block in hand (line 2, its first column).
TEST(PathCorner, ARapidAfterTheCornerAlarms) {
  FakeBlocks control;
  Raised raised;
  ncurve::nc::Span where;
  Recorder out;
  CornerStage stage(false, control, span_alarm(raised, where));
  stage.link(out);
  control.now = 1;
  stage.arm(request(corner::Kind::chamfer, 5));
  stage.on_move(motion(MoveKind::line, {0, 0, 0}, {50, 0, 0}, 50, 3, 1));
  control.now = 2;
  EXPECT_THROW(stage.on_move(motion(MoveKind::rapid, {50, 0, 0}, {50, 50, 0}, 50, 1, 2)), Stopped);
  EXPECT_EQ(raised.code, "PS0052");
  EXPECT_EQ(where.line, 2u);
  EXPECT_EQ(where.column, 3u);
  EXPECT_NE(raised.message.find("line 1"), std::string::npos) << raised.message;
  EXPECT_TRUE(out.moves.empty());
}

// A chamfer longer than the first block is PS0055 at the request's word in the held block.
TEST(PathCorner, AChamferThatDoesNotFitAlarmsAtItsWord) {
  FakeBlocks control;
  Raised raised;
  ncurve::nc::Span where;
  Recorder out;
  CornerStage stage(false, control, span_alarm(raised, where));
  stage.link(out);
  EXPECT_THROW(corner_blocks(control, stage, request(corner::Kind::chamfer, 60)), Stopped);
  EXPECT_EQ(raised.code, "PS0055");
  EXPECT_EQ(where.line, 1u);
  EXPECT_EQ(where.column, 14u);
}
