// The coordinate systems alone, worked by hand from the manual's rules: machine = work + origin,
// origin = external + G54..G59 (or G54.1) + G52 + G92 shift.
#include <gtest/gtest.h>

#include "machine/coordinates.hpp"

namespace ncurve::machine {
namespace {

TEST(Coordinates, SelectingAWorkOffsetKeepsTheToolOnTheMachine) {
  Coordinates c;
  c.work_offsets[0] = {1, 0, 0};     // external
  c.work_offsets[1] = {-100, -50, -200};  // G54
  c.work_offsets[2] = {-300, -50, -200};  // G55
  c.extended[2] = {10, 20, 30};           // G54.1 P2
  c.select(1);
  EXPECT_EQ(c.origin, (AxisVector{-99, -50, -200}));
  c.pos = {5, 6, 7};  // machine (-94, -44, -193)
  const AxisVector delta = c.select(2);
  EXPECT_EQ(c.origin, (AxisVector{-299, -50, -200}));
  EXPECT_EQ(c.pos, (AxisVector{205, 6, 7}));  // the same machine point
  EXPECT_EQ(delta, (AxisVector{200, 0, 0}));
  c.select(8);
  EXPECT_EQ(c.origin, (AxisVector{11, 20, 30}));
  EXPECT_EQ(c.pos, (AxisVector{-105, -64, -223}));
}

TEST(Coordinates, G92FoldsTheNamedAxesLocalOffsetIntoTheShift) {
  Coordinates c;
  c.local = {10, 20, 0};  // G52 X10 Y20
  c.select(1);
  EXPECT_EQ(c.origin, (AxisVector{10, 20, 0}));
  c.pos = {1, 2, 3};                               // machine (11, 22, 3)
  const AxisVector delta = c.set_current({0, 0, 0}, 1u << 0);  // G92 X0 Y0 Z0 naming X only
  EXPECT_EQ(delta, (AxisVector{-1, -2, -3}));
  EXPECT_EQ(c.pos, (AxisVector{0, 0, 0}));
  EXPECT_EQ(c.origin, (AxisVector{11, 22, 3}));     // the tool's machine point is the new zero
  EXPECT_EQ(c.local, (AxisVector{0, 20, 0}));       // Y keeps its G52 offset
  EXPECT_EQ(c.shift, (AxisVector{11, 2, 3}));
  c.select(1);                                       // origin recomputed from its parts: unchanged
  EXPECT_EQ(c.origin, (AxisVector{11, 22, 3}));
}

}  // namespace
}  // namespace ncurve::machine
