// Polar coordinate interpolation (G12.1) and cylindrical interpolation (G07.1): the machine's X and
// C at each block's end against hand-worked tests/programs/polar-cylindrical/*.expected.ends, and
// every emitted point (and the machine's straight X-C motion between points) checked on the
// programmed contour in closed form, independently of ncurve's geometry.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include "machine/path/developed_path.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
namespace fs = std::filesystem;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr int X = 0, Z = 2, C = 5;
// the hand-worked programs NAME.nc, their machines NAME.toml and their NAME.expected.ends
const fs::path kPrograms = fs::path(NCURVE_SOURCE_DIR) / "tests" / "programs" / "polar-cylindrical";

struct Pt {
  double x, y;
};
double seg_dist(Pt p, Pt a, Pt b) {  // distance from p to segment ab
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}
// The polar plane's point of a machine position: X (a diameter) and C (degrees) on a lathe.
Pt plane_of(const machine::AxisVector& v) { return {v[X] * std::cos(v[C] * kPi / 180), v[X] * std::sin(v[C] * kPi / 180)}; }

test::Ran run_file(const std::string& name, machine::RunOptions options = {}) {
  const fs::path& dir = kPrograms;
  machine::MachineProfile profile = machine::load_profile((dir / (name + ".toml")).string());
  std::ifstream in(dir / (name + ".nc"));
  std::stringstream text;
  text << in.rdbuf();
  return test::run(text.str(), profile, options);
}

// "line X(dia) Z C" rows of NAME.expected.ends: the last move of each line ends there.
void check_ends(const std::string& name) {
  SCOPED_TRACE(name);
  const test::Ran r = run_file(name);
  ASSERT_TRUE(r.result.ok()) << r.alarm_code() << " " << r.result.alarm->message;
  const fs::path file = kPrograms / (name + ".expected.ends");
  std::ifstream in(file);
  ASSERT_TRUE(in) << file;
  int rows = 0;
  for (std::string l; std::getline(in, l);) {
    if (l.empty() || l[0] == '#') continue;
    std::istringstream row(l);
    std::uint32_t line = 0;
    double x = 0, z = 0, c = 0;
    row >> line >> x >> z >> c;
    const machine::Move* last = nullptr;
    for (const auto& m : r.moves)
      if (m.is_motion() && m.line == line) last = &m;
    ASSERT_NE(last, nullptr) << "no move at line " << line;
    EXPECT_NEAR(last->end[X] * 2, x, 1e-5) << "line " << line;
    EXPECT_NEAR(last->end[Z], z, 1e-6) << "line " << line;
    EXPECT_NEAR(last->end[C], c, 1e-5) << "line " << line;
    ++rows;
  }
  EXPECT_GT(rows, 0);
}
}  // namespace

TEST(PolarInterpolation, FaceSquareCornersByHand) { check_ends("polar_face_square"); }
TEST(PolarInterpolation, CompensatedContourCornersByHand) { check_ends("polar_face_comp"); }
TEST(CylindricalInterpolation, ArcEndsByHand) { check_ends("cyl_arc"); }

// Every point of the square's blocks lies on its programmed edge, and the machine's straight X-C
// motion between consecutive points (checked at 16 points a piece) stays within the path tolerance.
TEST(PolarInterpolation, FaceSquareStaysOnTheContour) {
  machine::RunOptions options;
  options.path_tolerance = 0.002;
  const test::Ran r = run_file("polar_face_square", options);
  ASSERT_TRUE(r.result.ok());
  // the edges by hand (X as a radius, C of the plane): the tool starts at (30, 0)
  const std::map<std::uint32_t, std::pair<Pt, Pt>> edges{
      {8, {{30, 0}, {10, -10}}}, {9, {{10, -10}, {10, 10}}},   {10, {{10, 10}, {-10, 10}}},
      {11, {{-10, 10}, {-10, -10}}}, {12, {{-10, -10}, {10, -10}}}, {13, {{10, -10}, {30, 0}}}};
  int pieces = 0;
  for (const auto& m : r.moves) {
    auto it = edges.find(m.line);
    if (!m.is_motion() || it == edges.end()) continue;
    const auto [a, b] = it->second;
    const machine::AxisVector s = m.start, e = m.end;  // X as a radius
    EXPECT_LT(seg_dist(plane_of(e), a, b), 1e-9) << "line " << m.line;
    for (int k = 1; k < 16; ++k) {
      machine::AxisVector v = s;
      const double u = k / 16.0;
      v[X] = s[X] + u * (e[X] - s[X]);
      v[C] = s[C] + u * (e[C] - s[C]);
      EXPECT_LT(seg_dist(plane_of(v), a, b), 0.002 * 1.05) << "line " << m.line;
    }
    ++pieces;
  }
  EXPECT_GT(pieces, 12);  // the edges are not single X-C moves
}

