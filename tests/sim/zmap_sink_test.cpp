// The move stream into a Z-map: the tool in the spindle by T number, lines, arcs and rapids cut.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/zmap_sink.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

TEST(ZMapSink, ProgramCutsWithTheToolInTheSpindle) {
  // a slot with T1 (flat, R 5), then T2 (ball, R 3) round a G03 half circle, one G18 arc left out
  auto r = test::run(
      "G90 G17 G00 X20. Y50. Z5.\nG01 Z-3. F500.\nX80.\nG00 Z5.\nT1 M06\nG00 X20. Y50.\nG01 Z-3. F500.\nX80.\n"
      "G00 Z5.\nT2 M06\nG00 X40. Y20.\nG01 Z-1.\nG03 X60. Y20. R10.\nG18 G02 X70. Z-1. R5.\nM30\n",
      test::calculator_mill());
  ASSERT_TRUE(r.result.ok());
  sim::ZMap map(sim::Box{{0, 0, -20}, {100, 100, 0}});
  sim::ZMapSink sink(map, {{1, sim::ToolShape::flat(5)}, {2, sim::ToolShape::ball(3)}});
  for (const auto& m : r.moves) sink.on_move(m);
  EXPECT_EQ(sink.counts().no_tool, 4u);  // before the first M06
  EXPECT_EQ(sink.counts().not_xy_arc, 1u);
  EXPECT_EQ(sink.counts().cut, 7u);
  EXPECT_EQ(map.height_at(50.05, 50.05), -3);
  EXPECT_EQ(map.height_at(50.05, 56.05), 0);
  // the ball's arc (G03 from the left through the bottom): its tip at Z-1 on the circle of radius
  // 10 about (50, 20); the cell's distance from the circle is 10 - D
  const double d = 10 - std::hypot(0.05, 9.95);
  EXPECT_NEAR(map.height_at(50.05, 10.05), -1 + 3 - std::sqrt(9 - d * d), 1e-9);
  EXPECT_EQ(map.height_at(50.05, 30.05), 0);
  const double exact = 60 * 10 * 3 + std::numbers::pi * 25 * 3;
  EXPECT_GT(map.volume_removed(), exact);
}
