// STL files read (src/sim/stl_read*) and a mesh's top on a grid (src/sim/mesh_top*): binary and
// ASCII read back to the vertices written, every malformed file refused with its name and what is
// wrong, and a pyramid's heights against its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>

#include "sim/mesh_top.hpp"
#include "sim/stl_read.hpp"
#include "support/meshes.hpp"

using namespace ncurve;

namespace {

std::string binary(const sim::Mesh& m) {
  std::ostringstream out;
  sim::write_stl(out, m, "test");
  return out.str();
}

// The error parse_stl gives, or "" when it reads the bytes.
std::string error_of(const std::string& bytes) {
  try {
    (void)sim::parse_stl(bytes, "x.stl");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

const char* const kAsciiTetra = R"(solid tetra
  facet normal 0 0 -1
    outer loop
      vertex 0 0 0
      vertex 0 10 0
      vertex 10 0 0
    endloop
  endfacet
  facet normal 0 -1 0
    outer loop
      vertex 0 0 0
      vertex 10 0 0
      vertex 0 0 10
    endloop
  endfacet
  facet normal -1 0 0
    outer loop
      vertex 0 0 0
      vertex 0 0 10
      vertex 0 10 0
    endloop
  endfacet
  facet normal 0.577 0.577 0.577
    outer loop
      vertex 10 0 0
      vertex 0 10 0
      vertex 0 0 1e1
    endloop
  endfacet
endsolid tetra
)";

}  // namespace

TEST(StlRead, BinaryRoundTrip) {
  // a box whose coordinates are exact in float32: read back vertex for vertex
  const sim::Mesh box = test::box_mesh(-20, 20.5, -7.25, 3, -10, 0.125);
  const sim::Mesh back = sim::parse_stl(binary(box), "box.stl");
  ASSERT_EQ(back.triangles.size(), box.triangles.size());
  for (std::size_t t = 0; t < box.triangles.size(); ++t)
    for (int v = 0; v < 3; ++v)
      EXPECT_EQ(back.vertices[back.triangles[t][v]], box.vertices[box.triangles[t][v]]) << t << " " << v;
  EXPECT_DOUBLE_EQ(sim::enclosed_volume(back), 40.5 * 10.25 * 10.125);
  // the header starts "ncurve binary STL", and a header that starts "solid" is still binary by its size
  std::string solid = binary(box);
  std::memcpy(solid.data(), "solid box", 9);
  EXPECT_EQ(sim::parse_stl(solid, "box.stl").triangles.size(), 12u);
  // from a file, in inches
  const sim::Mesh inch = sim::read_stl(test::stl_file("inch.stl", test::box_mesh(0, 1, 0, 2, 0, 0.5)), 25.4);
  const sim::Box b = sim::mesh_box(inch);
  EXPECT_DOUBLE_EQ(b.max[0], 25.4);
  EXPECT_DOUBLE_EQ(b.max[1], 50.8);
  EXPECT_DOUBLE_EQ(b.max[2], 12.7);
}

TEST(StlRead, AsciiWrittenByHand) {
  const sim::Mesh m = sim::parse_stl(kAsciiTetra, "tetra.stl");
  ASSERT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.vertices[m.triangles[3][2]], (sim::Point3{0, 0, 10}));  // 1e1
  std::string plus = kAsciiTetra;  // a sign before a number, as some writers put it
  plus.replace(plus.find("vertex 10 0 0"), 13, "vertex +1.0e+001 -0 +0");
  EXPECT_EQ(sim::parse_stl(plus, "plus.stl").vertices[2], (sim::Point3{10, 0, 0}));
  EXPECT_DOUBLE_EQ(sim::enclosed_volume(m), 1000.0 / 6);  // the corner tetrahedron, 10^3 / 6
  // two solids in one file, names after solid and endsolid, CRLF line ends
  std::string two = std::string(kAsciiTetra) + kAsciiTetra;
  for (std::size_t at = 0; (at = two.find('\n', at)) != std::string::npos; at += 2) two.insert(at, "\r");
  EXPECT_EQ(sim::parse_stl(two, "two.stl").triangles.size(), 8u);
}

