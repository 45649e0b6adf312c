// The papers' programs: seed 003's hyperbola (verbatim and corrected), seed 000's spiral, seed 001's G102.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "machine/profile.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {
std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
const std::string kDir = NCURVE_SOURCE_DIR;
}  // namespace

TEST(Seed003, VerbatimProgramStopsWhereAFanucControlWould) {
  auto lathe = machine::load_profile(kDir + "/profiles/fanuc-lathe.toml");
  auto r = test::run(slurp(kDir + "/tests/programs/papers/seed003_hyperbola_verbatim.nc"), lathe);
  // X#106+50.: an address takes one value; '+50.' is a number without an address
  EXPECT_EQ(r.alarm_code(), "PS0004");
  EXPECT_EQ(r.alarm_line(), 12u);
  EXPECT_EQ(r.result.alarm->span.column, 10u);
  ASSERT_FALSE(r.parse.empty());
  EXPECT_EQ(r.parse[0].span.line, 12u);
  // with only that fixed, the first G01 has no feed rate: F0.15 comes one block later
  auto b = test::run(slurp(kDir + "/tests/programs/papers/seed003_hyperbola_bracketed.nc"), lathe);
  EXPECT_EQ(b.alarm_code(), "PS0011");
  EXPECT_EQ(b.alarm_line(), 17u);
}

TEST(Seed003, CorrectedProgramCutsTheHyperbola) {
  auto lathe = machine::load_profile(kDir + "/profiles/fanuc-lathe.toml");
  auto r = test::run(slurp(kDir + "/tests/programs/papers/seed003_hyperbola_corrected.nc"), lathe);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  const double a = 100, b = 202.4;
  // the alpha sequence the program computes, in the same floating-point steps
  std::vector<double> zsign_alpha;
  for (double alpha = 40.0; alpha > 0.0; alpha -= 0.2) zsign_alpha.push_back(alpha);
  std::size_t first_loop = zsign_alpha.size();
  for (double alpha = 0.0; alpha < 40.0; alpha += 0.2) zsign_alpha.push_back(alpha);
  std::vector<machine::Move> cuts;
  for (const auto& m : r.motions())
    if (m.kind == machine::MoveKind::line) cuts.push_back(m);
  ASSERT_EQ(cuts.size(), zsign_alpha.size());
  const double deg = std::numbers::pi / 180;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    double alpha = zsign_alpha[i];
    double sign = i < first_loop ? 1 : -1;
    double x_dia = 2 * a / std::cos(alpha * deg);
    double z = sign * b * std::tan(alpha * deg);
    EXPECT_NEAR(2 * cuts[i].end[0], x_dia, 0.0005 + 1e-9) << "point " << i;  // rounded to 0.001 mm on the diameter
    EXPECT_NEAR(cuts[i].end[2], z, 0.0005 + 1e-9) << "point " << i;
    EXPECT_TRUE(cuts[i].feed_per_rev);
    EXPECT_DOUBLE_EQ(cuts[i].feed, 0.15);
  }
  // the start position: G55 X[#106+50.] Z[#109+50.]
  auto first = r.motions().at(0);
  EXPECT_DOUBLE_EQ(2 * first.end[0], 250.0);
  EXPECT_DOUBLE_EQ(first.end[2], 148.0);
}

TEST(Seed000, SpiralMacroPointsLieOnTheSpiral) {
  auto r = test::run(slurp(kDir + "/examples/spiral.nc"));
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  std::vector<machine::Move> cuts;
  for (const auto& m : r.motions())
    if (m.kind == machine::MoveKind::line && m.end[2] == -0.5 && m.start[2] == -0.5) cuts.push_back(m);
  ASSERT_EQ(cuts.size(), 100u);  // 3.6 degree steps over one turn
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    double theta = (i + 1) * 3.6 * std::numbers::pi / 180;
    double r_expected = 1 + 2 * theta;
    double x = r_expected * std::cos(theta), y = r_expected * std::sin(theta);
    EXPECT_NEAR(cuts[i].end[0], x, 0.0005 + 1e-9);
    EXPECT_NEAR(cuts[i].end[1], y, 0.0005 + 1e-9);
  }
  EXPECT_NEAR(r.result.stats.feed_length - 5.5, 48.08, 0.05);  // the paper's 48 mm spiral (plus the plunge)
}

namespace {
machine::MachineProfile g102_mill() {
  auto p = machine::default_mill();
  p.g_code_macros[0] = 102;
  return p;
}
// Line number of the first line of macros/O9010.nc that starts with `prefix`.
std::uint32_t o9010_line(const std::string& prefix) {
  std::ifstream in(kDir + "/macros/O9010.nc");
  std::string line;
  for (std::uint32_t n = 1; std::getline(in, line); ++n)
    if (line.rfind(prefix, 0) == 0) return n;
  return 0;
}
test::Ran g102(const std::string& call) {
  return test::run("G90 G00 X30. Y0.\n" + call + "\nM30\n", g102_mill(), {}, {}, {kDir + "/macros"});
}
}  // namespace

