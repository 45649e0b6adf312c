// The geometry of the lathe multiple repetitive cycles (src/machine/stock_removal.*): invariants of
// the roughing passes (inside the stock, never into the shape, depths of Δd but the last) checked on
// fixed and random shapes, and the small cases worked by hand.
#include "machine/cycles/stock_removal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "support/run_program.hpp"

using namespace ncurve::machine::mrc;

namespace {

Element line(P2 a, P2 b) { return Element{a, b, false, {}, 0, false}; }

Shape polyline(const std::vector<P2>& pts) {
  Shape s;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) s.push_back(line(pts[i], pts[i + 1]));
  return s;
}

// X of the shape at z (OD: the part is below it); where a wall stands at z, the lower of its sides.
double shape_x(const Shape& s, double z) {
  double best = 1e300;
  for (const Element& e : s) {
    const double lo = std::min(e.start.y, e.end.y), hi = std::max(e.start.y, e.end.y);
    if (z < lo - 1e-9 || z > hi + 1e-9 || hi - lo < 1e-12) continue;
    double a = 0, b = 1;  // bisection on t: Z is monotone within an element
    const bool up = e.end.y > e.start.y;
    for (int k = 0; k < 60; ++k) {
      const double m = (a + b) / 2;
      ((point_at(e, m).y < z) == up ? a : b) = m;
    }
    best = std::min(best, point_at(e, (a + b) / 2).x);
  }
  return best;
}

// Every point of the path (ends and points inside each move) stays at or above the shape (OD).
void expect_no_gouge(const Path& path, P2 start, const Shape& s) {
  P2 at = start;
  for (const Step& st : path) {
    for (int k = 1; k <= 20; ++k) {
      const double t = k / 20.0;
      P2 p;
      if (!st.arc) {
        p = {at.x + t * (st.end.x - at.x), at.y + t * (st.end.y - at.y)};
      } else {
        Element e{at, st.end, true, st.centre, st.sweep, false};
        p = point_at(e, t);
      }
      const double c = std::min(shape_x(s, p.y - 1e-6), shape_x(s, p.y + 1e-6));
      if (c < 1e299) {
        EXPECT_GE(p.x, c - 1e-6) << "cuts into the shape at z " << p.y << " (x " << p.x << ", shape " << c << ")";
      }
    }
    at = st.end;
  }
}

}  // namespace

TEST(StockRemoval, TypeIPassesAreDeltaDApartAndEndOnTheShape) {
  Roughing r;
  r.start = {20, 2};
  r.shape = polyline({{10.5, 2.5}, {10.5, -9.5}, {15.5, -9.5}, {15.5, -19.5}, {21.5, -19.5}});
  r.depth = 3;
  r.escape = 1;
  const std::vector<double> levels = roughing_levels(r);
  ASSERT_EQ(levels.size(), 4u);
  EXPECT_DOUBLE_EQ(levels[0], 17);
  EXPECT_DOUBLE_EQ(levels[1], 14);
  EXPECT_DOUBLE_EQ(levels[2], 11);
  EXPECT_DOUBLE_EQ(levels[3], 10.5);  // the last: what is left
  const Path p = stock_removal(r);
  expect_no_gouge(p, r.start, r.shape);
  // each feed move along Z runs at a level, from the start line to the shape
  int cuts = 0;
  P2 at = r.start;
  for (const Step& s : p) {
    if (!s.rapid && std::fabs(s.end.x - at.x) < 1e-12 && std::fabs(at.y - 2) < 1e-12) {
      EXPECT_DOUBLE_EQ(s.end.x, levels[cuts]);
      EXPECT_LE(shape_x(r.shape, s.end.y + 1e-6), s.end.x + 1e-9);  // up to its end the shape is below it
      const double beyond = shape_x(r.shape, s.end.y - 1e-6);        // and past it above it (or ended)
      EXPECT_TRUE(beyond > s.end.x + 1e-9) << beyond;
      ++cuts;
    }
    at = s.end;
  }
  EXPECT_EQ(cuts, 4);
  EXPECT_DOUBLE_EQ(p.back().end.x, 20);  // back to the start
  EXPECT_DOUBLE_EQ(p.back().end.y, 2);
}

