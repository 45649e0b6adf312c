// The path stages (src/machine/path/) alone, without an Interpreter: hand-made moves in, what
// reaches a recording sink out, against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "machine/path/statistics.hpp"

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

struct FixedSetup final : SetupSource {
  Setup now;
  Setup setup_now() const override { return now; }
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
