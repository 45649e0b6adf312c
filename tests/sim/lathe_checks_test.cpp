// The lathe's checks beyond the cut: a rapid moved as the machine moves it (NC2080 along its dog-leg),
// the holder meeting the bar (NC2085) and the tool meeting a fixture (NC2086). The expected areas are
// worked by hand from the tools' outlines (docs/verify.md, "Lathe: the checks").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "sim/lathe_section.hpp"
#include "sim/lathe_section_sink.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using namespace ncurve::sim;

namespace {

Cylinder bar(double diameter, double length, double face = 0) {
  Cylinder c;
  c.diameter = diameter;
  c.length = length;
  c.face = face;
  return c;
}

// A tip-3 insert of nose radius r in T1.
ToolLibrary turning(double r, double holder_width = 0, double holder_length = 0) {
  LatheInsert i;
  i.nose_radius = r;
  i.tip = 3;
  i.holder_width = holder_width;
  i.holder_length = holder_length;
  ToolLibrary lib;
  lib.tools[1] = i;
  return lib;
}

// A lathe whose X and Z rapid at the same rate, its positioning linear or not.
machine::MachineProfile lathe(bool linear_rapid) {
  machine::MachineProfile p = machine::default_lathe();
  p.rapid_rate[0] = p.rapid_rate[2] = 20000;
  p.linear_rapid = linear_rapid;
  return p;
}

struct Checked {
  std::vector<Finding> findings;
  LatheSectionSink::Counts counts;
  double area_removed = 0;
  std::vector<const Finding*> of(const std::string& code) const {
    std::vector<const Finding*> out;
    for (const Finding& f : findings)
      if (f.diagnostic.code == code) out.push_back(&f);
    return out;
  }
};

// The program run on the profile and its moves given to a sink on the bar; `rapids` is the profile
// the sink moves rapids by (none: straight).
Checked check(const std::string& program, const Cylinder& stock, const ToolLibrary& lib,
              const machine::MachineProfile& profile, const machine::MachineProfile* rapids,
              std::vector<Fixture> fixtures = {}) {
  auto r = test::run(program, profile);
  EXPECT_TRUE(r.result.ok());
  LatheSection section(stock);
  LatheSinkOptions o;
  o.profile = rapids;
  o.fixtures = std::move(fixtures);
  LatheSectionSink sink(section, lib, {}, std::nullopt, o);
  for (const auto& m : r.moves) sink.on_move(m);
  return {sink.findings(), sink.counts(), section.area_removed()};
}

// From radius 40 at Z-20 (beside a D50 bar, outside it) to radius 20 at Z10 (in front of its face).
// X programmed as a diameter.
const char* kDogLeg = "G21 G99 G18 M03 S500\nG00 X80. Z-20.\nT0101\nG00 X40. Z10.\nM30\n";

}  // namespace

// Non-linear positioning with X and Z at the same rate: X (20 to go) arrives first, so the tip runs
// at 45 degrees from (Z-20, radius 40) to the corner (Z0, radius 20), then along Z to Z10. The
// diagonal crosses the bar's corner: the triangle (Z0, r20), (Z0, r25), (Z-5, r25), 12.5 mm^2, less
// the band the nose does not reach. A tip-3 insert lies at and above and right of its tip, and its
// nose circle of radius r about tip + (r, r) reaches r (sqrt 2 - 1) short of the tip's line across a
// 45-degree move: the triangle's hypotenuse (5 / sqrt 2 from its right angle) moves in by that much,
// and the area scales by the square of the height left. The straight line (its Z0 at radius 26.67)
// misses the bar.
TEST(LatheChecks, RapidDogLegCrossesTheBar) {
  const double r = 0.4;
  const double h = 5 / std::sqrt(2.0), w = r * (std::sqrt(2.0) - 1);
  const double expected = 12.5 * ((h - w) / h) * ((h - w) / h);  // 11.356
  const auto profile = lathe(false);
  const Checked c = check(kDogLeg, bar(50, 100), turning(r), profile, &profile);
  ASSERT_EQ(c.of("NC2080").size(), 1u);
  const Finding& f = *c.of("NC2080")[0];
  EXPECT_EQ(f.diagnostic.span.line, 4u);
  EXPECT_NEAR(f.amount, expected, 0.01);
  EXPECT_NEAR(c.area_removed, expected, 0.01);
  EXPECT_NE(f.diagnostic.message.find("corner at Z0.000 radius 20.000"), std::string::npos) << f.diagnostic.message;
}

