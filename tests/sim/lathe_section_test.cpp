// The lathe's half-section against closed forms. The section is exact to kSectionResolution: a
// boundary point is within the chord error of the nose polygon plus that of an arc move's chords plus
// the grid's rounding of the boundary the round tools would cut. Where the boundary is straight and
// made by a straight edge or a nose's quadrant point (a diameter or face turned by a tip-3 tool) the
// grid is the only error. A volume is within 2 pi x (the largest radius) x (the bound) x (the length of
// the boundary that is curved) of the exact one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include "sim/lathe_section.hpp"
#include "sim/lathe_section_sink.hpp"
#include "sim/stl.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using namespace ncurve::sim;
using geom::V2;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kGrid = kSectionUnit;  // a straight boundary on the grid, or a nose's quadrant point

// A CNMG 80-degree insert in a 95-degree holder: tip 3, clearance 5.
LatheInsert turning(double r) {
  LatheInsert i;
  i.nose_radius = r;
  i.tip = 3;
  return i;
}

Cylinder bar(double diameter, double length, double face = 0, double inner = 0) {
  Cylinder c;
  c.diameter = diameter;
  c.inner_diameter = inner;
  c.length = length;
  c.face = face;
  return c;
}

// The spandrel between a square corner and a nose of radius r fitted in it: its area, and its first
// moment about the corner's side along Z.
double spandrel_area(double r) { return r * r * (1 - kPi / 4); }
double spandrel_moment(double r) { return r * r * r * (5.0 / 6 - kPi / 4); }

// The bound along X where the boundary's slope dX/dZ is m: the resolution is a distance from the
// boundary, across it.
double along_x(double m) { return kSectionResolution * std::sqrt(1 + m * m); }

bool convex_ccw(const std::vector<V2>& p) {
  for (std::size_t i = 0, n = p.size(); i < n; ++i)
    if (geom::cross(p[(i + 1) % n] - p[i], p[(i + 2) % n] - p[(i + 1) % n]) < -1e-12) return false;
  return true;
}

}  // namespace

TEST(InsertOutline, TurningInsertAboutItsImaginaryTip) {
  // tip 3, R0.8: the nose centre at (0.8, 0.8) from the programmed point; the polygon reaches Z0 and
  // X0 (its quadrant points) and nothing below or to the left
  const ToolOutline o = insert_outline(turning(0.8));
  ASSERT_FALSE(o.empty());
  EXPECT_TRUE(convex_ccw(o.points));
  double zmin = 1e9, xmin = 1e9;
  for (const V2& p : o.points) zmin = std::min(zmin, p.x), xmin = std::min(xmin, p.y);
  EXPECT_NEAR(zmin, 0, 1e-12);
  EXPECT_NEAR(xmin, 0, 1e-12);
  // the nose's points lie on the circle; from its ends the trailing edge rises 5 degrees from Z and
  // the leading edge leans back 5 degrees from X (a 95-degree holder)
  int on_nose = 0;
  for (const V2& p : o.points)
    if (std::fabs(geom::norm(p - V2{0.8, 0.8}) - 0.8) < 1e-12) ++on_nose;
  EXPECT_GE(on_nose, 10);
  bool trailing = false, leading = false;
  for (std::size_t i = 0, n = o.points.size(); i < n; ++i) {
    const V2 a = o.points[i], b = o.points[(i + 1) % n];
    const bool from_nose = std::fabs(geom::norm(a - V2{0.8, 0.8}) - 0.8) < 1e-12 ||
                           std::fabs(geom::norm(b - V2{0.8, 0.8}) - 0.8) < 1e-12;
    if (!from_nose || geom::norm(b - a) < 1) continue;
    const double deg = std::remainder(std::atan2(b.y - a.y, b.x - a.x) * 180 / kPi, 180.0);
    if (std::fabs(deg - 5) < 1e-9) trailing = true;
    if (std::fabs(deg - 85) < 1e-9) leading = true;
  }
  EXPECT_TRUE(trailing);
  EXPECT_TRUE(leading);
  // tip 8, a sharp 60-degree point: symmetric about -X
  LatheInsert thread;
  thread.tip = 8;
  thread.insert_angle = 60;
  const ToolOutline t = insert_outline(thread);
  ASSERT_EQ(t.points.size(), 4u);
  double lowest = 1e9;
  for (const V2& p : t.points) lowest = std::min(lowest, p.y);
  EXPECT_EQ(lowest, 0);
  for (const V2& p : t.points)
    if (p.y > 0 && p.y < 12) {
      EXPECT_NEAR(std::fabs(p.x) / p.y, std::tan(kPi / 6), 1e-12);
    }
}

