// A rapid's path as the machine moves it (machine/rapid_path): non-linear positioning by
// No.1401#1 LRP = 0, each axis at its own rate; the corners worked by hand.
#include <gtest/gtest.h>

#include "machine/rapid_path.hpp"

using namespace ncurve::machine;

namespace {
AxisVector at(double x, double y, double z) { return {x, y, z, 0, 0, 0}; }
}  // namespace

TEST(RapidPath, EachAxisAtItsOwnRateMakesADogLeg) {
  MachineProfile p = default_mill();
  p.rapid_rate = {15000, 15000, 15000, 3600, 3600, 3600};
  // X 10, Y 20, Z -5 at one rate: Z arrives first (after 5), then X (after 10), then Y
  const auto path = rapid_path(at(0, 0, 0), at(10, 20, -5), p);
  ASSERT_EQ(path.size(), 4u);
  EXPECT_EQ(path[1], at(5, 5, -5));
  EXPECT_EQ(path[2], at(10, 10, -5));
  EXPECT_EQ(path[3], at(10, 20, -5));
}

TEST(RapidPath, SlowerAxisArrivesLast) {
  MachineProfile p = default_mill();
  p.rapid_rate = {30000, 30000, 10000, 3600, 3600, 3600};
  // X 30 mm at 30000 mm/min arrives at t = 0.001 min, Z 6 mm at 10000 at t = 0.0006: the corner
  // is where Z arrives, X then at 30000 * 0.0006 = 18
  const auto path = rapid_path(at(0, 0, 20), at(30, 0, 14), p);
  ASSERT_EQ(path.size(), 3u);
  EXPECT_DOUBLE_EQ(path[1][0], 18);
  EXPECT_DOUBLE_EQ(path[1][2], 14);
}

TEST(RapidPath, LinearPositioningAndOneAxisAreStraight) {
  MachineProfile p = default_mill();
  p.linear_rapid = true;  // No.1401#1 = 1
  EXPECT_EQ(rapid_path(at(0, 0, 0), at(10, 20, -5), p).size(), 2u);
  p.linear_rapid = false;
  EXPECT_EQ(rapid_path(at(0, 0, 0), at(0, 0, 50), p).size(), 2u);
  EXPECT_EQ(rapid_path(at(0, 0, 0), at(7, 7, 7), p).size(), 2u);  // all arrive together
  EXPECT_EQ(rapid_path(at(1, 2, 3), at(1, 2, 3), p).size(), 2u);
}
