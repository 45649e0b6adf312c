// A turned part's surface against a profile curve: the shipped G71/G70 example's part, whose
// profile is known in closed form (tests/sim/lathe_section_test.cpp, G71G70PartIsItsProfile),
// against lines on it and beside it; the errors along the normal worked by hand.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "machine/profile.hpp"
#include "sim/lathe_section_sink.hpp"
#include "sim/section_walls.hpp"
#include "sim/setup_toml.hpp"
#include "support/run_program.hpp"

namespace ncurve::sim {
namespace {

struct Turned {
  machine::MachineProfile profile = machine::load_profile(NCURVE_SOURCE_DIR "/profiles/fanuc-lathe.toml");
  SetupFile setup = read_setup(NCURVE_SOURCE_DIR "/examples/lathe-mrc.setup.toml");
  LatheSection section{std::get<Cylinder>(*setup.stock)};
  ProfileMoves moves;
  test::Ran ran;  // its library holds the source the moves' blocks point into
  Turned() {
    std::ifstream in(NCURVE_SOURCE_DIR "/examples/lathe-mrc.nc");
    std::stringstream text;
    text << in.rdbuf();
    ran = test::run(text.str(), profile);
    EXPECT_TRUE(ran.result.ok());
    LatheSectionSink sink(section, setup.tools, profile.lathe_offsets);
    for (const auto& m : ran.moves) {
      sink.on_move(m);
      moves.on_move(m);
    }
  }
  // a profile line X(radius) = x(t), Z = t over [from, to], as gen and analyze place it on a lathe
  WallReport against(const std::string& x, double from, double to) {
    geom::CurveSpec spec;
    spec.name = "expr";
    spec.x = x, spec.y = "0", spec.z = "t", spec.from = from, spec.to = to;
    const geom::Curve curve(spec, {});
    geom::Placement place;
    place.from = {0, -1, 2};
    return measure_section_walls(section, moves, curve, place, WallOptions{});
  }
};

TEST(SectionWalls, TurnedDiameterAndTaperOnTheirCurves) {
  Turned t;
  // the diameter 30 from Z-20 to Z-35 and the taper from X15 at Z-35 to X20 at Z-45
  for (const WallReport& r : {t.against("15", -34, -21), t.against("15+[-35-t]/2", -44, -36)}) {
    ASSERT_GE(r.points.size(), 500u);
    EXPECT_LT(r.largest_gouge, kSectionResolution);
    EXPECT_LT(r.largest_left, kSectionResolution);
    EXPECT_TRUE(r.turned);
  }
}

TEST(SectionWalls, BesideTheCurveIsAGougeOrStockLeft) {
  Turned t;
  // the design 0.02 above the diameter: the part is inside it, a gouge of 0.02; 0.03 below: stock left
  const WallReport above = t.against("15.02", -34, -21), below = t.against("14.97", -34, -21);
  EXPECT_NEAR(above.largest_gouge, 0.02, kSectionResolution);
  EXPECT_EQ(above.left_at, -1);
  EXPECT_NEAR(below.largest_left, 0.03, kSectionResolution);
  EXPECT_EQ(below.gouge_at, -1);
  // the taper 0.02 higher in radius: along its normal 0.02 cos(atan(1/2)) = 0.0178885
  const WallReport taper = t.against("15.02+[-35-t]/2", -44, -36);
  EXPECT_NEAR(taper.largest_gouge, 0.02 * 2 / std::sqrt(5.0), 2 * kSectionResolution);
  // the findings at the blocks that turned the diameter: G70's finishing pass, lines 13..19
  const std::vector<Finding> f = wall_findings(t.moves.block(), above, 0.01);
  ASSERT_FALSE(f.empty());
  for (const Finding& g : f) {
    EXPECT_EQ(g.diagnostic.code, "NC2087");
    EXPECT_NE(g.diagnostic.message.find("radius 15.0200"), std::string::npos) << g.diagnostic.message;
    EXPECT_NEAR(g.at[0], 15, kSectionResolution);  // X: the surface found, radius 15
    EXPECT_EQ(g.at[1], 0);
  }
}

// The 8 mm drill's bore (radius 4 from the face to its point at Z-20): on its curve, clean; the
// design at radius 3.98, the bore 0.02 beyond it (a gouge); at 4.03, 0.03 short (stock left).
TEST(SectionWalls, ABoreIsMeasuredFromItsSide) {
  Turned t;
  const WallReport on = t.against("4", -15, -2), inside = t.against("3.98", -15, -2), outside = t.against("4.03", -15, -2);
  ASSERT_GE(on.points.size(), 500u);
  EXPECT_LT(std::max(on.largest_gouge, on.largest_left), kSectionResolution);
  EXPECT_NEAR(inside.largest_gouge, 0.02, kSectionResolution);
  EXPECT_EQ(inside.left_at, -1);
  EXPECT_NEAR(outside.largest_left, 0.03, kSectionResolution);
  EXPECT_EQ(outside.gouge_at, -1);
  for (const WallPoint& p : inside.points) EXPECT_GT(p.ny, 0);  // into the material: away from the axis
}

TEST(SectionWalls, AFaceIsNotMeasured) {
  Turned t;
  geom::CurveSpec spec;  // the shoulder at Z-60: X from 20 to 25 at one Z
  spec.name = "expr";
  spec.x = "t", spec.y = "0", spec.z = "-60", spec.from = 20.5, spec.to = 24.5;
  const geom::Curve face(spec, {});
  geom::Placement place;
  place.from = {0, -1, 2};
  const WallReport r = measure_section_walls(t.section, t.moves, face, place, WallOptions{});
  EXPECT_TRUE(r.points.empty());
  EXPECT_GT(r.no_design, 400u);
}

}  // namespace
}  // namespace ncurve::sim