TEST(InsertOutline, GroovingBladeFromItsReferenceCorner) {
  LatheInsert b;
  b.nose_radius = 0.2;
  b.width = 3;
  b.tip = 3;  // the -Z corner, the blade towards +Z
  ToolOutline o = insert_outline(b);
  EXPECT_TRUE(convex_ccw(o.points));
  double zmin = 1e9, zmax = -1e9, xmin = 1e9;
  for (const V2& p : o.points) zmin = std::min(zmin, p.x), zmax = std::max(zmax, p.x), xmin = std::min(xmin, p.y);
  EXPECT_NEAR(zmin, 0, 1e-12);
  EXPECT_NEAR(zmax, 3, 1e-12);
  EXPECT_NEAR(xmin, 0, 1e-12);
  b.tip = 4;  // the +Z corner, the blade towards -Z
  o = insert_outline(b);
  zmin = 1e9, zmax = -1e9;
  for (const V2& p : o.points) zmin = std::min(zmin, p.x), zmax = std::max(zmax, p.x);
  EXPECT_NEAR(zmin, -3, 1e-12);
  EXPECT_NEAR(zmax, 0, 1e-12);
}

TEST(InsertOutline, DrillOnTheSpindleAxis) {
  MillTool d;
  d.kind = MillKind::drill;
  d.diameter = 8;
  d.point_angle = 118;
  d.flute_length = 40;
  const ToolOutline o = axial_tool_outline(d);
  EXPECT_TRUE(convex_ccw(o.points));
  // the point at the programmed point, the full diameter 4 / tan(59 degrees) behind it
  bool tip = false, rim = false;
  for (const V2& p : o.points) {
    if (p.x == 0 && p.y == 0) tip = true;
    if (std::fabs(p.y - 4) < 1e-12 && std::fabs(p.x - 4 / std::tan(59 * kPi / 180)) < 1e-12) rim = true;
  }
  EXPECT_TRUE(tip);
  EXPECT_TRUE(rim);
}

TEST(LatheSection, StockAreaAndVolume) {
  LatheSection bar_section(bar(50, 100, 2));
  EXPECT_NEAR(bar_section.area(), 25 * 100, 1e-9);
  EXPECT_NEAR(bar_section.volume(), kPi * 625 * 100, 1e-6);
  EXPECT_EQ(bar_section.volume_removed(), 0);
  EXPECT_EQ(bar_section.outer_radius(0), 25);
  EXPECT_EQ(bar_section.inner_radius(0), 0);
  EXPECT_TRUE(std::isnan(bar_section.outer_radius(3)));
  LatheSection tube(bar(50, 100, 0, 20));
  EXPECT_NEAR(tube.volume(), kPi * (625 - 100) * 100, 1e-6);
  EXPECT_EQ(tube.inner_radius(-50), 10);
}

TEST(LatheSection, FacingRemovesTheRing) {
  // a tube D50 ID20 faced 1.5 deep past its bore, and a bar faced past its centre: pi (R^2 - r^2) depth
  const ToolOutline tool = insert_outline(turning(0.8));
  LatheSection tube(bar(50, 60, 0, 20));
  tube.cut_line(tool, {-1.5, 27}, {-1.5, 8});
  EXPECT_NEAR(tube.volume_removed(), kPi * (625 - 100) * 1.5, 1e-6);
  EXPECT_NEAR(tube.area_removed(), 15 * 1.5, 1e-9);
  EXPECT_TRUE(std::isnan(tube.outer_radius(-1)));
  LatheSection solid(bar(50, 60));
  solid.cut_line(tool, {-1.5, 27}, {-1.5, -1.6});
  EXPECT_NEAR(solid.volume_removed(), kPi * 625 * 1.5, 1e-6);
}