TEST(Seed001, G102CutsTheSpiral) {
  // from radius 30 at 0 degrees, centre at the origin, two turns of 10 mm each to radius 50
  auto r = g102("G102 X50. Y0. I-30. J0. Q10. A1. F500.");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto ms = r.motions();
  ASSERT_EQ(ms.size(), 1u + 720u);
  const std::uint32_t step_line = o9010_line("G01 X["), end_line = o9010_line("N40 G01");
  ASSERT_GT(step_line, 0u);
  for (std::size_t i = 1; i < ms.size(); ++i) {
    double x = ms[i].end[0], y = ms[i].end[1];
    double theta = i * 1.0;  // degrees from the start
    double rr = 30 + 10 * theta / 360;
    EXPECT_NEAR(x, rr * std::cos(theta * std::numbers::pi / 180), 0.0005 + 1e-9) << i;
    EXPECT_NEAR(y, rr * std::sin(theta * std::numbers::pi / 180), 0.0005 + 1e-9) << i;
    EXPECT_EQ(ms[i].line, i < ms.size() - 1 ? step_line : end_line);  // O9010's G01 blocks
  }
}

TEST(Seed001, G102TurnsCAndItsRules) {
  auto by_c = g102("G102 X50. Y0. I-30. J0. C2. A1. F500.");
  ASSERT_TRUE(by_c.result.ok()) << nc::format(*by_c.result.alarm);
  EXPECT_EQ(by_c.motions().size(), 721u);
  // Q wins over C: a wrong C is ignored when Q is given
  auto q_wins = g102("G102 X50. Y0. I-30. J0. Q10. C7. A1. F500.");
  EXPECT_TRUE(q_wins.result.ok());
  EXPECT_EQ(q_wins.motions().size(), 721u);
  // values that disagree with the end point: alarm 3000
  auto conflict = g102("G102 X50. Y0. I-30. J0. Q7. A1. F500.");
  EXPECT_EQ(conflict.alarm_code(), "MC3000");
  EXPECT_EQ(conflict.result.alarm->message, "PARA ERROR");
  auto zero_end = g102("G102 X0. Y0. I-30. J0. C1. A1. F500.");
  EXPECT_EQ(zero_end.alarm_code(), "MC3001");
  // neither Q nor C
  auto missing = g102("G102 X50. Y0. I-30. J0. A1.");
  EXPECT_EQ(missing.alarm_code(), "MC3002");
}

TEST(Seed001, G102BeyondTheSeedClockwiseToleranceAndRamp) {
  // clockwise (D2): from radius 30 at 0 degrees one turn inward... here outward by Q10 to radius 40
  auto cw = g102("G102 X40. Y0. I-30. J0. Q10. A1. D2. F500.");
  ASSERT_TRUE(cw.result.ok()) << nc::format(*cw.result.alarm);
  auto ms = cw.motions();
  ASSERT_EQ(ms.size(), 1u + 360u);
  for (std::size_t i = 1; i < ms.size(); ++i) {
    double theta = -static_cast<double>(i) * std::numbers::pi / 180;  // clockwise
    double rr = 30 + 10 * i / 360.0;
    EXPECT_NEAR(ms[i].end[0], rr * std::cos(theta), 0.0005 + 1e-9) << i;
    EXPECT_NEAR(ms[i].end[1], rr * std::sin(theta), 0.0005 + 1e-9) << i;
  }
  // chord error T instead of an angle step: every chord's largest distance from the spiral within T
  // (plus the rounding of its end points), and fewer points where the radius is small
  const double t = 0.002;
  auto tol = g102("G102 X50. Y0. I-30. J0. Q10. T0.002 F500.");
  ASSERT_TRUE(tol.result.ok()) << nc::format(*tol.result.alarm);
  auto pts = tol.motions();
  ASSERT_GT(pts.size(), 20u);
  double unwrap = 0, last = 0, worst = 0;
  auto angle = [&](const auto& p) {
    double a = std::atan2(p[1], p[0]);
    while (a + unwrap < last - 1e-9) unwrap += 2 * std::numbers::pi;
    return last = a + unwrap;
  };
  angle(pts[0].end);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const auto &p0 = pts[i - 1].end, &p1 = pts[i].end;
    double a0 = last, a1 = angle(p1);
    for (int k = 1; k < 32; ++k) {  // distance of spiral points to the chord
      double th = a0 + (a1 - a0) * k / 32, rr = 30 + 10 * th / (2 * std::numbers::pi);
      double x = rr * std::cos(th), y = rr * std::sin(th);
      double ex = p1[0] - p0[0], ey = p1[1] - p0[1];
      worst = std::max(worst, std::fabs((x - p0[0]) * ey - (y - p0[1]) * ex) / std::hypot(ex, ey));
    }
  }
  EXPECT_LE(worst, t + 0.0008);
  EXPECT_GT(worst, 0.5 * t);  // the step uses the tolerance
  // a spiral ramp: K is the Z lead per turn, Z an end Z that wins over K
  auto ramp = test::run("G90 G00 X30. Y0. Z0.\nG102 X40. Y0. I-30. J0. Q10. A1. K-2. F500.\nM30\n", g102_mill(), {},
                        {}, {kDir + "/macros"});
  ASSERT_TRUE(ramp.result.ok());
  auto rm = ramp.motions();
  EXPECT_NEAR(rm[180].end[2], -1.0, 1e-3);
  EXPECT_NEAR(rm.back().end[2], -2.0, 1e-9);
  auto to_z = test::run("G90 G00 X30. Y0. Z0.\nG102 X40. Y0. Z-5. I-30. J0. Q10. A1. K-2. F500.\nM30\n", g102_mill(),
                        {}, {}, {kDir + "/macros"});
  ASSERT_TRUE(to_z.result.ok());
  EXPECT_NEAR(to_z.motions()[180].end[2], -2.5, 1e-3);
  // a direction other than 2 or 3
  EXPECT_EQ(g102("G102 X40. Y0. I-30. J0. Q10. A1. D5. F500.").alarm_code(), "MC3003");
}