// A slot through the centre: X40 to X-40 along C0 is the linear axis going past the centre, C still.
TEST(PolarInterpolation, ThroughTheCentreTheLinearAxisChangesSide) {
  machine::MachineProfile p = machine::load_profile(
      (kPrograms / "polar_face_square.toml").string());
  const test::Ran r = test::run("G98\nG00 X40. C30.\nG12.1\nG01 X-40. F100\nG13.1\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  const auto moves = r.motions();
  ASSERT_GE(moves.size(), 2u);
  for (const auto& m : moves) {
    if (m.line != 4) continue;
    EXPECT_NEAR(m.end[C], 30, 1e-9);  // angle 0 of the plane is C30, the C at G12.1
  }
  EXPECT_NEAR(moves.back().end[X], -20, 1e-9);
}

TEST(PolarInterpolation, AlarmsOfTheMode) {
  machine::MachineProfile p = machine::load_profile(
      (kPrograms / "polar_face_square.toml").string());
  EXPECT_EQ(test::run("G98\nG00 X40. C0\nT0111\nG41 G01 X30. F100\nG12.1\nM30\n", p).alarm_code(), "PS0146");
  EXPECT_EQ(test::run("G98\nG00 X40. C0\nG12.1\nT0111\nG41 G01 X30. F100\nG13.1\nM30\n", p).alarm_code(), "PS0146");
  EXPECT_EQ(test::run("G98\nG00 X40. C0\nG12.1 X20.\nM30\n", p).alarm_code(), "PS0145");
  EXPECT_EQ(test::run("G98\nG00 X40. C0\nG12.1\nG01 X20. F100\nG50 X0 Z0\nM30\n", p).alarm_code(), "PS0146");
  EXPECT_EQ(test::run("G98\nG00 X40. C0\nG12.1\nG18\nM30\n", p).alarm_code(), "PS0146");
  EXPECT_EQ(test::run("G98\nG00 X40. C0\nG12.1\nG07.1 C20.\nM30\n", p).alarm_code(), "PS0146");
  machine::MachineProfile mill = machine::default_mill();
  EXPECT_EQ(test::run("G112\nM30\n", mill).alarm_code(), "PS0010");  // a lathe's name for G12.1
  EXPECT_EQ(test::run("G12.1\nM30\n", mill).alarm_code(), "PS0145");  // No.5460/5461 not set
}

TEST(CylindricalInterpolation, AlarmsOfTheMode) {
  machine::MachineProfile p = machine::load_profile(
      (kPrograms / "polar_face_square.toml").string());
  EXPECT_EQ(test::run("G98\nG01 X40. Z0 C0 F100\nG07.1 C20.\nG02 Z-10. C90. I5.\nM30\n", p).alarm_code(), "PS0022");
  EXPECT_EQ(test::run("G98\nG01 X40. Z0 C0 F100\nG07.1 C20.\nG28 U0\nM30\n", p).alarm_code(), "PS0176");
  EXPECT_EQ(test::run("G98\nG01 X40. Z0 C0 F100\nG07.1 C20. Z3.\nM30\n", p).alarm_code(), "PS0175");
  EXPECT_EQ(test::run("G98\nG01 X40. Z0 C0 F100\nG07.1 Z20.\nM30\n", p).alarm_code(), "PS0175");
  EXPECT_EQ(test::run("G98\nG01 X40. Z0 C0 F100\nG07.1 C20.\nG07.1 C10.\nM30\n", p).alarm_code(), "PS0176");
  // G07.1 C0 outside the mode cancels nothing and moves nothing
  const test::Ran r = test::run("G98\nG01 X40. Z0 C10. F100\nG07.1 C0\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  EXPECT_NEAR(r.motions().back().end[C], 10, 1e-12);
}

// The arc of cyl_arc on the developed surface (Z, s = 20 C pi / 180): its centre from the chord and
// R by hand, every point at R from it, the chords within the tolerance.
TEST(CylindricalInterpolation, ArcPointsOnTheDevelopedCircle) {
  const test::Ran r = run_file("cyl_arc");
  ASSERT_TRUE(r.result.ok());
  const double rc = 20, R = 20;
  const Pt a{0, rc * kPi / 2}, b{-20, rc * kPi};  // (Z, s) of C90 and C180
  const double dx = b.x - a.x, dy = b.y - a.y, d = std::hypot(dx, dy), h = std::sqrt(R * R - d * d / 4);
  const Pt centre{a.x + dx / 2 + h * dy / d, a.y + dy / 2 - h * dx / d};  // G02, R > 0: right of the chord
  int pieces = 0;
  double last_angle = 1e9;
  for (const auto& m : r.moves) {
    if (!m.is_motion() || m.line != 9) continue;
    const Pt e{m.end[Z], m.end[C] * kPi / 180 * rc};
    const Pt s{m.start[Z], m.start[C] * kPi / 180 * rc};
    EXPECT_NEAR(std::hypot(e.x - centre.x, e.y - centre.y), R, 1e-9);
    EXPECT_NEAR(m.end[X], 20, 1e-12);  // X (radius 20) unmoved
    const Pt mid{(s.x + e.x) / 2, (s.y + e.y) / 2};
    EXPECT_LE(R - std::hypot(mid.x - centre.x, mid.y - centre.y), 0.001 + 1e-9);  // the chord's sagitta
    const double angle = std::atan2(e.y - centre.y, e.x - centre.x);
    if (last_angle < 1e8) {
      EXPECT_LT(std::remainder(angle - last_angle, 2 * kPi), 0);  // clockwise
    }
    last_angle = angle;
    ++pieces;
  }
  EXPECT_GT(pieces, 10);
}

// polar_points against random lines and arcs: each point on the contour, the straight motion of
// the linear axis and the angle between points (16 checks a piece) within the tolerance.
TEST(PolarInterpolation, RandomContoursStayWithinTolerance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-50, 50);
  for (int n = 0; n < 300; ++n) {
    machine::Move m;
    m.kind = n % 2 ? machine::MoveKind::arc : machine::MoveKind::line;
    m.start = {u(rng), u(rng), 0, 0, 0, 0};
    if (m.kind == machine::MoveKind::line) {
      m.end = {u(rng), u(rng), 0, 0, 0, 0};
    } else {
      m.center = {u(rng) / 2, u(rng) / 2, 0};
      const double r0 = std::hypot(m.start[0] - m.center[0], m.start[1] - m.center[1]);
      const double a0 = std::atan2(m.start[1] - m.center[1], m.start[0] - m.center[0]);
      m.sweep = u(rng) / 50 * 2 * kPi;
      m.end = {m.center[0] + r0 * std::cos(a0 + m.sweep), m.center[1] + r0 * std::sin(a0 + m.sweep), 0, 0, 0, 0};
    }
    const double tol = n % 3 == 0 ? 0.001 : 0.01;
    const machine::PlanePath path = machine::PlanePath::of(m, 0, 1);
    int sign = 1;
    double angle = std::atan2(m.start[1], m.start[0]);
    const auto pts = machine::polar_points(path, tol, sign, angle);
    ASSERT_GE(pts.size(), 2u);
    auto dist = [&](Pt q) {  // closed form: the segment, or the circle
      if (m.kind == machine::MoveKind::line) return seg_dist(q, {m.start[0], m.start[1]}, {m.end[0], m.end[1]});
      const double r0 = std::hypot(m.start[0] - m.center[0], m.start[1] - m.center[1]);
      return std::fabs(std::hypot(q.x - m.center[0], q.y - m.center[1]) - r0);
    };
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const machine::V2 q = machine::polar_to_plane(pts[i].linear, pts[i].angle);
      EXPECT_LT(dist({q.x, q.y}), 1e-7) << n;
      if (i == 0) continue;
      for (int k = 1; k < 16; ++k) {
        const double f = k / 16.0;
        const machine::V2 v = machine::polar_to_plane(pts[i - 1].linear + f * (pts[i].linear - pts[i - 1].linear),
                                                      pts[i - 1].angle + f * (pts[i].angle - pts[i - 1].angle));
        EXPECT_LT(dist({v.x, v.y}), tol * 1.1) << n << " piece " << i;
      }
    }
    const machine::V2 end = machine::polar_to_plane(pts.back().linear, pts.back().angle);
    EXPECT_NEAR(end.x, m.end[0], 1e-9);
    EXPECT_NEAR(end.y, m.end[1], 1e-9);
  }
}