TEST(LatheSection, StraightTurningToADiameter) {
  // D50 to D40 over 30 mm with a tip-3 R0.8 insert, retracting straight out: the ring less the
  // spandrel the nose leaves in the corner at Z-30
  const double R = 25, x = 20, L = 30, r = 0.8;
  const ToolOutline tool = insert_outline(turning(r));
  LatheSection s(bar(50, 60));
  s.cut_line(tool, {2, 30}, {2, x});
  s.cut_line(tool, {2, x}, {-L, x});
  s.cut_line(tool, {-L, x}, {-L, 30});
  s.cut_line(tool, {-L, 30}, {2, 30});
  for (double z : {-0.5, -10.0, -29.0}) EXPECT_NEAR(s.outer_radius(z), x, kGrid) << z;
  // in the corner the nose's arc about (Z-29.2, X20.8)
  for (double z : {-29.9, -29.7, -29.5}) {
    const double u = z + L - r, arc = x + r - std::sqrt(r * r - u * u);
    EXPECT_NEAR(s.outer_radius(z), arc, along_x(u / std::sqrt(r * r - u * u))) << z;
  }
  EXPECT_NEAR(s.outer_radius(-30.5), R, kGrid);
  const double exact = kPi * (R * R - x * x) * L - 2 * kPi * (spandrel_area(r) * x + spandrel_moment(r));
  const double bound = 2 * kPi * (x + r) * kSectionResolution * (kPi / 2 * r);
  EXPECT_NEAR(s.volume_removed(), exact, bound);
  EXPECT_NEAR(s.area_removed(), (R - x) * L - spandrel_area(r), kSectionResolution * (kPi / 2 * r));
}

TEST(LatheSection, TaperIsTheLineOffsetByTheNose) {
  // from (Z2, X15) to (Z-20, X20) (radii): the nose centre runs 0.8 above and beside it, and the part is
  // the centre's line less r sqrt(1 + m^2) along X
  const double r = 0.8, m = -5.0 / 22;
  LatheSection s(bar(50, 60));
  const ToolOutline tool = insert_outline(turning(r));
  s.cut_line(tool, {2, 30}, {2, 15});
  s.cut_line(tool, {2, 15}, {-20, 20});
  s.cut_line(tool, {-20, 20}, {-20, 30});
  for (double z : {-2.0, -5.0, -10.0, -15.0, -18.0}) {
    const double centre = 15 + r + m * (z - (2 + r));
    EXPECT_NEAR(s.outer_radius(z), centre - r * std::sqrt(1 + m * m), along_x(m)) << z;
  }
}

TEST(LatheSection, ConvexArcIsTheCircleOffsetByTheNose) {
  // the imaginary tip round a quarter circle of radius 8 about (Z-10, X10), from its top to its +Z
  // side (G02 seen with X up): the nose centre runs on the same circle moved by (0.8, 0.8), and the
  // part is that circle less the nose radius
  const double r = 0.8, rho = 8;
  const V2 c{-10, 10};
  LatheSection s(bar(40, 60));
  const ToolOutline tool = insert_outline(turning(r));
  s.cut_line(tool, {-10, 25}, {-10, 18});
  s.cut_arc(tool, {-10, 18}, {-2, 10}, c, -kPi / 2);
  s.cut_line(tool, {-2, 10}, {5, 10});
  for (double z = -9.1; z <= -2.1; z += 0.25) {
    const double dz = z - (c.x + r), h = std::sqrt((rho - r) * (rho - r) - dz * dz);
    EXPECT_NEAR(s.outer_radius(z), c.y + r + h, along_x(dz / h)) << z;
  }
  EXPECT_NEAR(s.outer_radius(-0.5), 10, kGrid);
  // the same arc as a Move of the ZX plane
  LatheSection t(bar(40, 60));
  machine::Move mv;
  mv.kind = machine::MoveKind::arc;
  mv.plane = 18;
  mv.clockwise = true;
  mv.start = {18, 0, -10, 0, 0, 0};
  mv.end = {10, 0, -2, 0, 0, 0};
  mv.center = {10, 0, -10};
  mv.sweep = -kPi / 2;
  t.cut_line(tool, {-10, 25}, {-10, 18});
  EXPECT_TRUE(t.cut(tool, mv));
  t.cut_line(tool, {-2, 10}, {5, 10});
  EXPECT_NEAR(t.area(), s.area(), 1e-12);
  mv.plane = 17;
  EXPECT_FALSE(t.cut(tool, mv));
}

