// The verifier (src/sim/verifier*): each finding has a program that must raise it and one that must
// not, with the depths worked by hand from the stock and the tool.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "sim/verifier.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

// A 100 x 100 x 20 block, top at Z0, on 0.1 mm cells; T1 a 10 mm flat end mill with 5 mm flutes,
// T2 a 6 mm drill, T3 a 10 mm end mill that does not cut at its centre, T4 limited to 8000 rev/min,
// T5 in a 40 mm holder 20 mm above its tip, T6 a 3 mm cutter on a 6 mm shank with 8 mm flutes; a
// clamp at X30..40 Y-10..10 standing 5 mm above the block.
const char* const kSetup = R"(
[stock]
shape = "box"
min = [-50, -50, -20]
max = [50, 50, 0]

[tools.1]
kind = "flat"
diameter = 10
flute_length = 5

[tools.2]
kind = "drill"
diameter = 6

[tools.3]
kind = "flat"
diameter = 10
centre_cutting = false

[tools.4]
kind = "flat"
diameter = 10
max_spindle_speed = 8000

[tools.5]
kind = "flat"
diameter = 10
flute_length = 20
stick_out = 20
holder = [{ diameter = 40, length = 30 }]

[tools.6]
kind = "flat"
diameter = 3
flute_length = 8
shank_diameter = 6
stick_out = 30

[tools.7]
kind = "ball"
diameter = 6

[[fixtures]]
name = "clamp"
shape = "box"
min = [30, -10, -20]
max = [40, 10, 5]
)";

struct Verified {
  machine::MachineProfile profile = test::calculator_mill();
  test::Ran ran;
  sim::SetupFile setup;
  std::unique_ptr<sim::MillTools> tools;
  std::unique_ptr<sim::Verifier> verifier;

  std::vector<const sim::Finding*> of(const std::string& code) const {
    std::vector<const sim::Finding*> out;
    for (const auto& f : verifier->findings())
      if (f.diagnostic.code == code) out.push_back(&f);
    return out;
  }
};

Verified verify(const std::string& program, const char* setup_text = kSetup, bool linear_rapid = false) {
  Verified v;
  v.profile.linear_rapid = linear_rapid;
  v.ran = test::run(program, v.profile);
  EXPECT_TRUE(v.ran.result.ok()) << (v.ran.result.alarm ? v.ran.result.alarm->message : "");
  v.setup = sim::parse_setup(setup_text, "s.toml");
  v.tools = std::make_unique<sim::MillTools>(v.setup.tools, test::calculator_mill());
  sim::VerifyOptions o;
  o.cell = 0.1;
  o.profile = &v.profile;
  v.verifier = std::make_unique<sim::Verifier>(*v.setup.stock, *v.tools, v.setup.tool_in_spindle, o, v.setup.fixtures);
  for (const auto& m : v.ran.moves) v.verifier->on_move(m);
  return v;
}

}  // namespace

TEST(Verifier, RapidIntoTheStockWarnsWithItsDepth) {
  auto v = verify("T1 M06\nM03 S1000\nG90 G00 X0.05 Y0.05 Z5.\nG00 Z-2.\nG00 Z5.\nM30\n");
  const auto found = v.of("NC2080");
  ASSERT_EQ(found.size(), 1u);
  const sim::Finding& f = *found[0];
  EXPECT_EQ(f.diagnostic.span.line, 4u);  // G00 Z-2.: the flat end removes 2 mm under it
  EXPECT_EQ(f.diagnostic.span.column, 1u);
  EXPECT_EQ(f.diagnostic.severity, nc::Severity::warning);
  EXPECT_DOUBLE_EQ(f.amount, 2.0);
  EXPECT_NEAR(f.at[2], -2.0, 1e-12);
  EXPECT_LE(std::hypot(f.at[0] - 0.05, f.at[1] - 0.05), 5.0);
  EXPECT_NE(f.diagnostic.message.find("2.000 mm deep"), std::string::npos) << f.diagnostic.message;
  EXPECT_EQ(v.verifier->findings().size(), 1u);  // the retract goes up its own hole
}