TEST(StockRemoval, SpansOfAPocketedShape) {
  const Shape s = polyline({{15, 2}, {15, -4}, {10, -9}, {10, -13}, {15, -18}, {15, -22}, {21, -22}});
  auto sp = spans_at(s, 2, 16, -1);
  ASSERT_EQ(sp.size(), 1u);
  EXPECT_DOUBLE_EQ(sp[0].a, 2);
  EXPECT_DOUBLE_EQ(sp[0].b, -22);
  sp = spans_at(s, 2, 14, -1);
  ASSERT_EQ(sp.size(), 1u);
  EXPECT_NEAR(sp[0].a, -5, 1e-12);
  EXPECT_NEAR(sp[0].b, -17, 1e-12);
  EXPECT_TRUE(spans_at(s, 2, 9, -1).empty());  // below the bottom
}

TEST(StockRemoval, TwoPocketsAreCutOneAfterTheOther) {
  // two pockets split by a bump at x 14: the one nearer the start is finished first
  const Shape s = polyline({{16, 0}, {10, -5}, {10, -8}, {14, -10}, {8, -14}, {8, -16}, {20, -18}});
  Roughing r;
  r.start = {20, 1};
  r.shape = s;
  r.depth = 1.5;
  r.escape = 0.5;
  r.pockets = true;
  r.finish_pass = false;  // it runs along both pockets
  const Path p = stock_removal(r);
  expect_no_gouge(p, r.start, s);
  // the cuts along Z below the bump (x < 14) come first in the first pocket (z > -10), then the second
  int last_pocket = 0;
  P2 at = r.start;
  for (const Step& st : p) {
    const bool along_z = !st.rapid && std::fabs(st.end.x - at.x) < 1e-12 && std::fabs(st.end.y - at.y) > 1e-9;
    if (along_z && st.end.x < 14 - 1e-9) {
      const int pocket = (at.y + st.end.y) / 2 > -10 ? 1 : 2;
      EXPECT_GE(pocket, last_pocket);
      last_pocket = pocket;
    }
    at = st.end;
  }
  EXPECT_EQ(last_pocket, 2);
}

TEST(StockRemoval, RandomMonotoneShapesAreRoughedWithoutGouging) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> step(0.5, 6), rise(0, 4);
  for (int n = 0; n < 200; ++n) {
    std::vector<P2> pts{{5 + rise(rng), 1}};
    double z = 1;
    for (int k = 0; k < 5; ++k) {
      z -= step(rng);
      pts.push_back({pts.back().x, z});
      pts.push_back({pts.back().x + rise(rng), z - rise(rng) * 0.5});
      z = pts.back().y;
    }
    pts.push_back({40, pts.back().y});
    Roughing r;
    r.start = {30, 2};
    r.shape = polyline(pts);
    r.depth = 0.5 + step(rng) / 2;
    r.escape = 0.3;
    r.pockets = n % 2 == 1;  // type II must cut a monotone shape safely too
    const Path p = stock_removal(r);
    SCOPED_TRACE(n);
    expect_no_gouge(p, r.start, r.shape);
    const std::vector<double> levels = roughing_levels(r);
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
      const double above = k == 0 ? r.start.x : levels[k - 1];
      EXPECT_NEAR(above - levels[k], r.depth, 1e-9);
    }
    if (!levels.empty()) {
      EXPECT_LE(levels.size() < 2 ? r.start.x - levels.back() : levels[levels.size() - 2] - levels.back(),
                r.depth + 1e-9);
      EXPECT_NEAR(levels.back(), pts.front().x, 1e-9);  // down to the shape's deepest point
    }
    for (const Step& s : p) EXPECT_LE(s.end.x, 40 + 1e-9);  // within the stock and the shape's end
  }
}

TEST(StockRemoval, MonotoneChecks) {
  EXPECT_EQ(first_reversal(polyline({{10, 0}, {10, -5}, {15, -10}, {15, -20}}), 0), -1);
  EXPECT_EQ(first_reversal(polyline({{10, 0}, {15, -5}, {12, -10}}), 0), 1);
  EXPECT_EQ(first_reversal(polyline({{10, 0}, {15, -5}, {16, -2}}), 1), 1);
  // a half circle turns in X inside itself
  Shape arc{Element{{10, 0}, {10, -10}, true, {10, -5}, -std::acos(-1.0), false}};
  EXPECT_EQ(first_reversal(arc, 0), 0);
  // a corner arc that leaves the face along X: its turning point in Z lies 6e-9 mm past Z0 through
  // rounding of the centre (a real program's G03 X3.87 Z-.0542 R.082 from X3.7157 Z0, inch), not a
  // turn back
  const double in = 25.4;
  const P2 c{1.8578562380150385 * in, -0.08199999976272664 * in};
  const P2 a0{3.7157 / 2 * in, 0}, a1{3.87 / 2 * in, -0.0542 * in};
  const double th0 = std::atan2(a0.x - c.x, a0.y - c.y), th1 = std::atan2(a1.x - c.x, a1.y - c.y);
  Shape corner{Element{a0, a1, true, c, th1 - th0, false}, line(a1, {3.9967 / 2 * in, -0.2301 * in})};
  EXPECT_EQ(first_reversal(corner, 1), -1);
  // the same arc carried on 5 degrees further back past its top does turn back
  const double back = th0 - 5 * std::acos(-1.0) / 180;
  const P2 b0{c.x + 0.082 * in * std::sin(back), c.y + 0.082 * in * std::cos(back)};
  Shape bulge{Element{b0, a1, true, c, th1 - back, false}};
  EXPECT_EQ(first_reversal(bulge, 1), 0);
}

