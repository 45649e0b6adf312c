// The cut part as a binary STL (src/sim/part_stl*): closed (every edge shared by two facets, in
// opposite directions), facing outwards, and enclosing the volume the heights say.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <map>
#include <sstream>
#include <vector>

#include "sim/part_stl.hpp"

using namespace ncurve::sim;

namespace {

using P = std::array<float, 3>;
struct Mesh {
  std::uint32_t count = 0;
  std::vector<std::array<P, 3>> facets;
  std::vector<P> normals;
};

Mesh read(const std::string& bytes) {
  Mesh m;
  EXPECT_GE(bytes.size(), 84u);
  std::memcpy(&m.count, bytes.data() + 80, 4);
  EXPECT_EQ(bytes.size(), 84u + 50u * m.count);
  for (std::uint32_t k = 0; k < m.count; ++k) {
    float f[12];
    std::memcpy(f, bytes.data() + 84 + 50 * k, 48);
    m.normals.push_back({f[0], f[1], f[2]});
    m.facets.push_back({P{f[3], f[4], f[5]}, P{f[6], f[7], f[8]}, P{f[9], f[10], f[11]}});
  }
  return m;
}

// Each directed edge once, and its reverse once: a closed, consistently oriented surface.
void expect_closed(const Mesh& m) {
  std::map<std::pair<P, P>, int> edges;
  for (const auto& t : m.facets)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : edges) {
    EXPECT_EQ(n, 1);
    const auto back = edges.find({e.second, e.first});
    EXPECT_TRUE(back != edges.end() && back->second == 1);
  }
}

// The enclosed volume by the divergence theorem (positive when the facets face outwards).
double volume(const Mesh& m) {
  double v = 0;
  for (const auto& t : m.facets) {
    const double ax = t[0][0], ay = t[0][1], az = t[0][2], bx = t[1][0], by = t[1][1], bz = t[1][2];
    const double cx = t[2][0], cy = t[2][1], cz = t[2][2];
    v += (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6;
  }
  return v;
}

std::string stl_of(const ZMap& map) {
  std::ostringstream out;
  write_part_stl(map, out);
  return out.str();
}

}  // namespace

TEST(PartStl, UncutStockIsItsBox) {
  ZMap map(Box{{-10, -5, -4}, {10, 5, 0}}, 1.0);
  const Mesh m = read(stl_of(map));
  EXPECT_EQ(m.count, part_stl_triangles(map));
  expect_closed(m);
  EXPECT_NEAR(volume(m), 20 * 10 * 4, 1e-3);
}

TEST(PartStl, CutPartIsClosedAndHoldsWhatIsLeft) {
  // a 2 mm deep step over the half x > 0 of a 20 x 10 x 4 block on 0.5 mm cells
  ZMap map(Box{{-10, -5, -4}, {10, 5, 0}}, 0.5);
  for (int j = 0; j < map.ny(); ++j)
    for (int i = 0; i < map.nx(); ++i)
      if (map.cell_x(i) > 0) map.row(j)[i] = -2;
  const Mesh m = read(stl_of(map));
  expect_closed(m);
  // the surface through the cells' centres: the step rises over the one strip of cells between
  // the centres at x = -0.25 and x = 0.25 (its middle at x = 0), so the volume is the step's exactly
  EXPECT_NEAR(volume(m), 20 * 10 * 4 - 10 * 10 * 2, 1e-3);
  // a cell below the bottom (cut through) is held at the bottom: still closed
  map.row(3)[5] = -9;
  const Mesh through = read(stl_of(map));
  expect_closed(through);
}

TEST(PartStl, OneRowOfCellsIsABox) {
  ZMap map(Box{{0, 0, -1}, {10, 0.5, 0}}, 1.0);  // 10 x 1 cells
  ASSERT_EQ(map.ny(), 1);
  const Mesh m = read(stl_of(map));
  EXPECT_EQ(m.count, 12u);
  expect_closed(m);
}