// The same rapid with linear positioning (No.1401#1 = 1), or cut straight (no profile), stays clear.
TEST(LatheChecks, RapidStraightLineMissesTheBar) {
  const auto linear = lathe(true);
  const Checked c = check(kDogLeg, bar(50, 100), turning(0.4), linear, &linear);
  EXPECT_TRUE(c.findings.empty());
  EXPECT_EQ(c.area_removed, 0);
  const Checked straight = check(kDogLeg, bar(50, 100), turning(0.4), linear, nullptr);
  EXPECT_TRUE(straight.findings.empty());
}

// With the fanuc-lathe's rates (X 20000, Z 24000 mm/min) the corner moves: X arrives after 20 / 20000
// min, when Z has gone 24, at Z4: the diagonal (slope 20 / 24) crosses radius 25 at Z-2 and Z0 at
// radius 23.33; the triangle (Z0, r23.33), (Z0, r25), (Z-2, r25) is 1.667 mm^2 less the nose's band.
TEST(LatheChecks, RapidDogLegFollowsEachAxisRate) {
  auto profile = lathe(false);
  profile.rapid_rate[2] = 24000;
  const Checked c = check(kDogLeg, bar(50, 100), turning(0), profile, &profile);
  ASSERT_EQ(c.of("NC2080").size(), 1u);
  EXPECT_NEAR(c.of("NC2080")[0]->amount, 0.5 * 2 * (25 - 20 - 20.0 * 4 / 24), 1e-3);
}

namespace {

// A sharp 80-degree insert in a 95-degree holder (tip 3, clearance 5) reaches, from its tip, 12.7 /
// sin 80 along each edge: its far corner is (cos 5 + sin 5) times that above the tip and beyond it in
// Z, and its holder's shank starts there and runs up (+X) from the tip's Z towards +Z.
double insert_height() {
  const double deg = std::numbers::pi / 180;
  return 12.7 / std::sin(80 * deg) * (std::cos(5 * deg) + std::sin(5 * deg));  // 13.970
}

std::string turn_pass(double diameter) {
  return "G21 G99 G18 M03 S500\nG00 X200. Z50.\nT0101\nG00 X" + std::to_string(diameter) +
         " Z2.\nG01 Z-30. F0.2\nG00 Z2.\nG00 X100.\nM30\n";
}

}  // namespace

// One pass 16 deep into a D50 bar (to radius 9) from Z2 to Z-30: the insert takes up to radius
// 9 + 13.970 = 22.970, and the shank (25 wide, 150 long) sweeps from there up over Z-30..27; the bar's
// ring of radius 22.970..25 over Z-30..0 is inside it: 30 x 2.030 mm^2, at the G01. The G00 back
// along Z keeps the contact (not listed again).
TEST(LatheChecks, HolderMeetsTheBar) {
  const auto profile = machine::default_lathe();
  const Checked c = check(turn_pass(18), bar(50, 100), turning(0, 25, 150), profile, nullptr);
  ASSERT_EQ(c.of("NC2085").size(), 1u);
  const Finding& f = *c.of("NC2085")[0];
  EXPECT_EQ(f.diagnostic.span.line, 5u);
  EXPECT_NEAR(f.amount, 30 * (25 - 9 - insert_height()), 1e-3);
  EXPECT_NEAR(f.at[2], -15, 1e-3);  // the centroid of the ring's section
  EXPECT_NEAR(f.at[0], (25 + 9 + insert_height()) / 2, 1e-3);
  EXPECT_NE(f.diagnostic.message.find("the holder of T1 meets the bar"), std::string::npos) << f.diagnostic.message;
  EXPECT_TRUE(c.of("NC2080").empty());
}

// The same pass 13.9 deep (to radius 11.1): the shank starts at 25.07, above the bar; and 16 deep
// with no holder in the library: nothing to check.
TEST(LatheChecks, HolderClearOfTheBar) {
  const auto profile = machine::default_lathe();
  EXPECT_TRUE(check(turn_pass(22.2), bar(50, 100), turning(0, 25, 150), profile, nullptr).findings.empty());
  EXPECT_TRUE(check(turn_pass(18), bar(50, 100), turning(0), profile, nullptr).findings.empty());
}