TEST(Verifier, RapidThatStopsAboveTheStockIsClean) {
  auto v = verify("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG00 Z0.1\nX30. Y20.\nG00 Z5.\nM30\n");
  EXPECT_TRUE(v.verifier->findings().empty());
  EXPECT_EQ(v.verifier->map().volume_removed(), 0);
}

TEST(Verifier, RapidBackAlongACutSlotIsClean) {
  // the slot is fed at Z-3, then a rapid runs back along it at the same depth through air
  auto v = verify("T1 M06\nM03 S1000\nG90 G00 X-20. Y0 Z5.\nG01 Z-3. F200.\nX20.\nG00 X-20.\nG00 Z5.\nM30\n");
  EXPECT_TRUE(v.of("NC2080").empty());
  EXPECT_TRUE(v.verifier->findings().empty());
}

TEST(Verifier, DrillingCycleIsClean) {
  // G98 G81: rapid to R2 above the top, feed to Z-5, rapid back to the initial level
  auto v = verify("T2 M06\nM03 S2000\nG90 G00 X0 Y0 Z10.\nG98 G81 X10. Y10. Z-5. R2. F100.\nX-10.\nG80\nM30\n");
  EXPECT_TRUE(v.verifier->findings().empty());
  // the hole's bottom under the point: the tip at Z-5 on the hole's axis
  EXPECT_NEAR(v.verifier->map().height_at(10.05, 10.05), -5 + 0.05 * std::sqrt(2.0) / std::tan(59 * std::numbers::pi / 180),
              1e-9);
}

TEST(Verifier, CutDeeperThanTheFlutesWarns) {
  auto deep = verify("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-8. F100.\nX20.\nG00 Z5.\nM30\n");
  const auto found = deep.of("NC2081");
  ASSERT_EQ(found.size(), 2u);  // the plunge and the slot, each 8 mm into the block
  EXPECT_EQ(found[0]->diagnostic.span.line, 4u);
  EXPECT_DOUBLE_EQ(found[0]->amount, 8.0);
  EXPECT_EQ(found[1]->diagnostic.span.line, 5u);
  auto shallow = verify("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-4.5 F100.\nX20.\nG00 Z5.\nM30\n");
  EXPECT_TRUE(shallow.verifier->findings().empty());
}

TEST(Verifier, PlungeWithAToolThatDoesNotCentreCutWarns) {
  auto plunge = verify("T3 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-2. F100.\nG00 Z5.\nM30\n");
  ASSERT_EQ(plunge.of("NC2082").size(), 1u);
  EXPECT_EQ(plunge.of("NC2082")[0]->diagnostic.span.line, 4u);
  // a ramp over 20 mm (more than the radius) into the same depth is how such a tool goes in
  auto ramp = verify("T3 M06\nM03 S1000\nG90 G00 X-10. Y0 Z1.\nG01 X10. Z-2. F100.\nG00 Z5.\nM30\n");
  EXPECT_TRUE(ramp.of("NC2082").empty());
  // the same plunge with a centre-cutting tool
  auto centre = verify("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-2. F100.\nG00 Z5.\nM30\n");
  EXPECT_TRUE(centre.verifier->findings().empty());
}

TEST(Verifier, CutWithTheSpindleStoppedWarns) {
  auto never = verify("T1 M06\nG90 G00 X0 Y0 Z5.\nG01 Z-1. F100.\nX10.\nG00 Z5.\nM30\n");
  ASSERT_EQ(never.of("NC2083").size(), 2u);
  EXPECT_EQ(never.of("NC2083")[0]->diagnostic.span.line, 3u);
  auto stopped = verify("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-1. F100.\nM05\nX10.\nG00 Z5.\nM30\n");
  ASSERT_EQ(stopped.of("NC2083").size(), 1u);
  EXPECT_EQ(stopped.of("NC2083")[0]->diagnostic.span.line, 6u);
  // a feed move in the air with the spindle stopped removes nothing: no finding
  auto air = verify("T1 M06\nG90 G00 X0 Y0 Z5.\nG01 Z1. F100.\nM30\n");
  EXPECT_TRUE(air.verifier->findings().empty());
}