TEST(LatheSection, BatchingDoesNotChangeTheCut) {
  const ToolOutline tool = insert_outline(turning(0.4));
  LatheSection one(bar(50, 60), 1), many(bar(50, 60));
  for (LatheSection* s : {&one, &many}) {
    for (int pass = 0; pass < 20; ++pass) {
      const double x = 24.5 - 0.5 * pass, z = -40.0 + pass;
      s->cut_line(tool, {2, x + 1}, {2, x});
      s->cut_line(tool, {2, x}, {z, x});
      s->cut_line(tool, {z, x}, {z, x + 1});
    }
    s->cut_arc(tool, {-10, 15}, {-20, 15}, {-15, 15}, -kPi);
  }
  // each batch rounds the points where its cuts cross the boundary to the grid: within half a unit
  // across a boundary some 200 mm long
  const double bound = kSectionUnit / 2 * 200;
  EXPECT_NEAR(one.area(), many.area(), bound);
  EXPECT_NEAR(one.volume(), many.volume(), 2 * kPi * 25 * bound);
}

// examples/lathe-mrc.nc on its setup: G71 roughs and G70 finishes the profile under G42 (nose radius
// 0.4, tip 3), G75 grooves it with a 3 mm blade, G74 drills the centre with an 8 mm drill. The
// finished part is the programmed profile wherever the nose can touch it: everywhere but the
// concave corners at Z-35 and Z-60 (a fillet of the nose radius) and the groove.
TEST(LatheSectionSink, G71G70PartIsItsProfile) {
  std::ifstream in(NCURVE_SOURCE_DIR "/examples/lathe-mrc.nc");
  std::stringstream text;
  text << in.rdbuf();
  const auto profile = machine::load_profile(NCURVE_SOURCE_DIR "/profiles/fanuc-lathe.toml");
  auto r = test::run(text.str(), profile);
  ASSERT_TRUE(r.result.ok());
  const SetupFile setup = read_setup(NCURVE_SOURCE_DIR "/examples/lathe-mrc.setup.toml");
  LatheSection section(std::get<Cylinder>(*setup.stock));
  LatheSectionSink sink(section, setup.tools, profile.lathe_offsets);
  for (const auto& m : r.moves) sink.on_move(m);
  EXPECT_EQ(sink.counts().no_tool, 0u);
  EXPECT_EQ(sink.counts().not_zx_arc, 0u);
  EXPECT_GT(sink.counts().cut, 50u);
  // the profile (radii): Z0 X8, chamfer to Z-2 X10, Z-15, concave R5 about (Z-15, X15) to Z-20 X15,
  // Z-35, taper to Z-45 X20, Z-60, up to X26 (above the stock's 25)
  // (its radius and slope dX/dZ at z)
  auto profile_x = [](double z) -> std::pair<double, double> {
    if (z > -2) return {8 - z, -1};
    if (z > -15) return {10, 0};
    if (z > -20) {
      const double u = z + 15, h = std::sqrt(25 - u * u);
      return {15 - h, u / h};
    }
    if (z > -35) return {15, 0};
    if (z > -45) return {15 + (-35 - z) / 2, -0.5};
    if (z > -60) return {20, 0};
    return {25, 0};
  };
  for (double z : {-0.5, -1.0, -1.9, -2.5, -5.0, -10.0, -11.5, -16.5, -17.0, -18.0, -19.0, -19.9, -21.0, -25.0,
                   -30.0, -34.0, -36.0, -38.0, -40.0, -43.0, -44.9, -46.0, -50.0, -55.0, -59.0, -61.0, -80.0}) {
    const auto [x, m] = profile_x(z);
    EXPECT_NEAR(section.outer_radius(z), x, along_x(m)) << "Z" << z;
  }
  // the groove: Z-16 to Z-12 (the blade's -Z corner at Z-15 and at Z-16, the blade 3 wide) to X8
  for (double z : {-15.5, -14.0, -12.5}) EXPECT_NEAR(section.outer_radius(z), 8, kSectionResolution) << "Z" << z;
  // the concave corners keep the nose's radius: at Z-60 the part meets the shoulder 0.4 higher
  EXPECT_NEAR(section.outer_radius(-59.8), 20 + 0.4 - std::sqrt(0.16 - 0.04), along_x(0.2 / std::sqrt(0.12)));
  // the 8 mm drill to Z-20: the bore's radius 4, its 118-degree point from Z-20
  EXPECT_NEAR(section.inner_radius(-10), 4, kGrid);
  EXPECT_NEAR(section.inner_radius(-19), std::tan(59 * kPi / 180), along_x(std::tan(59 * kPi / 180)));
  EXPECT_EQ(section.inner_radius(-25), 0);
  const auto by_tool = sink.volume_by_tool();
  ASSERT_EQ(by_tool.size(), 3u);
  double sum = 0;
  for (const auto& [t, v] : by_tool) sum += v;
  EXPECT_NEAR(sum, section.volume_removed(), 1e-6 * sum);
  // the drill's share: a cylinder of radius 4 to its rim and the cone of its point
  const double rim = 4 / std::tan(59 * kPi / 180);
  EXPECT_NEAR(by_tool.at(3), kPi * 16 * (20 - rim) + kPi * 16 * rim / 3, 2 * kPi * 4 * kSectionResolution * 25);
}