// A box fixture on a lathe is the ring it sweeps: Z over its range, the radius from its XY
// rectangle's nearest point to the axis to its farthest corner.
TEST(LatheChecks, BoxFixtureIsTheRingItSweeps) {
  const Cylinder jaw = fixture_ring({{25, -10, -100}, {45, 10, -75}});
  EXPECT_DOUBLE_EQ(jaw.inner_diameter, 50);
  EXPECT_DOUBLE_EQ(jaw.diameter, 2 * std::sqrt(45.0 * 45 + 10 * 10));
  EXPECT_DOUBLE_EQ(jaw.face, -75);
  EXPECT_DOUBLE_EQ(jaw.length, 25);
  const Cylinder off = fixture_ring({{3, 4, 0}, {6, 8, 1}});
  EXPECT_DOUBLE_EQ(off.inner_diameter, 10);  // (3, 4)
  EXPECT_DOUBLE_EQ(off.diameter, 20);        // (6, 8)
  const Cylinder centre = fixture_ring({{-5, -5, 200}, {5, 5, 260}});
  EXPECT_DOUBLE_EQ(centre.inner_diameter, 0);
  EXPECT_DOUBLE_EQ(centre.diameter, 2 * std::sqrt(50.0));
}

namespace {

// A chuck jaw holding the D50 bar over Z-100..-75: the ring of radius 25..46.10.
Fixture chuck_jaw() { return {"chuck jaw", AxisBox{{25, -10, -100}, {45, 10, -75}}}; }

// A 3 mm grooving blade (tip 3, sharp, 20 deep): from its tip 3 along +Z and 20 up.
ToolLibrary blade() {
  LatheInsert i;
  i.tip = 3;
  i.width = 3;
  ToolLibrary lib;
  lib.tools[1] = i;
  return lib;
}

std::string blade_pass(const std::string& z) {
  return "G21 G99 G18 M03 S500\nG00 X200. Z50.\nT0101\nG00 X48. Z2.\nG01 Z" + z + " F0.2\nG00 Z2.\nG00 X200.\nM30\n";
}

}  // namespace

// The blade along radius 24 to Z-80 enters the jaw's ring over Z-80..-75 at radius 25..44: 5 x 19
// mm^2 at the G01; the G00 back out of it keeps the contact (not listed again).
TEST(LatheChecks, InsertMeetsTheChuckJaw) {
  const auto profile = machine::default_lathe();
  const Checked c = check(blade_pass("-80."), bar(50, 100), blade(), profile, nullptr, {chuck_jaw()});
  ASSERT_EQ(c.of("NC2086").size(), 1u);
  const Finding& f = *c.of("NC2086")[0];
  EXPECT_EQ(f.diagnostic.span.line, 5u);
  EXPECT_NEAR(f.amount, 5 * 19, 1e-3);
  EXPECT_NEAR(f.at[2], -77.5, 1e-3);
  EXPECT_NEAR(f.at[0], 34.5, 1e-3);
  EXPECT_NE(f.diagnostic.message.find("T1's insert meets the fixture 'chuck jaw'"), std::string::npos)
      << f.diagnostic.message;
}

// Stopping 0.1 short of the jaw (Z-74.9) is clean; so is the bar with no fixture.
TEST(LatheChecks, InsertShortOfTheChuckJaw) {
  const auto profile = machine::default_lathe();
  EXPECT_TRUE(check(blade_pass("-74.9"), bar(50, 100), blade(), profile, nullptr, {chuck_jaw()}).findings.empty());
  EXPECT_TRUE(check(blade_pass("-80."), bar(50, 100), blade(), profile, nullptr).findings.empty());
}

namespace {

// A sharp 80-degree boring tool (tip 2) whose bar, 16 wide and 150 long, runs along +Z from the
// insert's far end (13.970 beyond its tip) at the tip's radius and below; a tailstock centre's ring,
// radius 0..sqrt 50, Z200..260.
ToolLibrary boring_bar() {
  LatheInsert i;
  i.tip = 2;
  i.holder_width = 16;
  i.holder_length = 150;
  ToolLibrary lib;
  lib.tools[1] = i;
  return lib;
}
Fixture tailstock() { return {"tailstock centre", AxisBox{{-5, -5, 200}, {5, 5, 260}}}; }

std::string boring_move(const std::string& z) {
  return "G21 G99 G18 M03 S500\nG00 X200. Z50.\nT0101\nG00 X40. Z20.\nG01 Z" + z + " F0.2\nG00 X200.\nM30\n";
}

}  // namespace