TEST(Verifier, SpindleFasterThanTheToolWarnsOnce) {
  auto fast = verify("T4 M06\nM03 S10000\nG90 G00 X0 Y0 Z5.\nG01 Z-1. F100.\nX10.\nG00 Z5.\nM30\n");
  ASSERT_EQ(fast.of("NC2084").size(), 1u);
  EXPECT_DOUBLE_EQ(fast.of("NC2084")[0]->amount, 10000);
  auto slow = verify("T4 M06\nM03 S8000\nG90 G00 X0 Y0 Z5.\nG01 Z-1. F100.\nX10.\nG00 Z5.\nM30\n");
  EXPECT_TRUE(slow.verifier->findings().empty());
}

TEST(Verifier, AFindingOnceABlockInALoop) {
  // the same G00 block rapids into fresh material three times
  auto v = verify("T1 M06\nM03 S1000\nG90 G00 Z5.\n#1=0\nWHILE [#1 LT 3] DO1\nG00 X[#1*20] Y0\nG00 Z-1.\nG00 Z5.\n"
                  "#1=#1+1\nEND1\nM30\n");
  ASSERT_EQ(v.of("NC2080").size(), 1u);
  EXPECT_EQ(v.of("NC2080")[0]->diagnostic.span.line, 7u);
}

TEST(Verifier, SlotVolumeAndToolsVolumes) {
  // a slot 40 long, 10 wide, 3 deep with round ends: 40*10*3 + pi*25*3, to the resolution's bound
  auto v = verify("T1 M06\nM03 S1000\nG90 G00 X-20. Y0 Z5.\nG01 Z-3. F200.\nX20.\nG00 Z5.\nM30\n");
  const double exact = 40 * 10 * 3 + std::numbers::pi * 25 * 3;
  const double bound = 3 * std::sqrt(2.0) * 0.1 * (80 + 2 * std::numbers::pi * 5);
  EXPECT_NEAR(v.verifier->map().volume_removed(), exact, bound);
  ASSERT_EQ(v.verifier->volume_by_tool().size(), 1u);
  EXPECT_NEAR(v.verifier->volume_by_tool().at(1), v.verifier->map().volume_removed(), 1e-6);
}

TEST(Verifier, ADefaultToolIsAFlatEndMillOfTheDOffsetInForce) {
  auto profile = test::calculator_mill();
  profile.tool_offsets[27].geometry = 4;  // D27 = 4 mm (offset memory A)
  sim::ToolLibrary none;
  sim::MillTools tools(none, profile);
  EXPECT_EQ(tools.get(7, 0), nullptr);  // D0: no size yet
  const sim::VerifyTool* t7 = tools.get(7, 27);
  ASSERT_NE(t7, nullptr);
  EXPECT_FALSE(t7->from_library);
  EXPECT_EQ(t7->shape.kind(), sim::ToolShape::Kind::flat);
  EXPECT_DOUBLE_EQ(t7->shape.radius(), 4);
  EXPECT_EQ(tools.get(7, 0), t7);  // its size kept once known
  EXPECT_EQ(tools.get(8, 28), nullptr);  // no offset 28
}

TEST(Verifier, ProgramWithoutALibraryCutsWithItsDOffset) {
  // T5 has no library entry; D25 = 3 mm is in force when it cuts a 3 mm deep slot of width 6
  auto profile = test::calculator_mill();
  profile.tool_offsets[25].geometry = 3;
  auto ran = test::run("T5 M06\nM03 S1000\nG90 G00 X-10. Y0 Z5. D25\nG01 Z-3. F200.\nX10.\nG00 Z5.\nM30\n", profile);
  ASSERT_TRUE(ran.result.ok());
  sim::ToolLibrary none;
  sim::MillTools tools(none, profile);
  sim::VerifyOptions o;
  o.cell = 0.1;
  sim::Verifier v(sim::AxisBox{{-50, -50, -20}, {50, 50, 0}}, tools, std::nullopt, o);
  for (const auto& m : ran.moves) v.on_move(m);
  EXPECT_EQ(v.map().height_at(0.05, 2.95), -3);  // inside the 3 mm radius
  EXPECT_EQ(v.map().height_at(0.05, 3.05), 0);   // outside
}