// G76 on a 20 mm bar: each pass's depth from the crest (radius 10) is dd sqrt(n), at least dmin more
// than the last, the roughing clamped at k - d, then the finishing pass at k, worked by hand:
// dd 0.35, dmin 0.05, d 0.05, k 0.92, m 1 give 0.35, 0.494975, 0.606218, 0.7, 0.782624, 0.857321,
// 0.87, 0.92. The section holds the thread as a groove of revolution at the tool's point: after each
// pass the part's radius is 10 less that depth, and the root (the minor diameter) is the programmed
// X18.16 = 20 - 2 x 0.92.
TEST(LatheSectionSink, G76ThreadRootDiameter) {
  auto profile = machine::default_lathe();
  auto r = test::run("G21 G99 G18 M03 S500\nT0101\nG00 X24. Z5.\nG76 P010060 Q50 R0.05\n"
                     "G76 X18.16 Z-24. P920 Q350 F1.5\nG00 X50. Z50.\nM30\n",
                     profile);
  ASSERT_TRUE(r.result.ok());
  ToolLibrary lib;
  LatheInsert thread;
  thread.tip = 8;
  thread.insert_angle = 60;
  lib.tools[1] = thread;
  LatheSection section(bar(20, 40));
  LatheSectionSink sink(section, lib);
  std::vector<double> radii;
  for (const auto& m : r.moves) {
    sink.on_move(m);
    if (m.threading) radii.push_back(section.outer_radius(-12));
  }
  const std::vector<double> depth{0.35, 0.35 * std::sqrt(2.0), 0.35 * std::sqrt(3.0), 0.7, 0.35 * std::sqrt(5.0),
                                  0.35 * std::sqrt(6.0), 0.87, 0.92};
  ASSERT_EQ(radii.size(), depth.size());
  for (std::size_t i = 0; i < depth.size(); ++i) EXPECT_NEAR(radii[i], 10 - depth[i], kGrid) << "pass " << i + 1;
  EXPECT_NEAR(2 * section.outer_radius(-12), 18.16, 2 * kGrid);
  EXPECT_NEAR(2 * section.outer_radius(-23), 18.16, 2 * kGrid);
}

TEST(LatheSectionSink, DefaultInsertFromTheOffsets) {
  // no library: T0101 is offset 1's nose (R0.8, tip 3); moves before the first T code cut nothing
  auto profile = machine::default_lathe();
  profile.lathe_offsets[1].r = 0.8;
  profile.lathe_offsets[1].tip = 3;
  auto r = test::run("G21 G99\nG00 X60. Z2.\nT0101\nG00 X40. Z2.\nG01 Z-30. F0.2\nX60.\nG00 Z2.\nT0000\nG00 X0\nM30\n",
                     profile);
  ASSERT_TRUE(r.result.ok());
  LatheSection section(bar(50, 60));
  LatheSectionSink sink(section, {}, profile.lathe_offsets);
  for (const auto& m : r.moves) sink.on_move(m);
  EXPECT_EQ(sink.counts().no_tool, 2u);
  EXPECT_EQ(sink.counts().cut, 4u);
  EXPECT_NEAR(section.outer_radius(-15), 20, kGrid);
  EXPECT_NEAR(section.outer_radius(-29.5), 20.8 - std::sqrt(0.64 - 0.09), along_x(0.3 / std::sqrt(0.55)));
}