TEST(StockRemoval, TransposedTwiceIsTheSame) {
  Shape s{Element{{10, 0}, {15, -5}, true, {15, 0}, 1.2, false}};
  const Shape t = transposed(transposed(s));
  EXPECT_DOUBLE_EQ(t[0].sweep, s[0].sweep);
  EXPECT_DOUBLE_EQ(t[0].centre.x, s[0].centre.x);
  EXPECT_DOUBLE_EQ(transposed(s)[0].sweep, -1.2);  // the mirror turns the arc the other way
  EXPECT_DOUBLE_EQ(transposed(s)[0].start.x, 0);
}

TEST(PatternRepeating, PassesFallFromReliefToAllowance) {
  Pattern p;
  p.start = {25, 4};
  p.shape = polyline({{25, 4}, {10, 0}, {10, -10}, {23, -15}});
  p.shape[0].rapid = true;
  p.relief = {4, 2};
  p.allowance = {0.2, 0.2};
  p.count = 3;
  const Path path = pattern_repeating(p);
  ASSERT_EQ(path.size(), 12u);  // per pass: to the first block's end, two moves, back to A
  const double firsts[3] = {4.2, 2.2, 0.2};
  for (int j = 0; j < 3; ++j) {
    EXPECT_TRUE(path[4 * j].rapid);
    EXPECT_NEAR(path[4 * j].end.x, 10 + firsts[j], 1e-12);
    EXPECT_NEAR(path[4 * j + 3].end.x, 25, 1e-12);
  }
}

TEST(PeckCycle, LastPeckIsWhatIsLeft) {
  Pecking k;
  k.start = {0, 2};
  k.end = {0, -9};
  k.peck = 4;
  k.back = 1;
  const Path p = peck_cycle(k);
  // Z-2, back -1, Z-6, back -5, Z-9, (relief 0 skipped) back to Z2
  ASSERT_EQ(p.size(), 6u);
  EXPECT_DOUBLE_EQ(p[0].end.y, -2);
  EXPECT_DOUBLE_EQ(p[1].end.y, -1);
  EXPECT_DOUBLE_EQ(p[2].end.y, -6);
  EXPECT_DOUBLE_EQ(p[4].end.y, -9);
  EXPECT_DOUBLE_EQ(p[5].end.y, 2);
}

// ---- the cycles through the interpreter ----

namespace {
const char* kTwoBlock =
    "G99 G00 X40. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X20.\nG01 Z-10.\nN20 X42.\nM30\n";

std::vector<ncurve::machine::Move> motions_of(const char* text, ncurve::machine::MachineProfile p) {
  auto r = ncurve::test::run(text, p);
  EXPECT_TRUE(r.result.ok()) << (r.result.alarm ? r.result.alarm->message : "");
  return r.motions();
}

void expect_same_path(const std::vector<ncurve::machine::Move>& a, const std::vector<ncurve::machine::Move>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].kind, b[i].kind) << i;
    EXPECT_NEAR(a[i].end[0], b[i].end[0], 1e-9) << i;
    EXPECT_NEAR(a[i].end[2], b[i].end[2], 1e-9) << i;
  }
}
}  // namespace

TEST(RepetitiveCycles, OneBlockFormatGivesTheDepthByD) {
  auto one = ncurve::machine::default_lathe();
  one.series10_format = true;  // No.0001#1 FCV
  one.mrc_escape = 0.5;      // No.5133: e has no word in this format
  const auto a = motions_of(kTwoBlock, ncurve::machine::default_lathe());
  const auto b = motions_of("G99 G00 X40. Z2.\nG71 P10 Q20 U0.4 W0.1 D2000 F0.2\nN10 G00 X20.\nG01 Z-10.\nN20 X42.\nM30\n", one);
  expect_same_path(a, b);
  EXPECT_GT(a.size(), 8u);
}