// The tool at radius 20 moved from Z20 to Z40: the bar's end reaches 40 + 13.970 + 150 = 203.970,
// its radius 4..20 meeting the centre's 0..7.071 over Z200..203.970.
TEST(LatheChecks, HolderMeetsTheTailstock) {
  const auto profile = machine::default_lathe();
  const Checked c = check(boring_move("40."), bar(50, 100), boring_bar(), profile, nullptr, {tailstock()});
  ASSERT_EQ(c.of("NC2086").size(), 1u);
  const Finding& f = *c.of("NC2086")[0];
  EXPECT_EQ(f.diagnostic.span.line, 5u);
  EXPECT_NEAR(f.amount, (40 + insert_height() + 150 - 200) * (std::sqrt(50.0) - 4), 1e-3);
  EXPECT_NE(f.diagnostic.message.find("T1's holder meets the fixture 'tailstock centre'"), std::string::npos)
      << f.diagnostic.message;
  // to Z36 the bar ends at 199.970
  EXPECT_TRUE(check(boring_move("36."), bar(50, 100), boring_bar(), profile, nullptr, {tailstock()}).findings.empty());
}

namespace {

// An 8 mm drill on the spindle axis, 60 out of a holder of D32 and 40 long.
ToolLibrary drill_in_holder() {
  MillTool d;
  d.kind = MillKind::drill;
  d.diameter = 8;
  d.point_angle = 118;
  d.flute_length = 50;
  d.stick_out = 60;
  d.holder = {{32, 32, 40}};
  ToolLibrary lib;
  lib.tools[1] = d;
  return lib;
}

std::string drilling(const std::string& z) {
  return "G21 G99 G18 M03 S500\nG00 X200. Z50.\nT0101\nG00 X0 Z3.\nG01 Z" + z + " F0.1\nG00 Z50.\nM30\n";
}

}  // namespace

// Drilling to Z-65 takes the holder's face (60 above the tip) to Z-5: the bar's material about the
// D8 hole, radius 4..16 over Z-5..0, is inside it: 5 x 12 mm^2. To Z-59.9 it stops 0.1 short (and
// the drill is past its flutes: DrillPastItsFlutes).
TEST(LatheChecks, DrillHolderMeetsTheFace) {
  const auto profile = machine::default_lathe();
  const Checked c = check(drilling("-65."), bar(50, 100), drill_in_holder(), profile, nullptr);
  ASSERT_EQ(c.of("NC2085").size(), 1u);
  EXPECT_EQ(c.of("NC2085")[0]->diagnostic.span.line, 5u);
  EXPECT_NEAR(c.of("NC2085")[0]->amount, 5 * 12, 1e-3);
  EXPECT_TRUE(check(drilling("-59.9"), bar(50, 100), drill_in_holder(), profile, nullptr).of("NC2085").empty());
}

// NC2081 on a lathe: the D8 drill with 50 mm flutes fed from Z3 to Z-59.9 in one move takes its body
// above the flutes (from 50 above the tip up) to Z-9.9, through the bar's uncut column of radius 4
// over Z-9.9..0: 9.9 x 4 mm^2. To Z-49.9 that body stops 0.1 above the face: clean.
TEST(LatheChecks, DrillPastItsFlutes) {
  const auto profile = machine::default_lathe();
  const Checked deep = check(drilling("-59.9"), bar(50, 100), drill_in_holder(), profile, nullptr);
  ASSERT_EQ(deep.of("NC2081").size(), 1u);
  EXPECT_EQ(deep.of("NC2081")[0]->diagnostic.span.line, 5u);
  EXPECT_NEAR(deep.of("NC2081")[0]->amount, 9.9 * 4, 1e-3);
  EXPECT_TRUE(check(drilling("-49.9"), bar(50, 100), drill_in_holder(), profile, nullptr).findings.empty());
}

