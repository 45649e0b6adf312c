// Chamfering and corner R: the corner geometry alone (closed-form cases and random invariants), and
// the interpreter's handling of ,C ,R and the lathe's 90-degree form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "machine/path/compensation.hpp"
#include "machine/path/corner_geometry.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using machine::V2;
using machine::corner::Cut;
using machine::corner::Fault;
using machine::corner::Kind;
using machine::corner::Path;

namespace {

Path line(V2 s, V2 e) { return Path{false, s, e, {}, 0}; }
Path arc(V2 c, double r, double from_deg, double sweep_deg) {
  const double a0 = from_deg * std::numbers::pi / 180, a1 = (from_deg + sweep_deg) * std::numbers::pi / 180;
  return Path{true, {c.x + r * std::cos(a0), c.y + r * std::sin(a0)}, {c.x + r * std::cos(a1), c.y + r * std::sin(a1)},
              c, sweep_deg * std::numbers::pi / 180};
}
double dist(V2 a, V2 b) { return std::hypot(a.x - b.x, a.y - b.y); }
// The distance of x from the path's line or circle.
double off_path(const Path& p, V2 x) {
  if (p.arc) return std::fabs(dist(x, p.c) - dist(p.s, p.c));
  const double len = dist(p.s, p.e);
  return std::fabs(((p.e.x - p.s.x) * (x.y - p.s.y) - (p.e.y - p.s.y) * (x.x - p.s.x)) / len);
}

}  // namespace

TEST(CornerGeometry, ChamferAtRightAngle) {
  const Cut c = machine::corner::cut_corner(line({0, 0}, {10, 0}), line({10, 0}, {10, 10}), Kind::chamfer, 2);
  ASSERT_EQ(c.fault, Fault::none);
  ASSERT_FALSE(c.none);
  EXPECT_NEAR(c.a_end.x, 8, 1e-12);
  EXPECT_NEAR(c.a_end.y, 0, 1e-12);
  EXPECT_NEAR(c.b_start.x, 10, 1e-12);
  EXPECT_NEAR(c.b_start.y, 2, 1e-12);
  EXPECT_NEAR(c.a_part, 0.8, 1e-12);
  EXPECT_NEAR(c.b_part, 0.2, 1e-12);
}

// A turn of 120 degrees: the tangent points lie r * tan(60 deg) from the corner.
TEST(CornerGeometry, RoundAtSharpCorner) {
  const V2 end{10 - 5, 8.660254037844386};
  const Cut c = machine::corner::cut_corner(line({0, 0}, {10, 0}), line({10, 0}, end), Kind::round, 1);
  ASSERT_EQ(c.fault, Fault::none);
  const double t = std::sqrt(3.0);
  EXPECT_NEAR(c.a_end.x, 10 - t, 1e-12);
  EXPECT_NEAR(c.a_end.y, 0, 1e-12);
  EXPECT_NEAR(c.b_start.x, 10 - 0.5 * t, 1e-12);
  EXPECT_NEAR(c.b_start.y, 0.8660254037844386 * t, 1e-12);
  EXPECT_NEAR(c.centre.x, 10 - t, 1e-12);
  EXPECT_NEAR(c.centre.y, 1, 1e-12);
  EXPECT_TRUE(c.ccw);
}

// On an arc the distance from the virtual corner is the chord: 2 asin(c / 2R) of turn.
TEST(CornerGeometry, ChamferOnArcByChord) {
  const Path a = arc({0, 0}, 10, 0, 90);  // (10,0) to (0,10) counter-clockwise
  const Cut c = machine::corner::cut_corner(a, line({0, 10}, {0, 20}), Kind::chamfer, 2);
  ASSERT_EQ(c.fault, Fault::none);
  const double delta = 2 * std::asin(0.1);
  EXPECT_NEAR(c.a_end.x, 10 * std::sin(delta), 1e-12);  // 1.98997..
  EXPECT_NEAR(c.a_end.y, 10 * std::cos(delta), 1e-12);  // 9.8
  EXPECT_NEAR(dist(c.a_end, {0, 10}), 2, 1e-12);
  EXPECT_NEAR(c.a_part, (std::numbers::pi / 2 - delta) / (std::numbers::pi / 2), 1e-12);
  EXPECT_NEAR(c.b_start.y, 12, 1e-12);
}