TEST(Verifier, CylinderStockHasNoMaterialOutsideTheBar) {
  sim::Cylinder bar;
  bar.diameter = 40;
  bar.length = 30;
  sim::ToolLibrary none;
  auto profile = test::calculator_mill();
  sim::MillTools tools(none, profile);
  sim::VerifyOptions o;
  o.cell = 0.1;
  sim::Verifier v(bar, tools, std::nullopt, o);
  EXPECT_EQ(v.map().height_at(0.05, 0.05), 0);      // the face
  EXPECT_EQ(v.map().height_at(19.45, 0.05), 0);     // inside the 20 mm radius
  EXPECT_EQ(v.map().height_at(19.75, 19.75), -30);  // outside: the bottom, no material
  EXPECT_NEAR(v.map().volume_removed(), 0, 1e-6);
}

TEST(Verifier, HolderInTheStockWarns) {
  // 25 deep with the holder's face 20 above the tip: its bottom at Z-5, 5 mm into the block beyond
  // the 5 mm the cutter cleared round the axis
  auto deep = verify("T5 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-25. F100.\nG00 Z30.\nM30\n");
  const auto found = deep.of("NC2085");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0]->diagnostic.span.line, 4u);
  EXPECT_DOUBLE_EQ(found[0]->amount, 5.0);
  const double r = std::hypot(found[0]->at[0], found[0]->at[1]);
  EXPECT_GT(r, 5 - 0.1);
  EXPECT_LE(r, 20);
  EXPECT_NE(found[0]->diagnostic.message.find("the holder (20 mm above the tip)"), std::string::npos);
  auto shallow = verify("T5 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-19.9 F100.\nG00 Z30.\nM30\n");
  EXPECT_TRUE(shallow.of("NC2085").empty());
}

TEST(Verifier, ShankWiderThanTheCutWarns) {
  // 10 deep with 8 mm flutes: the 6 mm shank's bottom at Z-2, 2 mm into the block outside the 3 mm hole
  auto deep = verify("T6 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-10. F100.\nG00 Z5.\nM30\n");
  ASSERT_EQ(deep.of("NC2085").size(), 1u);
  EXPECT_DOUBLE_EQ(deep.of("NC2085")[0]->amount, 2.0);
  EXPECT_EQ(deep.of("NC2081").size(), 1u);  // and deeper than the flutes
  auto ok = verify("T6 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG01 Z-7.5 F100.\nG00 Z5.\nM30\n");
  EXPECT_TRUE(ok.verifier->findings().empty());
}

TEST(Verifier, ToolIntoAFixtureWarns) {
  // at Z2 the 10 mm cutter's edge reaches X33, 3 mm into the clamp whose top is at Z5
  auto crash = verify("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z2.\nG01 X28. F300.\nG00 Z20.\nM30\n");
  const auto found = crash.of("NC2086");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0]->diagnostic.span.line, 4u);
  EXPECT_DOUBLE_EQ(found[0]->amount, 3.0);
  EXPECT_GE(found[0]->at[0], 30);
  EXPECT_LE(found[0]->at[0], 33);
  EXPECT_NE(found[0]->diagnostic.message.find("'clamp'"), std::string::npos);
  // stopping 1 mm short of it, and passing over it at Z10, are clean
  auto near = verify("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z2.\nG01 X24. F300.\nG00 Z10.\nX50.\nM30\n");
  EXPECT_TRUE(near.of("NC2086").empty());
  const auto checked = near.verifier->fixtures_checked();
  ASSERT_EQ(checked.size(), 1u);
  EXPECT_EQ(checked[0], "clamp: checked");
}