TEST(StlRead, MalformedFilesAreRefusedSayingWhy) {
  const std::string box = binary(test::box_mesh(0, 1, 0, 1, 0, 1));
  EXPECT_NE(error_of(box.substr(0, box.size() - 10)).find("x.stl: error: the header counts 12 triangles, 684 bytes, "
                                                          "but the file has 674: truncated"),
            std::string::npos);
  EXPECT_NE(error_of(box + "xx").find("not a binary STL of that count"), std::string::npos);
  EXPECT_NE(error_of("abc").find("3 bytes: too short for a binary STL"), std::string::npos);
  // a count of 2^32 - 1 in a short file: refused by the size, nothing allocated
  std::string huge = box;
  std::memset(huge.data() + 80, 0xFF, 4);
  EXPECT_NE(error_of(huge).find("4294967295 triangles"), std::string::npos);
  std::string nan = box;
  const float q = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(nan.data() + 84 + 50 + 12 + 4, &q, 4);  // the second triangle's first vertex's y
  EXPECT_NE(error_of(nan).find("triangle 2 (byte 134): vertex 1 has y = nan, not a finite number"), std::string::npos);
  // ASCII: the line and column of the word
  std::string text = kAsciiTetra;
  text.replace(text.find("vertex 0 10 0"), 13, "vertex 0 nan 0");
  EXPECT_NE(error_of(text).find("x.stl:5:16: error: the vertex's y is nan, not a finite number"), std::string::npos)
      << error_of(text);
  text = kAsciiTetra;
  text.replace(text.find("vertex 10 0 0"), 6, "vertx");
  EXPECT_NE(error_of(text).find("x.stl:6:7: error: 'vertx' where 'vertex' was expected"), std::string::npos)
      << error_of(text);
  text = kAsciiTetra;
  EXPECT_NE(error_of(text.substr(0, text.find("endfacet"))).find("the file ends where 'endfacet' was expected"),
            std::string::npos);
  EXPECT_NE(error_of("solid a\n  facet normal 0 0 1\n outer loop\n vertex 1 2 1e999\n").find("x.stl:4:13: error: the "
                                                                                            "vertex's z '1e999' is out of range"),
            std::string::npos);
  EXPECT_NE(error_of("solid empty\nendsolid empty\n").find("no triangle: not a solid"), std::string::npos);
  // flat: every vertex at Z0
  sim::Mesh flat;
  test::add_quad(flat, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  EXPECT_NE(error_of(binary(flat)).find("every vertex of the STL has Z = 0: a flat surface, not a solid"),
            std::string::npos);
  try {
    (void)sim::read_stl(::testing::TempDir() + "no-such.stl");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no-such.stl: error: cannot read the STL file"), std::string::npos);
  }
}

TEST(MeshTop, PyramidHeightsAtTheCellCentres) {
  // apex (0, 0, 10) over the square |x|, |y| <= 10 at Z0: its top is 10 - max(|x|, |y|)
  sim::Mesh m;
  const sim::Point3 apex{0, 0, 10}, c[4] = {{-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}};
  for (int k = 0; k < 4; ++k) {
    const auto n = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {c[k], c[(k + 1) % 4], apex});
    m.triangles.push_back({n, n + 1, n + 2});
  }
  test::add_quad(m, c[0], c[3], c[2], c[1]);
  const sim::ZMap grid(sim::Box{{-12, -12, 0}, {12, 12, 10}}, 0.75);  // 32 x 32, beyond the base by 2
  const std::vector<double> top = sim::mesh_top(m, grid);
  int covered = 0;
  for (int j = 0; j < grid.ny(); ++j)
    for (int i = 0; i < grid.nx(); ++i) {
      const double x = grid.cell_x(i), y = grid.cell_y(j), t = top[j * grid.nx() + i];
      if (std::max(std::abs(x), std::abs(y)) <= 10) {
        ++covered;
        EXPECT_NEAR(t, 10 - std::max(std::abs(x), std::abs(y)), 1e-12) << x << " " << y;
      } else {
        EXPECT_EQ(t, -std::numeric_limits<double>::infinity()) << x << " " << y;
      }
    }
  EXPECT_EQ(covered, 26 * 26);  // centres +-0.375 .. +-9.375
}

TEST(MeshTop, RandomTrianglesAgainstAVerticalRayEachOne) {
  // an independent reference: each cell centre's vertical ray against every triangle by
  // Moller-Trumbore (the ray from below, z along it), the highest hit
  std::mt19937 random(36);
  std::uniform_real_distribution<double> xy(-10, 10), z(-5, 5);
  sim::Mesh m;
  for (int t = 0; t < 40; ++t) {
    const auto n = static_cast<std::uint32_t>(m.vertices.size());
    for (int v = 0; v < 3; ++v) m.vertices.push_back({xy(random), xy(random), z(random)});
    m.triangles.push_back({n, n + 1, n + 2});
  }
  const sim::ZMap grid(sim::Box{{-10, -10, -5}, {10, 10, 5}}, 0.37);
  const std::vector<double> top = sim::mesh_top(m, grid);
  int covered = 0;
  for (int j = 0; j < grid.ny(); ++j)
    for (int i = 0; i < grid.nx(); ++i) {
      const double ox = grid.cell_x(i), oy = grid.cell_y(j), oz = -100;  // the ray (ox, oy, oz) + s (0, 0, 1)
      double best = -std::numeric_limits<double>::infinity();
      for (const auto& t : m.triangles) {
        const sim::Point3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
        const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double p[3] = {-e2[1], e2[0], 0};  // (0, 0, 1) x e2
        const double det = e1[0] * p[0] + e1[1] * p[1];
        if (std::abs(det) < 1e-12) continue;
        const double s[3] = {ox - a[0], oy - a[1], oz - a[2]};
        const double u = (s[0] * p[0] + s[1] * p[1]) / det;
        const double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
        const double v = q[2] / det;
        if (u < 0 || v < 0 || u + v > 1) continue;
        best = std::max(best, oz + (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det);
      }
      const double got = top[static_cast<std::size_t>(j) * grid.nx() + i];
      if (std::isinf(best)) {
        EXPECT_TRUE(std::isinf(got)) << i << " " << j;
      } else {
        ++covered;
        EXPECT_NEAR(got, best, 1e-9) << i << " " << j;
      }
    }
  EXPECT_GT(covered, 1000);  // of 55 x 55
}