TEST(CornerGeometry, WithinOneDegreeNothingIsInserted) {
  const double a = 0.9 * std::numbers::pi / 180;
  const Cut c = machine::corner::cut_corner(line({0, 0}, {10, 0}), line({10, 0}, {10 + 10 * std::cos(a), 10 * std::sin(a)}),
                                            Kind::round, 1);
  EXPECT_EQ(c.fault, Fault::none);
  EXPECT_TRUE(c.none);
  const double b = 1.1 * std::numbers::pi / 180;
  EXPECT_FALSE(machine::corner::cut_corner(line({0, 0}, {10, 0}),
                                           line({10, 0}, {10 + 10 * std::cos(b), 10 * std::sin(b)}), Kind::round, 1)
                   .none);
}

TEST(CornerGeometry, FaultsName) {
  EXPECT_EQ(machine::corner::cut_corner(line({0, 0}, {1, 0}), line({1, 0}, {1, 10}), Kind::chamfer, 2).fault,
            Fault::first_too_short);
  EXPECT_EQ(machine::corner::cut_corner(line({0, 0}, {10, 0}), line({10, 0}, {10, 1}), Kind::chamfer, 2).fault,
            Fault::second_too_short);
  EXPECT_EQ(machine::corner::cut_corner(line({0, 0}, {10, 0}), line({10, 0}, {10, 1}), Kind::round, 2).fault,
            Fault::second_too_short);
  EXPECT_EQ(machine::corner::cut_corner(line({0, 0}, {10, 0}), line({10, 0}, {0, 0}), Kind::round, 1).fault,
            Fault::no_solution);
  // a chamfer longer than the arc's diameter
  EXPECT_EQ(machine::corner::cut_corner(line({-10, 0}, {0, 0}), arc({1, 0}, 1, 180, -180), Kind::chamfer, 3).fault,
            Fault::second_too_short);
}

// Random line/arc pairs: whatever is cut must touch both paths as the definitions say.
TEST(CornerGeometry, RandomCornersKeepTheDefinitions) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked_round = 0, checked_chamfer = 0;
  for (int i = 0; i < 20000; ++i) {
    const V2 p{0, 0};
    auto make = [&](bool ending) {
      if (u(rng) < 0) {
        const double ang = u(rng) * std::numbers::pi, len = 2 + 20 * std::fabs(u(rng));
        const V2 far{len * std::cos(ang), len * std::sin(ang)};
        return ending ? line(far, p) : line(p, far);
      }
      const double r = 1 + 20 * std::fabs(u(rng)), at = u(rng) * 180, sweep = u(rng) * 300;
      const V2 c{-r * std::cos(at * std::numbers::pi / 180), -r * std::sin(at * std::numbers::pi / 180)};
      return ending ? arc(c, r, at - sweep, sweep) : arc(c, r, at, sweep);
    };
    const Path a = make(true), b = make(false);
    if (std::fabs(a.sweep) < 0.01 && a.arc) continue;
    if (std::fabs(b.sweep) < 0.01 && b.arc) continue;
    const double amount = 0.05 + 3 * std::fabs(u(rng));
    for (Kind k : {Kind::chamfer, Kind::round}) {
      const Cut c = machine::corner::cut_corner(a, b, k, amount);
      if (c.fault != Fault::none || c.none) continue;
      SCOPED_TRACE(::testing::Message() << "case " << i << (k == Kind::round ? " round" : " chamfer"));
      EXPECT_LT(off_path(a, c.a_end), 1e-7);
      EXPECT_LT(off_path(b, c.b_start), 1e-7);
      EXPECT_GE(c.a_part, 0);
      EXPECT_LE(c.a_part, 1);
      EXPECT_GE(c.b_part, 0);
      EXPECT_LE(c.b_part, 1);
      if (k == Kind::chamfer) {
        EXPECT_NEAR(dist(c.a_end, p), amount, 1e-9);
        EXPECT_NEAR(dist(c.b_start, p), amount, 1e-9);
        ++checked_chamfer;
        continue;
      }
      EXPECT_NEAR(dist(c.centre, c.a_end), amount, 1e-7);
      EXPECT_NEAR(dist(c.centre, c.b_start), amount, 1e-7);
      // tangent: the radius to the touching point is at right angles to the path there
      const V2 ta = machine::corner::tangent(a, c.a_end), tb = machine::corner::tangent(b, c.b_start);
      EXPECT_NEAR((c.a_end.x - c.centre.x) * ta.x + (c.a_end.y - c.centre.y) * ta.y, 0, 1e-7);
      EXPECT_NEAR((c.b_start.x - c.centre.x) * tb.x + (c.b_start.y - c.centre.y) * tb.y, 0, 1e-7);
      // and the arc turns the way both paths go: its direction at the touching points is theirs
      const double side = c.ccw ? 1 : -1;
      const V2 ra{c.a_end.x - c.centre.x, c.a_end.y - c.centre.y};
      EXPECT_GT(side * (-ra.y * ta.x + ra.x * ta.y), 0);
      ++checked_round;
    }
  }
  EXPECT_GT(checked_round, 1000);
  EXPECT_GT(checked_chamfer, 1000);
}