// Numbers no setup should hold (a fuzzed one): fixtures of 1e300 and NaN, holders of NaN and 1e300,
// rapid rates of NaN, 0 and infinity; nothing crashes and nothing is found.
TEST(LatheChecks, BadNumbersNeverCrash) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  auto profile = machine::default_lathe();
  profile.rapid_rate[0] = nan;
  profile.rapid_rate[2] = inf;
  std::vector<Fixture> fixtures{{"huge", AxisBox{{-1e300, -1e300, -1e300}, {1e300, 1e300, -200}}},
                                {"nan", AxisBox{{nan, nan, nan}, {nan, nan, nan}}}};
  for (double size : {nan, 1e300, -5.0}) {
    const Checked c = check(kDogLeg, bar(50, 100), turning(0.4, size, size), profile, &profile, fixtures);
    EXPECT_TRUE(c.of("NC2085").empty());
    EXPECT_TRUE(c.of("NC2086").empty());
  }
  profile.rapid_rate[0] = 0;
  EXPECT_TRUE(check(kDogLeg, bar(50, 100), turning(0.4), profile, &profile).findings.empty());
}

namespace ncurve::sim {
namespace {

// NC2083 on a lathe: the pass 3 deep into the D50 bar (to radius 22) with no M03, or after an M05,
// removes 30 x 3 mm^2 of the section at the G01 (line 5): found; the same with the spindle turning,
// and a feed move in front of the face with it stopped, clean.
TEST(LatheChecks, CutWithTheSpindleStopped) {
  const auto profile = machine::default_lathe();
  std::string stopped = turn_pass(44);
  stopped.replace(stopped.find(" M03 S500"), 9, "");
  const Checked no_m03 = check(stopped, bar(50, 100), turning(0), profile, nullptr);
  ASSERT_EQ(no_m03.of("NC2083").size(), 1u);
  EXPECT_EQ(no_m03.of("NC2083")[0]->diagnostic.span.line, 5u);
  // the ring 30 x 3 less the triangle the insert's edge across the axis leaves at Z-30, leaning back
  // 5 degrees (its clearance): 3 x 3 tan 5 / 2
  EXPECT_NEAR(no_m03.of("NC2083")[0]->amount, 90 - 4.5 * std::tan(5 * std::numbers::pi / 180), 1e-3);
  std::string m05 = turn_pass(44);
  m05.replace(m05.find("T0101\n"), 6, "T0101 M05\n");
  EXPECT_EQ(check(m05, bar(50, 100), turning(0), profile, nullptr).of("NC2083").size(), 1u);
  EXPECT_TRUE(check(turn_pass(44), bar(50, 100), turning(0), profile, nullptr).of("NC2083").empty());
  const std::string air = "G21 G99 G18\nG00 X200. Z50.\nT0101\nG00 X60. Z10.\nG01 X0 F0.2\nG00 Z50.\nM30\n";
  EXPECT_TRUE(check(air, bar(50, 100), turning(0), profile, nullptr).of("NC2083").empty());
}

}  // namespace
}  // namespace ncurve::sim

namespace ncurve::sim {
namespace {

// NC2082 on a lathe: a D10 end mill that does not cut at its centre, on the axis, fed from Z3 to
// Z-5 into the D50 bar's face: its end (radius 5) takes 5 x 5 mm^2 of the section: found. The same
// with a centre-cutting one, or the plunge stopping at Z0.5, clean.
TEST(LatheChecks, PlungeWithoutACentreCuttingEdge) {
  const auto profile = machine::default_lathe();
  auto mill = [](bool centre) {
    MillTool e;
    e.kind = MillKind::flat;
    e.diameter = 10;
    e.flute_length = 20;
    e.centre_cutting = centre;
    ToolLibrary lib;
    lib.tools[1] = e;
    return lib;
  };
  const Checked plunge = check(drilling("-5."), bar(50, 100), mill(false), profile, nullptr);
  ASSERT_EQ(plunge.of("NC2082").size(), 1u);
  EXPECT_EQ(plunge.of("NC2082")[0]->diagnostic.span.line, 5u);
  EXPECT_NEAR(plunge.of("NC2082")[0]->amount, 5 * 5, 1e-3);
  EXPECT_TRUE(check(drilling("-5."), bar(50, 100), mill(true), profile, nullptr).of("NC2082").empty());
  EXPECT_TRUE(check(drilling("0.5"), bar(50, 100), mill(false), profile, nullptr).of("NC2082").empty());
}

}  // namespace
}  // namespace ncurve::sim