TEST(LatheSection, MeshIsClosedAndHoldsThePart) {
  LatheSection s(bar(50, 60, 0, 0));
  const ToolOutline tool = insert_outline(turning(0.8));
  s.cut_line(tool, {2, 20}, {-30, 20});
  s.cut_line(tool, {-30, 20}, {-30, 30});
  s.cut_arc(tool, {-32, 30}, {-48, 30}, {-40, 30}, -kPi);  // a groove of radius 8 below X30
  for (int n : {3, 16, 128}) {
    const Mesh m = s.mesh(n);
    EXPECT_TRUE(is_closed(m)) << n;
    const double polygon = n * std::sin(2 * kPi / n) / (2 * kPi);
    EXPECT_NEAR(enclosed_volume(m), s.volume() * polygon, 1e-9 * s.volume()) << n;
  }
  LatheSection tube(bar(50, 60, 0, 20));
  const Mesh t = tube.mesh(64);
  EXPECT_TRUE(is_closed(t));
  EXPECT_EQ(t.triangles.size(), 4u * 64 * 2);
  EXPECT_NEAR(enclosed_volume(t), tube.volume() * 64 * std::sin(2 * kPi / 64) / (2 * kPi), 1e-9 * tube.volume());
}

TEST(Stl, BinaryLayout) {
  LatheSection s(bar(50, 60));
  const Mesh m = s.mesh(32);
  ASSERT_TRUE(is_closed(m));
  std::ostringstream out;
  write_stl(out, m, "lathe part");
  const std::string b = out.str();
  ASSERT_EQ(b.size(), kStlHeaderBytes + 4 + kStlTriangleBytes * m.triangles.size());
  EXPECT_EQ(b.substr(0, 5) == "solid", false);
  EXPECT_EQ(b.substr(0, 29), "ncurve binary STL: lathe part");
  std::uint32_t count = 0;
  for (int i = 0; i < 4; ++i) count |= static_cast<std::uint32_t>(static_cast<unsigned char>(b[80 + i])) << (8 * i);
  EXPECT_EQ(count, m.triangles.size());
  // the first triangle: its normal of unit length, its vertices as float32
  float f[12];
  std::memcpy(f, b.data() + 84, sizeof f);
  EXPECT_NEAR(std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]), 1, 1e-6);
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(f[3 + 3 * v + k], static_cast<float>(m.vertices[m.triangles[0][v]][k]));
  EXPECT_EQ(b[84 + 48], 0);
  EXPECT_EQ(b[84 + 49], 0);
  // to a file, written whole
  const auto path = std::filesystem::temp_directory_path() / "ncurve_lathe_section_test.stl";
  write_stl(path.string(), m, "");
  EXPECT_EQ(std::filesystem::file_size(path), b.size());
  std::filesystem::remove(path);
  // an empty mesh is a header and a zero count; a bad one is refused
  std::ostringstream empty;
  write_stl(empty, Mesh{});
  EXPECT_EQ(empty.str().size(), 84u);
  Mesh bad;
  bad.vertices = {{0, 0, 0}};
  bad.triangles = {{0, 0, 1}};
  std::ostringstream refused;
  EXPECT_THROW(write_stl(refused, bad), std::invalid_argument);
  bad.vertices = {{kNaN, 0, 0}, {0, 0, 0}};
  EXPECT_THROW(write_stl(refused, bad), std::invalid_argument);
}

