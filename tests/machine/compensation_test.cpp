// Cutter radius compensation C against closed-form geometry: hand-worked corners of the FANUC
// manuals' rules, the alarms, and a property test on random closed contours of lines and arcs.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;
using machine::MoveKind;

namespace {

struct P2 {
  double x, y;
};

void expect_end(const machine::Move& m, double x, double y, const char* what) {
  EXPECT_NEAR(m.end[0], x, 1e-9) << what << " (line " << m.line << ")";
  EXPECT_NEAR(m.end[1], y, 1e-9) << what << " (line " << m.line << ")";
}

}  // namespace

// A clockwise square with G41 (tool outside) and 5 mm: start-up and cancel of type A put the
// vector perpendicular to the next / previous block; outer 90-degree corners meet at the offset
// lines' intersection.
TEST(Compensation, SquareTypeA) {
  auto r = run("G10 L11 P1 R5.\nG90 G17 G00 X0 Y0\nG41 G01 X20. Y10. D1 F100.\nY50.\nX60.\nY10.\nX20.\n"
               "G40 X0 Y0\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto ms = r.motions();
  ASSERT_EQ(ms.size(), 7u);
  expect_end(ms[1], 15, 10, "start-up: perpendicular to Y50.");
  expect_end(ms[2], 15, 55, "outer corner: intersection");
  expect_end(ms[3], 65, 55, "outer corner");
  expect_end(ms[4], 65, 5, "outer corner");
  expect_end(ms[5], 20, 5, "end of the last block before cancel: perpendicular");
  expect_end(ms[6], 0, 0, "cancel block ends without a vector");
  EXPECT_TRUE(ms[2].compensated);
  EXPECT_DOUBLE_EQ(ms[2].programmed_end[0], 20.0);
  EXPECT_DOUBLE_EQ(ms[2].programmed_end[1], 50.0);
}

// G42 along a line into a counter-clockwise arc (outside: radius 20 + 5), a line, a clockwise arc
// (inside: 20 - 5) and an inner corner of lines (intersection).
TEST(Compensation, ArcsKeepTheirCentreAndInnerCornersIntersect) {
  auto r = run("G10 L11 P1 R5.\nG90 G00 X0 Y0\nG42 G01 X20. Y0 D1 F100.\nG03 X40. Y20. R20.\nG01 Y40.\n"
               "G02 X60. Y60. R20.\nG01 X80.\nY0\nG40 X100. Y-20.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto ms = r.motions();
  ASSERT_EQ(ms.size(), 8u);
  expect_end(ms[1], 20, -5, "start-up");
  EXPECT_EQ(ms[2].kind, MoveKind::arc);
  expect_end(ms[2], 45, 20, "arc outside");
  EXPECT_NEAR(ms[2].center[0], 20, 1e-12);
  EXPECT_NEAR(ms[2].center[1], 20, 1e-12);
  expect_end(ms[3], 45, 40, "tangent line");
  expect_end(ms[4], 60, 55, "arc inside");
  expect_end(ms[5], 75, 55, "inner corner");
  expect_end(ms[6], 75, 0, "before cancel");
}

// An outer corner under 90 degrees: the first path runs on by r along itself, one extra move goes to
// r before the second path's offset start (FANUC's two extra vectors).
TEST(Compensation, AcuteOuterCornerInsertsAMove) {
  // up the Y axis, then back down at 45 degrees: a 45-degree outer corner for G42 (tool right: +X side)
  auto r = run("G10 L11 P1 R2.\nG90 G00 X0 Y-10.\nG42 G01 X0 Y0 D1 F100.\nY20.\nX-20. Y0\nG40 X-30.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto ms = r.motions();
  ASSERT_EQ(ms.size(), 6u);
  const double s = std::sqrt(0.5);
  // line 1 (up, tool at +X): offset x = 2, runs on to y = 20 + 2
  expect_end(ms[2], 2, 22, "extended by r");
  // second direction (-s, -s); its right normal is (-s, s); start r back: (0,20) + 2(-s,s) - 2(-s,-s)
  expect_end(ms[3], 0 - 2 * s + 2 * s, 20 + 2 * s + 2 * s, "extra move");
  EXPECT_EQ(ms[3].line, 4u);  // the extra move belongs to the block before the corner
}

TEST(Compensation, AlarmsAtTheirBlocks) {
  // G02 in the start-up block
  auto a = run("G10 L11 P1 R5.\nG00 X0 Y0\nG41 G02 X20. Y0 R10. D1 F100.\nM30\n");
  EXPECT_EQ(a.alarm_code(), "PS0034");
  EXPECT_EQ(a.alarm_line(), 3u);
  // plane change in offset mode
  auto b = run("G10 L11 P1 R5.\nG00 X0 Y0\nG41 G01 X20. D1 F100.\nG18\nM30\n");
  EXPECT_EQ(b.alarm_code(), "PS0037");
  EXPECT_EQ(b.alarm_line(), 4u);
  // a slot 6 mm wide for a 10 mm cutter: the offset path of the bottom runs backwards
  auto c = run("G10 L11 P1 R5.\nG00 X-20. Y20.\nG41 G01 X0 Y20. D1 F100.\nY0\nX6.\nY20.\nG40 X20.\nM30\n");
  EXPECT_EQ(c.alarm_code(), "PS0041");
  EXPECT_EQ(c.alarm_line(), 5u);
  // an inner arc of radius 3 with a 5 mm cutter
  auto d = run("G10 L11 P1 R5.\nG00 X0 Y0\nG41 G01 X10. D1 F100.\nG03 X16. Y0 R3.\nG01 X30.\nG40 Y-10.\nM30\n");
  EXPECT_EQ(d.alarm_code(), "PS0041");
  EXPECT_EQ(d.alarm_line(), 4u);
  // the moves before the alarm are written out
  EXPECT_FALSE(c.motions().empty());
}

// More blocks without motion in the plane than the control reads past: the vector at the end of the
// block before them stays perpendicular, the next block starts from there, and a warning names the
// resulting overcut: here the tool is 5 mm from the wall it should keep 5 mm from... at the start of
// an inner corner: Y50 then X60 with G41 inside a square, perpendicular end (25, 50) is 0 mm from the
// top wall y = 50 + ... worked below.
TEST(Compensation, LostReadAheadWarnsWithTheOvercut) {
  // G41 going up x = 20, then right along y = 50: the tool is on the left, outside the square for up
  // (x = 15) and above for right (y = 55): an outer corner. With two Z blocks between, the vector at
  // (20, 50) ends perpendicular to the up move: (15, 50); the next move starts there, 5 mm below its
  // offset line y = 55: an overcut of 5 mm into the top edge.
  auto r = run("G10 L11 P1 R5.\nG90 G00 X0 Y0\nG41 G01 X20. Y10. D1 F100.\nY50.\nZ1.\nZ0\nX60.\nY10.\n"
               "G40 X0 Y0\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  bool warned = false;
  for (const auto& w : r.result.warnings)
    if (w.code == "NC2101") {
      warned = true;
      EXPECT_NE(w.message.find("an overcut of 5.0000 mm"), std::string::npos) << w.message;
      EXPECT_EQ(w.span.line, 6u);
    }
  EXPECT_TRUE(warned);
  auto ms = r.motions();
  expect_end(ms[2], 15, 50, "perpendicular end");
  // one Z block alone is within the read-ahead: no warning, the corner is the intersection
  auto ok = run("G10 L11 P1 R5.\nG90 G00 X0 Y0\nG41 G01 X20. Y10. D1 F100.\nY50.\nZ1.\nX60.\nY10.\n"
                "G40 X0 Y0\nM30\n");
  ASSERT_TRUE(ok.result.ok());
  for (const auto& w : ok.result.warnings) EXPECT_NE(w.code, "NC2101");
  expect_end(ok.motions()[2], 15, 55, "intersection through one block without motion");
}

TEST(Compensation, StartUpTypeBGoesToTheIntersection) {
  auto p = machine::default_mill();
  p.compensation.startup_type_b = true;
  // start-up along +X to (20, 0), next block up: G41 tool on the left; outer obtuse corner (90 deg)
  auto r = run("G10 L11 P1 R5.\nG90 G00 X0 Y0\nG42 G01 X20. D1 F100.\nY30.\nG40 X0\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  // G42: right of +X is -Y, right of +Y is +X: offset lines y = -5 and x = 25 meet at (25, -5)
  expect_end(r.motions()[1], 25, -5, "type B start-up: intersection");
  auto a = run("G10 L11 P1 R5.\nG90 G00 X0 Y0\nG42 G01 X20. D1 F100.\nY30.\nG40 X0\nM30\n");
  expect_end(a.motions()[1], 25, 0, "type A start-up: perpendicular to the next block");
}

TEST(Compensation, RadiusFromOffsetMemoryCAndNegativeRadiusSwapsSides) {
  auto p = machine::default_mill();
  p.offset_memory = machine::OffsetMemory::C;
  auto r = run("G10 L12 P3 R4.\nG10 L13 P3 R-0.5\nG90 G00 X0 Y0\nG41 G01 X10. Y0 D3 F100.\nX30.\nG40 X40.\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  expect_end(r.motions()[2], 30, 3.5, "D geometry 4 + wear -0.5 on the left");
  auto n = run("G10 L11 P1 R-5.\nG90 G00 X0 Y0\nG41 G01 X10. Y0 D1 F100.\nX30.\nG40 X40.\nM30\n");
  expect_end(n.motions()[2], 30, -5, "a negative offset puts G41 on the right");
}

// Random closed contours of lines and arcs (fixed seed): every compensated move of the contour
// lies at the radius from its own programmed block on the commanded side, no point of the tool
// path comes nearer the contour than the radius, and the path is continuous.
TEST(Compensation, RandomContoursKeepTheRadius) {
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0, alarms = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 5 + static_cast<int>(u(rng) * 8);
    const double tool = std::round((0.5 + 2.5 * u(rng)) * 1000) / 1000;
    const bool left = u(rng) < 0.5;
    std::vector<P2> v;
    for (int i = 0; i < n; ++i) {
      double a = 2 * std::numbers::pi * (i + 0.2 + 0.6 * u(rng)) / n;
      double rad = 30 + 30 * u(rng);
      v.push_back({std::round(rad * std::cos(a) * 1000) / 1000, std::round(rad * std::sin(a) * 1000) / 1000});
    }
    std::string prog = fmt::format("G10 L11 P1 R{:.3f}\nG90 G17 G00 X0 Y0\n{} G01 X{:.3f} Y{:.3f} D1 F500.\n",
                                   tool, left ? "G41" : "G42", v[0].x, v[0].y);
    const int first_line = 4;
    std::vector<std::string> blocks;
    for (int k = 0; k < n; ++k) {
      const P2 a = v[k], b = v[(k + 1) % n];
      if (u(rng) < 0.4) {
        double chord = std::hypot(b.x - a.x, b.y - a.y);
        double R = chord * (1.0 + 2 * u(rng));  // bulges of at most 0.13 chord keep the contour clear of itself
        blocks.push_back(fmt::format("G0{} X{:.3f} Y{:.3f} R{:.3f}\n", u(rng) < 0.5 ? 2 : 3, b.x, b.y, R));
      } else {
        blocks.push_back(fmt::format("G01 X{:.3f} Y{:.3f}\n", b.x, b.y));
      }
    }
    blocks.push_back(blocks.front());  // round again to pass the first corner in offset mode
    for (const auto& blk : blocks) prog += blk;
    prog += "G40 G01 X0 Y0\nM30\n";
    auto r = run(prog);
    if (!r.result.ok()) {
      ASSERT_TRUE(r.alarm_code() == "PS0041" || r.alarm_code() == "PS0033") << nc::format(*r.result.alarm) << prog;
      ++alarms;
      continue;
    }
    ++checked;
    // the programmed contour: the uncompensated run's moves
    auto plain = run(std::string(prog).replace(prog.find(left ? "G41" : "G42"), 3, "G40"));
    ASSERT_TRUE(plain.result.ok());
    std::vector<machine::Move> contour;
    for (const auto& m : plain.motions())
      if (m.line >= static_cast<std::uint32_t>(first_line) && m.line < static_cast<std::uint32_t>(first_line + n + 1))
        contour.push_back(m);
    auto distance_to = [](const machine::Move& c, double x, double y) {
      if (c.kind != MoveKind::arc) {
        double dx = c.end[0] - c.start[0], dy = c.end[1] - c.start[1];
        double t = std::clamp(((x - c.start[0]) * dx + (y - c.start[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
        return std::hypot(x - c.start[0] - t * dx, y - c.start[1] - t * dy);
      }
      double a0 = std::atan2(c.start[1] - c.center[1], c.start[0] - c.center[0]);
      double a = std::atan2(y - c.center[1], x - c.center[0]);
      double rel = a - a0;
      if (c.sweep > 0) {
        while (rel < 0) rel += 2 * std::numbers::pi;
      } else {
        while (rel > 0) rel -= 2 * std::numbers::pi;
      }
      double R = std::hypot(c.start[0] - c.center[0], c.start[1] - c.center[1]);
      if (std::fabs(rel) <= std::fabs(c.sweep)) return std::fabs(std::hypot(x - c.center[0], y - c.center[1]) - R);
      return std::min(std::hypot(x - c.start[0], y - c.start[1]), std::hypot(x - c.end[0], y - c.end[1]));
    };
    auto ms = r.motions();
    for (std::size_t i = 1; i < ms.size(); ++i) {
      ASSERT_NEAR(ms[i].start[0], ms[i - 1].end[0], 1e-9) << prog;
      ASSERT_NEAR(ms[i].start[1], ms[i - 1].end[1], 1e-9) << prog;
    }
    for (const auto& m : ms) {
      // the start-up and cancel blocks, and the blocks next to them whose far vectors they set,
      // go to and from the offset without keeping it (the contour's corners are all passed again)
      if (m.line <= static_cast<std::uint32_t>(first_line) || m.line >= static_cast<std::uint32_t>(first_line + n))
        continue;
      for (int s = 0; s <= 16; ++s) {
        double f = s / 16.0, x, y;
        if (m.kind == MoveKind::arc) {
          double a0 = std::atan2(m.start[1] - m.center[1], m.start[0] - m.center[0]);
          double R0 = std::hypot(m.start[0] - m.center[0], m.start[1] - m.center[1]);
          x = m.center[0] + R0 * std::cos(a0 + f * m.sweep);
          y = m.center[1] + R0 * std::sin(a0 + f * m.sweep);
        } else {
          x = m.start[0] + f * (m.end[0] - m.start[0]);
          y = m.start[1] + f * (m.end[1] - m.start[1]);
        }
        double nearest = 1e300;
        for (const auto& c : contour) nearest = std::min(nearest, distance_to(c, x, y));
        ASSERT_GE(nearest, tool - 1e-6) << "gouge at " << x << "," << y << " line " << m.line << "\n" << prog;
        // a contour block's own move keeps exactly the radius, on the commanded side
        const bool own = m.line >= static_cast<std::uint32_t>(first_line + 1) &&
                         m.line < static_cast<std::uint32_t>(first_line + n + 1) && m.compensated && !m.corner &&
                         m.programmed_end == contour[m.line - first_line].end;
        if (!own) continue;
        const auto& c = contour[m.line - first_line];
        if (c.kind == MoveKind::arc) {
          double R = std::hypot(c.start[0] - c.center[0], c.start[1] - c.center[1]);
          double side = (left ? 1 : -1) * (c.sweep > 0 ? 1 : -1);  // left of a counter-clockwise arc: inside
          ASSERT_NEAR(std::hypot(x - c.center[0], y - c.center[1]), R - side * tool, 1e-9) << prog;
        } else {
          double dx = c.end[0] - c.start[0], dy = c.end[1] - c.start[1], L = std::hypot(dx, dy);
          double across = (dx * (y - c.start[1]) - dy * (x - c.start[0])) / L;  // + on the left
          ASSERT_NEAR(across, left ? tool : -tool, 1e-9) << prog;
        }
      }
    }
  }
  EXPECT_GT(checked, 1000) << alarms << " contours alarmed";
}

// --nose-centre writes the nose centre: the start-up of an outside chamfer with tip 3 (G42, nose
// 0.8) ends with the centre on the chamfer's offset, perpendicular to it at its start (Z0, X16 dia):
// Z 0.8 sin 45 = 0.5657, X 16 + 2 * 0.8 cos 45 = 17.1314 (diameter); the tip is 0.8 less in Z and
// 2 * 0.8 less in X.
TEST(Compensation, NoseCentreOrTip) {
  auto p = machine::default_lathe();
  p.lathe_offsets[1].r = 0.8;
  p.lathe_offsets[1].tip = 3;
  const std::string prog = "T0101\nG99 G40 G00 X16. Z5.\nG42 G01 Z0. F0.1\nX20. Z-2.\nZ-15.\nG40 G00 X40. Z5.\nM30\n";
  machine::RunOptions centre;
  centre.nose_centre = true;
  auto c = run(prog, p, centre);
  ASSERT_TRUE(c.result.ok()) << nc::format(*c.result.alarm);
  const double s = std::sqrt(0.5);
  EXPECT_NEAR(c.motions()[1].end[2], 0.8 * s, 1e-9);
  EXPECT_NEAR(2 * c.motions()[1].end[0], 16 + 2 * 0.8 * s, 1e-9);
  auto t = run(prog, p);
  EXPECT_NEAR(t.motions()[1].end[2], 0.8 * s - 0.8, 1e-9);
  EXPECT_NEAR(2 * t.motions()[1].end[0], 16 + 2 * 0.8 * s - 2 * 0.8, 1e-9);
}

// #5041.. (current position) includes the compensation: after the start-up block (type A, vector
// perpendicular to X40.'s direction +X: (0,40) + (0,5)) while X40. waits for its end vector;
// #5001.. is the programmed end point of the last block read.
TEST(Compensation, CurrentPositionReadsTheToolCentre) {
  auto r = run("G10 L11 P1 R5.\nG90 G17 G00 X0 Y-10.\nG41 G01 Y40. D1 F100.\nX40.\n#100=#5041\n#101=#5042\n"
               "#102=#5001\n#103=#5002\n#104=#5021\nY0\nG40 X60.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_NEAR(r.var(100), 0.0, 1e-9);
  EXPECT_NEAR(r.var(101), 45.0, 1e-9);
  EXPECT_NEAR(r.var(102), 40.0, 1e-9);
  EXPECT_NEAR(r.var(103), 40.0, 1e-9);
  EXPECT_NEAR(r.var(104), 0.0, 1e-9);  // machine = work here: no offsets
}

// G92 in offset mode: the block before ends perpendicular ((0,40) + (-5,0)), the tool keeps its place
// in the new coordinates ((-5,40) + (100,60)), and the next move starts up again (type A: vector
// perpendicular to Y60.'s direction -Y, i.e. +X, at (140,100)).
TEST(Compensation, CoordinateSystemSettingStartsUpAgain) {
  auto r = run("G10 L11 P1 R5.\nG90 G17 G00 X0 Y-10.\nG41 G01 Y40. D1 F100.\nG92 X100. Y100.\nG01 X140.\nY60.\n"
               "G40 X160.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto ms = r.motions();
  ASSERT_EQ(ms.size(), 5u);
  expect_end(ms[1], -5, 40, "perpendicular before G92");
  expect_end(ms[2], 145, 100, "start-up again in the new system");
  expect_end(ms[3], 145, 60, "last block before cancel");
  expect_end(ms[4], 160, 60, "cancel");
}

// Type C (No.5003#1): G41 alone shifts the tool in its own block, perpendicular to the next move;
// an M code read between comes after the shift; a cancel block with motion follows SUP (type A).
TEST(Compensation, TypeCShiftsInTheStartUpBlock) {
  auto profile = machine::default_mill();
  profile.compensation.startup_type_c = true;
  auto r = run("G10 L11 P1 R5.\nG90 G17 G00 X0 Y-10.\nG41 D1\nM08\nG01 Y40. F100.\nG40 X0 Y60.\nM30\n", profile);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  std::vector<machine::Move> ms;
  for (const auto& m : r.moves)
    if (m.is_motion() || m.kind == MoveKind::coolant) ms.push_back(m);
  ASSERT_EQ(ms.size(), 5u);
  EXPECT_EQ(ms[1].kind, MoveKind::rapid);
  EXPECT_EQ(ms[1].line, 3u);
  expect_end(ms[1], -5, -10, "the shift of the G41 block");
  EXPECT_EQ(ms[2].kind, MoveKind::coolant);
  expect_end(ms[2], -5, -10, "M08 where the tool is");
  expect_end(ms[3], -5, 40, "cancel type A: perpendicular to the last block");
  expect_end(ms[4], 0, 60, "cancel block");
  // G41 then G40, both without motion: nothing moves
  auto q = run("G10 L11 P1 R5.\nG90 G17 G00 X0 Y-10.\nG41 D1\nG40\nG01 X10. F100.\nM30\n", profile);
  ASSERT_TRUE(q.result.ok()) << nc::format(*q.result.alarm);
  auto mq = q.motions();
  ASSERT_EQ(mq.size(), 2u);
  EXPECT_EQ(mq[1].start[0], 0.0);
  expect_end(mq[1], 10, -10, "no offset left");
}

namespace {
int count_code(const ncurve::test::Ran& r, const std::string& code) {
  int n = 0;
  for (const auto& w : r.result.warnings) n += w.code == code;
  return n;
}
}  // namespace

// G41/G42 with D0 or no D runs the tool's centre on the contour with no alarm on the control: a
// warning at the start-up block (NC2070); a D whose offset the profile lacks says so (NC2071).
TEST(Compensation, ZeroRadiusOffsetWarns) {
  for (const char* start : {"G41 G01 X30. Y0 D0 F400.", "G41 G01 X30. Y0 F400.", "G42 D0 G01 X30. Y0 F400."}) {
    auto r = run(fmt::format("G90 G00 X0 Y-20.\n{}\nY30.\nX0\nG40 Y-20.\nM30\n", start));
    ASSERT_TRUE(r.result.ok()) << start;
    EXPECT_EQ(count_code(r, "NC2070"), 1) << start;
    EXPECT_EQ(r.result.warnings.front().span.line, 2u) << start;
  }
  auto unset = run("G90 G00 X0 Y-20.\nG41 G01 X30. Y0 D7 F400.\nY30.\nG40 X0 Y-20.\nM30\n");
  EXPECT_EQ(count_code(unset, "NC2071"), 1);
  EXPECT_EQ(count_code(unset, "NC2070"), 0);
}

TEST(Compensation, RadiusOffsetGivenDoesNotWarn) {
  // D on the start-up block, or on a block of its own before the first move, or changed in offset mode
  for (const char* prog : {"G10 L11 P1 R5.\nG90 G00 X0 Y-20.\nG41 G01 X30. Y0 D1 F400.\nY30.\nG40 X0 Y-20.\nM30\n",
                           "G10 L11 P1 R5.\nG90 G00 X0 Y-20.\nG41\nD1\nG01 X30. Y0 F400.\nY30.\nG40 X0 Y-20.\nM30\n",
                           "G10 L11 P1 R5.\nG10 L11 P2 R4.\nG41 G01 X30. Y0 D1 F400.\nY30. D2\nG40 X0 Y-20.\nM30\n"}) {
    auto r = run(prog);
    ASSERT_TRUE(r.result.ok()) << prog;
    EXPECT_EQ(count_code(r, "NC2070") + count_code(r, "NC2071"), 0) << prog;
  }
  // a lathe's tool-nose radius compensation with a sharp tool is not a mistake of the program
  auto lathe = run("G00 X40. Z5.\nG42 G01 X30. Z0 F0.2\nZ-20.\nG40 X40.\nM30\n", machine::default_lathe());
  EXPECT_EQ(count_code(lathe, "NC2070") + count_code(lathe, "NC2071"), 0);
}