TEST(Verifier, RapidAsTheMachineMovesIt) {
  // G00 from X0 Z20 to X60 Z2: on the straight line the tool is above Z6.5 over the clamp (X25..45
  // with its 5 mm radius) whose top is Z5; each axis at its own rate (15 m/min both), Z arrives at
  // X18 and the tool crosses the clamp at Z2
  const std::string program = "T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z20.\nG00 X60. Z2.\nG00 Z20.\nM30\n";
  auto dogleg = verify(program);
  ASSERT_EQ(dogleg.of("NC2086").size(), 1u);
  EXPECT_EQ(dogleg.of("NC2086")[0]->diagnostic.span.line, 4u);
  EXPECT_DOUBLE_EQ(dogleg.of("NC2086")[0]->amount, 3.0);
  auto straight = verify(program, kSetup, true);  // No.1401#1 = 1: linear positioning
  EXPECT_TRUE(straight.of("NC2086").empty());
}

TEST(Verifier, RetractOutOfASlopingBallCutIsClean) {
  // two raster rows of a ball over a sine surface, then straight up: the retract's kernel and the
  // sloping cuts' minimisation agree only to rounding, and that is no finding
  std::string program = "T7 M06\nM03 S8000\nG90 G00 X0 Y0 Z5.\n";
  for (int row = 0; row < 2; ++row)
    for (int k = 0; k < 40; ++k)
      program += fmt::format("G01 X{:.3f} Y{:.3f} Z{:.4f} F3000.\n", k * 0.25, row * 0.5,
                             -2 + std::sin(k * 3 * M_PI / 180) * std::cos(row * 4 * M_PI / 180));
  program += "G00 Z5.\nM30\n";
  auto v = verify(program);
  EXPECT_TRUE(v.verifier->findings().empty()) << v.verifier->findings()[0].diagnostic.message;
  EXPECT_GT(v.verifier->map().volume_removed(), 0);
}