TEST(LatheSection, BadInputsNeverCrash) {
  const ToolOutline tool = insert_outline(turning(0.8));
  const double inf = std::numeric_limits<double>::infinity();
  for (const Cylinder& c : {bar(0, 10), bar(50, 0), bar(50, -10), bar(kNaN, 10), bar(50, inf), bar(20, 10, 0, 30),
                            bar(1e300, 1e300, -1e300), bar(50, 10, kNaN)}) {
    LatheSection s(c);
    s.cut_line(tool, {2, 30}, {-5, 0});
    s.cut_line(tool, {kNaN, 0}, {1, 1});
    s.cut_arc(tool, {1, 1}, {2, 2}, {kNaN, 0}, 1);
    EXPECT_GE(s.area(), 0);
    EXPECT_TRUE(std::isfinite(s.volume()));
    EXPECT_TRUE(is_closed(s.mesh(8)));
  }
  LatheSection s(bar(50, 60));
  machine::Move m;
  m.kind = machine::MoveKind::line;
  m.start = {kNaN, 0, 0, 0, 0, 0};
  EXPECT_FALSE(s.cut(tool, m));
  m.start = {1e300, 0, -1e300, 0, 0, 0};
  m.end = {-1e300, 0, 1e300, 0, 0, 0};
  EXPECT_TRUE(s.cut(tool, m));  // a line across the section
  EXPECT_GE(s.area(), 0);
  EXPECT_LE(s.area(), 25 * 60);
  LatheSection arc(bar(50, 60));
  arc.cut_arc(tool, {0, 1e6}, {0, -1e6}, {0, 0}, 1e9);
  arc.cut_arc(tool, {0, 30}, {0, 30}, {0, 30}, 0);
  arc.cut_arc(tool, {-5, 30}, {5, 30}, {0, 30}, kNaN);
  EXPECT_GE(arc.area(), 0);
  // tools of bad numbers give safe outlines or none
  LatheInsert bad;
  bad.nose_radius = kNaN;
  bad.insert_angle = inf;
  bad.clearance_angle = -1e300;
  bad.tip = 42;
  bad.width = -3;
  EXPECT_FALSE(insert_outline(bad).empty());
  bad.nose_radius = 1e300;
  bad.width = 1e300;
  EXPECT_FALSE(insert_outline(bad).empty());
  MillTool drill;
  drill.diameter = kNaN;
  EXPECT_TRUE(axial_tool_outline(drill).empty());
  LatheSection cut(bar(50, 60));
  cut.cut_line(ToolOutline{}, {0, 0}, {-10, 0});
  EXPECT_EQ(cut.volume_removed(), 0);
  LatheSectionSink sink(cut, {}, {}, 0);
  m.start = {1, 0, 1, 0, 0, 0};
  m.end = {2, 0, 2, 0, 0, 0};
  sink.on_move(m);
  EXPECT_EQ(sink.counts().no_tool, 1u);
}

// NC2080 on a lathe: a rapid into a D50 bar is found at its block with the section area it took; a
// rapid outside the bar and one back along a diameter just turned are clean.
TEST(LatheSectionSink, RapidIntoTheBarIsFound) {
  auto profile = machine::default_lathe();
  auto r = test::run("G21 G99 G18 M03 S500\nT0101\nG00 X60. Z2.\nG00 X52. Z2.\nG00 X40. Z-10.\nG00 X60. Z2.\n"
                     "G00 X44. Z2.\nG01 Z-30. F0.2\nG00 Z2.\nG00 X100. Z50.\nM30\n",
                     profile);
  ASSERT_TRUE(r.result.ok());
  ToolLibrary lib;
  LatheInsert turn;
  turn.nose_radius = 0.4;
  turn.tip = 3;
  lib.tools[1] = turn;
  LatheSection section(bar(50, 100));
  LatheSectionSink sink(section, lib);
  for (const auto& m : r.moves) sink.on_move(m);
  ASSERT_EQ(sink.findings().size(), 1u);
  const Finding& f = sink.findings()[0];
  EXPECT_EQ(f.diagnostic.code, "NC2080");
  EXPECT_EQ(f.diagnostic.span.line, 5u);  // G00 X40. Z-10.: from radius 30 at Z2 into the bar of radius 25
  // the tip's straight path enters the bar at radius 25 at Z-4 (30 - 5/6 x 6) and ends at Z-10 radius
  // 20: the triangle under it, 6 x 5 / 2 = 15 mm^2, is cut (less the nose's rounding, 0.4^2 (1 - pi/4));
  // a tip-3 insert lies at Z and radius at or above its tip's, so no more than the bar's corner
  // Z -10..0, radius 20..25 (50 mm^2) is
  EXPECT_GT(f.amount, 15 - 0.04);
  EXPECT_LE(f.amount, 50 + 1e-3);
}