TEST(RepetitiveCycles, ParametersStandForAnOmittedFirstBlock) {
  auto p = ncurve::machine::default_lathe();
  p.mrc_depth = 2;     // No.5132
  p.mrc_escape = 0.5;  // No.5133
  const auto a = motions_of(kTwoBlock, ncurve::machine::default_lathe());
  const auto b = motions_of("G99 G00 X40. Z2.\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X20.\nG01 Z-10.\nN20 X42.\nM30\n", p);
  expect_same_path(a, b);
}

TEST(RepetitiveCycles, SystemCNamesThemTwoHigher) {
  auto c = ncurve::machine::default_lathe();
  c.gcode_system = 'C';
  const auto a = motions_of(kTwoBlock, ncurve::machine::default_lathe());
  const auto b = motions_of(
      "G95 G00 X40. Z2.\nG73 U2. R0.5\nG73 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X20.\nG01 Z-10.\nN20 X42.\nM30\n", c);
  expect_same_path(a, b);
}

TEST(RepetitiveCycles, FinishingUnderNoseRadiusCompensationIsCompensated) {
  auto p = ncurve::machine::default_lathe();
  p.lathe_offsets[1] = ncurve::machine::LatheOffset{0, 0, 0, 3, 0, 0, 0.4};
  auto r = ncurve::test::run(
      "T0101\nG99 G00 X40. Z2.\nG42 G00 X36.\nG70 P10 Q20 F0.1\nN10 G00 X20.\nG01 Z-10.\nN20 X42.\nG40 G00 X50.\nM30\n",
      p);
  ASSERT_TRUE(r.result.ok()) << r.result.alarm->message;
  bool compensated = false;
  for (const auto& m : r.motions())
    if (m.line == 6) compensated = compensated || m.compensated;
  EXPECT_TRUE(compensated);
}

TEST(RepetitiveCycles, ShapeAfterTheCycleIsNotRunAgain) {
  auto r = ncurve::test::run(kTwoBlock, ncurve::machine::default_lathe());
  ASSERT_TRUE(r.result.ok());
  for (const auto& m : r.motions()) EXPECT_TRUE(m.line == 1 || m.line == 3) << m.line;
}

// G71 under G42 roughs the shape as the imaginary tip follows it. Tip 3, r = 0.8: the diameters
// and the face come out as programmed; on the taper from (X radius 10, Z2) to (20, -10) the nose
// centre runs r along its normal (10, 12)/|(10, 12)| (Z, X), so the tip (centre - (r, r)) runs on
// Z = 14 - 1.2 X - 0.63795 r (worked by hand): the pass at X30 (radius 15) ends at Z-4.51036
// instead of the uncompensated Z-4.
TEST(RepetitiveCycles, RoughingUnderNoseRadiusCompensationFollowsTheTipPath) {
  auto p = ncurve::machine::default_lathe();
  p.lathe_offsets[1] = ncurve::machine::LatheOffset{0, 0, 0, 3, 0, 0, 0.8};
  const std::string shape = "G71 U2. R0.5\nG71 P10 Q40 U0 W0 F0.2\nN10 G00 X20.\nN20 G01 X40. Z-10.\nN30 Z-20.\nN40 X60.\n";
  auto end_of_pass = [](const ncurve::test::Ran& r, double x_radius) {
    for (const auto& m : r.moves)
      if (m.kind == ncurve::machine::MoveKind::line && m.line == 5 && std::fabs(m.start[0] - x_radius) < 1e-9 &&
          std::fabs(m.end[0] - x_radius) < 1e-9)
        return m.end[2];
    return 1e300;
  };
  auto comp = ncurve::test::run("T0101\nG99 G00 X62. Z2.\nG42 G00 X62. Z2.\n" + shape + "G40 G00 X80.\nM30\n", p);
  ASSERT_TRUE(comp.result.ok()) << ncurve::nc::format(*comp.result.alarm);
  auto plain = ncurve::test::run("T0101\nG99 G00 X62. Z2.\nG40 G00 X62. Z2.\n" + shape + "G00 X80.\nM30\n", p);
  ASSERT_TRUE(plain.result.ok()) << ncurve::nc::format(*plain.result.alarm);
  EXPECT_NEAR(end_of_pass(plain, 15), -4, 1e-9);
  EXPECT_NEAR(end_of_pass(comp, 15), 14 - 1.2 * 15 - 0.63795 * 0.8, 2e-5);
  EXPECT_NEAR(end_of_pass(plain, 29), -20, 1e-9);
  EXPECT_NEAR(end_of_pass(comp, 29), -20, 1e-9);
}