// ---- the interpreter ----

namespace {
machine::MachineProfile lathe(bool ccr = false) {
  auto p = machine::default_lathe();
  p.chamfer_address_c = ccr;
  return p;
}
}  // namespace

TEST(Chamfering, LatheAddressCWithCcr) {
  auto r = test::run("G00 X20. Z2.\nG01 X40. C-1. F0.2\nZ-10.\nM30\n", lathe(true));
  ASSERT_TRUE(r.result.ok()) << r.alarm_code();
  auto m = r.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_NEAR(m[1].end[0], 19, 1e-9);  // radius: X38 diameter, 1 before the corner
  EXPECT_NEAR(m[2].end[0], 20, 1e-9);
  EXPECT_NEAR(m[2].end[2], 1, 1e-9);  // Z2 - 1
  EXPECT_EQ(m[2].line, 2u);
}

// With CCR = 1 a taper with C or R is direct drawing dimension programming: cut as ,C / ,R.
TEST(Chamfering, LatheTaperWithCcrIsOptionalAngle) {
  auto r = test::run("G00 X20. Z0.\nG01 X40. Z-10. C1. F0.2\nZ-20.\nM30\n", lathe(true));
  ASSERT_TRUE(r.result.ok()) << r.alarm_code();
  auto m = r.motions();
  ASSERT_EQ(m.size(), 4u);
  // the taper (10 up, 10 along in radius/Z: 45 deg) ends 1 before (20, -10): (20 - 1/sqrt2, -10 + 1/sqrt2)
  EXPECT_NEAR(m[1].end[0], 20 - std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(m[1].end[2], -10 + std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(m[2].end[2], -11, 1e-9);
}

TEST(Chamfering, LatheAlarms) {
  EXPECT_EQ(test::run("G00 X20. Z2.\nG01 Z-10. K1. F0.2\nX30.\nM30\n", lathe()).alarm_code(), "PS0306");
  EXPECT_EQ(test::run("G00 X20. Z0.\nG01 Z-1. R2. F0.2\nX30.\nM30\n", lathe()).alarm_code(), "PS0055");
  EXPECT_EQ(test::run("G00 X20. Z0.\nG01 Z-10. I1. R2. F0.2\nX30.\nM30\n", lathe()).alarm_code(), "PS0053");
  EXPECT_EQ(test::run("G00 X20. Z0.\nG01 Z-10. R2. F0.2\nG02 X30. Z-15. R5.\nM30\n", lathe()).alarm_code(), "PS0052");
  EXPECT_EQ(test::run("G00 X20. Z0.\nG01 Z-10. R2. F0.2\nX22.\nM30\n", lathe()).alarm_code(), "PS0051");  // 1 < 2
  EXPECT_EQ(test::run("G00 X20. Z0.\nG01 Z-10. I1. F0.2\nX30.\nM30\n", lathe(true)).alarm_code(), "PS0009");
  EXPECT_EQ(test::run("G00 X20. Z0.\nG01 Z-10. A30. F0.2\nM30\n", lathe(true)).alarm_code(), "NC9001");
}

TEST(Chamfering, MacroStatementsBetweenAndVirtualCorner) {
  auto r = test::run("G90 G17 G00 X0 Y0 Z0\nG01 X20. ,C2. F100.\n#100 = #5001\nIF [#100 LT 0] GOTO 9\nY20.\nN9 M30\n");
  ASSERT_TRUE(r.result.ok()) << r.alarm_code();
  EXPECT_NEAR(r.var(100), 20, 1e-9);  // the program position is the virtual corner
  EXPECT_EQ(r.motions().size(), 4u);
}

TEST(Chamfering, IncrementalFromVirtualCorner) {
  auto r = test::run("G91 G17 G01 X20. ,R2. F100.\nY20.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << r.alarm_code();
  auto m = r.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_NEAR(m[2].end[0], 20, 1e-9);
  EXPECT_NEAR(m[2].end[1], 20, 1e-9);
  EXPECT_EQ(m[1].kind, machine::MoveKind::arc);
}

// M codes of the ,C block come after its chamfer; the next block's own ones after its move.
TEST(Chamfering, EventsFollowTheCorner) {
  auto r = test::run("G90 G17 G00 X0 Y0 Z0\nG01 X20. ,C2. F100. M08\nY20. M09\nM30\n");
  ASSERT_TRUE(r.result.ok()) << r.alarm_code();
  std::vector<std::string> kinds;
  for (const auto& m : r.moves) kinds.push_back(machine::to_string(m.kind));
  EXPECT_EQ(kinds, (std::vector<std::string>{"rapid", "line", "line", "coolant", "line", "coolant", "program_end"}));
}

TEST(Chamfering, ZeroAmountAndStraightCornersInsertNothing) {
  EXPECT_EQ(test::run("G17 G01 X20. ,C0 F100.\nY20.\nM30\n").motions().size(), 2u);
  auto r = test::run("G90 G17 G01 X20. Y0 ,C2. F100.\nX40. Y0.1\nM30\n");  // 0.29 deg
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.motions().size(), 2u);
  EXPECT_NEAR(r.motions()[0].end[0], 20, 1e-9);
}

TEST(Chamfering, MillAlarms) {
  EXPECT_EQ(test::run("G17 G01 X20. ,C2. F100.\n").alarm_code(), "PS0052");  // the program ends
  EXPECT_EQ(test::run("G17 G00 X20. ,C2.\nG01 Y20. F100.\nM30\n").alarm_code(), "PS0052");
  EXPECT_EQ(test::run("G17 G01 X20. ,C2. F100.\nG18 Z10.\nM30\n").alarm_code(), "PS0051");
  EXPECT_EQ(test::run("G17 G01 X20. F100.\nG28 X0 ,C2.\nM30\n").alarm_code(), "PS0055");
  EXPECT_EQ(test::run("G17 G01 X20. ,R30. F100.\nY50.\nM30\n").alarm_code(), "PS0055");
  EXPECT_EQ(test::run("G17 G01 X20. ,Q2. F100.\nM30\n").alarm_code(), "PS0053");
  EXPECT_EQ(test::run("G17 G01 X20. ,A2. F100.\nM30\n").alarm_code(), "NC9001");
  EXPECT_EQ(test::run("G65 P9100 ,C2.\nM30\n", machine::default_mill(), {}, {{"O9100.nc", "O9100\nM99\n"}})
                .alarm_code(),
            "PS0055");
  // cutter compensation cancelled in the block after the ,C block
  EXPECT_EQ(test::run("G10 L11 P1 R5.\nG17 G00 X0 Y-10.\nG41 G01 Y0 D1 F100.\nY20. ,C2.\nG40 X20.\nM30\n").alarm_code(),
            "PS0039");
}

// The chamfer of a block in offset mode keeps that block's D (5), though the next block gives D2 (2):
// the tool meets the chamfer's offset line at (-5, 15 + 5 tan 22.5) as in chf_mill_g41.
TEST(Chamfering, HeldMoveKeepsItsOffset) {
  auto r = test::run("G10 L11 P1 R5.\nG10 L11 P2 R2.\nG90 G17 G00 X0 Y-10. Z0\nG41 G01 Y0 D1 F100.\n"
                     "Y20. ,C5.\nX20. D2\nG40 X30.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << r.alarm_code();
  auto m = r.motions();
  ASSERT_GE(m.size(), 4u);
  EXPECT_NEAR(m[2].end[0], -5, 1e-6);
  EXPECT_NEAR(m[2].end[1], 15 + 5 * std::tan(std::numbers::pi / 8), 1e-6);
  EXPECT_EQ(m[3].line, 5u);  // the chamfer, of the ,C block
}
