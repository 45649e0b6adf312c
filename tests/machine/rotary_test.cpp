// Rotary axes (No.1006#0 ROTx): degrees without inch conversion, roll-over (No.1008), and the
// feed of a move that turns one, against values worked out by hand from the FANUC manuals.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
machine::MachineProfile rotary_mill(const std::string& parameters = "") {
  return machine::parse_profile("[machine]\naxes = [\"X\", \"Y\", \"Z\", \"A\", \"B\"]\n[parameters]\n"
                                "\"1006#0\" = [0, 0, 0, 1, 1]\n" + parameters,
                                "rotary.toml");
}
double seconds_of_line(const test::Ran& r, std::uint32_t line) {
  double s = 0;
  for (const auto& m : r.moves)
    if (m.line == line) s += m.seconds;
  return s;
}
}  // namespace

// The manual's example: G91 G01 X20.0 B40.0 F300.0 takes sqrt(20^2 + 40^2) / 300 = 0.14907 min, the
// degrees counted as mm.
TEST(Rotary, FeedAppliesToTheCombinedMove) {
  auto r = run("G91 G01 X20. B40. F300.\nG01 A90. F100.\nM30\n", rotary_mill());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_NEAR(seconds_of_line(r, 1), std::sqrt(20.0 * 20 + 40 * 40) / 300 * 60, 1e-9);
  EXPECT_NEAR(seconds_of_line(r, 2), 90.0 / 100 * 60, 1e-9);  // a turn alone: F in deg/min
  EXPECT_NEAR(r.motions().at(0).length, 20, 1e-12);           // the length stays the linear one
}

// G20: a rotary word stays in degrees (no inch conversion), its increment 0.001 deg; the feed counts
// degrees as inches: G01 X1. A10. F10. takes sqrt(1 + 100) / 10 min.
TEST(Rotary, DegreesAreNotInches) {
  auto r = run("G20 G90 G01 X1. A10. F10.\nA12500\nM30\n", rotary_mill());
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_NEAR(r.motions().at(0).end[0], 25.4, 1e-12);
  EXPECT_NEAR(r.motions().at(0).end[3], 10, 1e-12);
  EXPECT_NEAR(r.motions().at(1).end[3], 12.5, 1e-12);  // 12500 increments of 0.001 deg
  EXPECT_NEAR(seconds_of_line(r, 1), std::sqrt(101.0) / 10 * 60, 1e-9);
  // an A axis that is not rotary is a linear axis: inches
  auto linear = run("G20 G90 G00 A1.\nM30\n", machine::parse_profile("[machine]\naxes = [\"X\", \"Y\", \"Z\", \"A\"]\n", "l"));
  EXPECT_NEAR(linear.motions().at(0).end[3], 25.4, 1e-12);
}

// Roll-over: the position after a move is within one turn (#5004 reads it); without roll-over
// an absolute command is a plain position.
TEST(Rotary, RollOverKeepsThePositionWithinOneTurn) {
  auto r = run("G90 G00 A100.\nG91 A380.\n#100=#5004\nG90 A-30.\n#101=#5004\nM30\n",
               rotary_mill("\"1008#0\" = [0, 0, 0, 1, 0]\n"));
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 120);
  EXPECT_DOUBLE_EQ(r.var(101), 330);
  EXPECT_DOUBLE_EQ(r.motions().at(2).end[3] - r.motions().at(2).start[3], -150);  // 120 -> 330 the shorter way
  auto plain = run("G90 G00 A100.\nG91 A380.\nG90 A-30.\nM30\n", rotary_mill());
  EXPECT_DOUBLE_EQ(plain.motions().at(2).end[3], -30);
  EXPECT_DOUBLE_EQ(plain.motions().at(2).start[3], 480);
}

// No.1260: the travel of one turn (increments); 180 deg per turn here.
TEST(Rotary, TravelPerTurn) {
  auto r = run("G90 G00 A170.\nA10.\nM30\n", rotary_mill("\"1008#0\" = [0, 0, 0, 1, 0]\n\"1260\" = [0, 0, 0, 180000, 360000]\n"));
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.motions().at(1).end[3] - r.motions().at(1).start[3], 20);  // 170 -> 190 = 10 of the next turn
}

TEST(Rotary, ProfileSettings) {
  EXPECT_THROW(machine::parse_profile("[parameters]\n\"1006#0\" = [1, 0, 0]\n", "x"), std::runtime_error);  // X linear
  EXPECT_THROW(machine::parse_profile("[parameters]\n\"1008#0\" = 1\n", "x"), std::runtime_error);   // per axis
  EXPECT_THROW(machine::parse_profile("[parameters]\n\"1008#0\" = [0, 1]\n", "x"), std::runtime_error);  // 3 axes
  EXPECT_THROW(machine::parse_profile("[parameters]\n\"1008#0.A\" = 1\n", "x"), std::runtime_error);  // no A
  auto p = rotary_mill();
  machine::set_parameter(p, "1008#1.B", 1);
  EXPECT_TRUE(p.rotary[4].by_sign);
  EXPECT_THROW(machine::set_parameter(p, "1008#1", 1), std::runtime_error);
  // an axis word for an axis the machine lacks stays PS0009
  EXPECT_EQ(run("G00 A10.\nM30\n").alarm_code(), "PS0009");
}
