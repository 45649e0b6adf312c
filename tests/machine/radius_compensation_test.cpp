// RadiusCompensation alone, without an interpreter: programmed moves in, tool-centre moves out,
// checked against the corners of the FANUC manuals' cutter compensation C worked by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "machine/path/compensation.hpp"

namespace ncurve::machine {
namespace {

Move line(double x0, double y0, double x1, double y1, std::uint32_t source_line) {
  Move m;
  m.kind = MoveKind::line;
  m.plane = 17;
  m.start = {x0, y0, 0};
  m.end = {x1, y1, 0};
  m.feed = 100;
  m.line = source_line;
  return m;
}

struct Out {
  std::vector<Move> moves;
  std::vector<std::string> alarms, warnings;
  RadiusCompensation comp(CompensationSettings settings = {}) {
    return RadiusCompensation(
        settings, [this](Move& m) { moves.push_back(m); },
        [this](const Move&, const std::string& code, const std::string&) {
          alarms.push_back(code);
          throw std::runtime_error(code);
        },
        [this](const Move&, const std::string& code, const std::string&) { warnings.push_back(code); });
  }
};

// G41 (tool left of the path) with 5 mm round a counter-clockwise square 20 x 20: the tool runs
// inside. Type A start-up ends perpendicular to the next move; inner corners are the offset lines'
// intersections; the last move before G40 ends perpendicular; the cancel move ends on its point.
TEST(RadiusCompensation, InsideASquareTypeA) {
  Out out;
  RadiusCompensation comp = out.comp();
  comp.element(line(0, -10, 0, 0, 1), +1, 5);  // start-up
  comp.element(line(0, 0, 20, 0, 2), +1, 5);
  comp.element(line(20, 0, 20, 20, 3), +1, 5);
  comp.element(line(20, 20, 0, 20, 4), +1, 5);
  comp.element(line(0, 20, 0, 0, 5), +1, 5);
  comp.element(line(0, 0, 0, -10, 6), 0, 5);  // G40
  comp.finish();
  ASSERT_TRUE(out.alarms.empty());
  const double want[][4] = {{0, -10, 0, 5}, {0, 5, 15, 5}, {15, 5, 15, 15}, {15, 15, 5, 15}, {5, 15, 5, 0}, {5, 0, 0, -10}};
  ASSERT_EQ(out.moves.size(), std::size(want));
  for (std::size_t i = 0; i < out.moves.size(); ++i) {
    const Move& m = out.moves[i];
    EXPECT_NEAR(m.start[0], want[i][0], 1e-9) << i;
    EXPECT_NEAR(m.start[1], want[i][1], 1e-9) << i;
    EXPECT_NEAR(m.end[0], want[i][2], 1e-9) << i;
    EXPECT_NEAR(m.end[1], want[i][3], 1e-9) << i;
    EXPECT_EQ(m.line, static_cast<std::uint32_t>(i + 1));  // each tool move is its own block's
  }
}

// G42 (tool right of the path) with 5 mm round the same square: the tool runs outside; at each outer
// 90-degree corner the offset
// lines meet at their intersection (no move inserted at a right angle).
TEST(RadiusCompensation, OutsideASquareMeetsAtTheIntersections) {
  Out out;
  RadiusCompensation comp = out.comp();
  comp.element(line(0, -10, 0, 0, 1), -1, 5);
  comp.element(line(0, 0, 20, 0, 2), -1, 5);
  comp.element(line(20, 0, 20, 20, 3), -1, 5);
  comp.element(line(20, 20, 0, 20, 4), -1, 5);
  comp.element(line(0, 20, 0, 0, 5), -1, 5);
  comp.element(line(0, 0, 0, -10, 6), 0, 5);
  comp.finish();
  ASSERT_TRUE(out.alarms.empty());
  const double ends[][2] = {{0, -5}, {25, -5}, {25, 25}, {-5, 25}, {-5, 0}, {0, -10}};
  ASSERT_EQ(out.moves.size(), std::size(ends));
  for (std::size_t i = 0; i < out.moves.size(); ++i) {
    EXPECT_NEAR(out.moves[i].end[0], ends[i][0], 1e-9) << i;
    EXPECT_NEAR(out.moves[i].end[1], ends[i][1], 1e-9) << i;
  }
}

}  // namespace
}  // namespace ncurve::machine