// The move stream cut with the tool in the spindle by T number: lines, arcs and rapids cut, the
// moves before the first M06 counted, not cut.
TEST(Verifier, ProgramCutsWithTheToolInTheSpindle) {
  // a slot with T1 (flat, R 5), then T2 (ball, R 3) round a G03 half circle and a G18 arc
  auto r = test::run(
      "G90 G17 G00 X20. Y50. Z5.\nG01 Z-3. F500.\nX80.\nG00 Z5.\nT1 M06\nG00 X20. Y50.\nG01 Z-3. F500.\nX80.\n"
      "G00 Z5.\nT2 M06\nG00 X40. Y20.\nG01 Z-1.\nG03 X60. Y20. R10.\nG18 G02 X70. Z-1. R5.\nM30\n",
      test::calculator_mill());
  ASSERT_TRUE(r.result.ok());
  const sim::SetupFile setup = sim::parse_setup(
      "[tools.1]\nkind = \"flat\"\ndiameter = 10\n[tools.2]\nkind = \"ball\"\ndiameter = 6\n", "s.toml");
  sim::MillTools tools(setup.tools, test::calculator_mill());
  sim::Verifier v(sim::AxisBox{{0, 0, -20}, {100, 100, 0}}, tools, std::nullopt);
  const sim::ZMap& map = v.map();
  for (const auto& m : r.moves) v.on_move(m);
  EXPECT_EQ(v.counts().no_tool, 4u);  // before the first M06
  EXPECT_EQ(v.counts().not_xy_arc, 0u);
  EXPECT_GT(v.counts().cut, 7u);  // the G18 arc as chords
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

// A G18 arc, cut as chords within kArcChord: G02 from X-10 Z0 to X10 Z0 with R10 goes clockwise
// seen from +Y (Z across, X up) through Z-10. A flat end mill of R 2 leaves at X the lowest point
// of the circle within its reach: -10 within it of X0, else -sqrt(100 - (|X| - reach)^2); G03
// goes through Z+10, over the block, and cuts nothing.
TEST(Verifier, G18ArcIsCutAsTheCircle) {
  const sim::SetupFile setup = sim::parse_setup("[tools.1]\nkind = \"flat\"\ndiameter = 4\n", "s.toml");
  for (const char* g : {"G02", "G03"}) {
    auto r = test::run(fmt::format("T1 M06\nM03 S1000\nG90 G00 X-10. Y0 Z5.\nG01 Z0 F100.\nG18 {} X10. Z0 R10.\n"
                                   "G00 Z5.\nM30\n", g),
                       test::calculator_mill());
    ASSERT_TRUE(r.result.ok());
    sim::MillTools tools(setup.tools, test::calculator_mill());
    sim::VerifyOptions o;
    o.cell = 0.1;
    sim::Verifier v(sim::AxisBox{{-15, -5, -15}, {15, 5, 0}}, tools, std::nullopt, o);
    for (const auto& m : r.moves) v.on_move(m);
    const sim::ZMap& map = v.map();
    EXPECT_EQ(v.counts().not_xy_arc, 0u);
    if (std::string(g) == "G03") {
      EXPECT_NEAR(map.volume_removed(), 0, 1e-9);
      continue;
    }
    // the cells' centres at Y0.05: the tool reaches sqrt(4 - 0.05^2) along X; a chord lies within
    // kArcChord of the circle across it, within kArcChord / cos(slope) upright
    const double reach = std::sqrt(4 - 0.05 * 0.05);
    for (double x : {-7.95, -4.05, -1.05, 0.05, 1.95, 5.05, 8.95}) {
      const double c = std::max(std::fabs(x) - reach, 0.0);
      const double want = -std::sqrt(100 - c * c), upright = 10 / std::sqrt(100 - c * c);
      EXPECT_LE(map.height_at(x, 0.05), want + sim::kArcChord * upright + 1e-9) << x;
      EXPECT_GE(map.height_at(x, 0.05), want - 1e-9) << x;  // chords inside the circle: never deeper
    }
  }
}

// NC2089: reference position 1 (machine zero in the profile) in the work coordinates the setup's
// work zero gives: 5 mm into the block when the work zero is 5 mm above machine zero; at the top
// face or far above it, clean.
TEST(Verifier, ReferencePointInsideTheStockWarnsOnce) {
  const auto ran = test::run("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG00 X10.\nM30\n", test::calculator_mill());
  const sim::SetupFile setup = sim::parse_setup(kSetup, "s.toml");
  machine::MachineProfile profile = test::calculator_mill();
  profile.reference_points[0] = {};
  auto found = [&](double origin_z) {
    sim::MillTools tools(setup.tools, profile);
    sim::VerifyOptions o;
    o.cell = 0.5;
    o.profile = &profile;
    sim::Verifier v(*setup.stock, tools, std::nullopt, o, setup.fixtures);
    machine::Setup s;
    s.origin[0] = -10;
    s.origin[2] = origin_z;
    v.on_setup(s);
    for (const auto& m : ran.moves) v.on_move(m);
    v.on_setup(s);  // said once, not again at the next work zero
    for (const auto& m : ran.moves) v.on_move(m);
    std::vector<sim::Finding> out;
    for (const auto& f : v.findings())
      if (f.diagnostic.code == "NC2089") out.push_back(f);
    return out;
  };
  const auto inside = found(5);
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_DOUBLE_EQ(inside[0].amount, 5.0);
  EXPECT_EQ(inside[0].at, (std::array<double, 3>{10, 0, -5}));
  EXPECT_EQ(inside[0].diagnostic.span.line, 3u);  // the first motion after the work zero is set
  EXPECT_TRUE(found(0).empty());     // at the top face
  EXPECT_TRUE(found(-400).empty());  // high above, as a machine's reference point is

  // a bar D40 30 long, face at Z0: the reference point 5 mm down at X19.75 Y19.75 is in the map's
  // square but outside the bar (no material there); at X0 Y0 it is in the bar
  sim::Cylinder bar;
  bar.diameter = 40;
  bar.length = 30;
  auto in_bar = [&](double x, double y) {
    sim::MillTools tools(setup.tools, profile);
    sim::VerifyOptions o;
    o.cell = 0.1;
    o.profile = &profile;
    sim::Verifier v(bar, tools, std::nullopt, o);
    machine::Setup s;
    s.origin = {-x, -y, 5};
    v.on_setup(s);
    for (const auto& m : ran.moves) v.on_move(m);
    return !v.findings().empty() && v.findings()[0].diagnostic.code == "NC2089";
  };
  EXPECT_TRUE(in_bar(0, 0));
  EXPECT_FALSE(in_bar(19.75, 19.75));
}
