// The cut part of a Z-map as a closed binary STL: its top surface through the cells' centres
// (heights held between the stock's bottom and top; the outer row of vertices on the stock's edge),
// four walls down to the bottom and the bottom face, all triangles sharing their edges.
#pragma once
#include <cstdint>
#include <ostream>
#include <vector>

#include "sim/zmap.hpp"

namespace ncurve::sim {

// The part's top surface on a grid of at most `most` points a side for drawing: each point the
// lowest height of the cells it stands for (a narrow groove stays visible), held between the
// stock's bottom and top; point (i, j) at (x0 + i dx, y0 + j dy).
struct PartGrid {
  int nx = 0, ny = 0;
  double x0 = 0, y0 = 0, dx = 0, dy = 0;
  double bottom = 0, top = 0;
  std::vector<float> heights;  // row by row, nx a row
};
PartGrid part_grid(const ZMap& map, int most = 400);

// How many triangles write_part_stl writes for the map.
std::uint64_t part_stl_triangles(const ZMap& map);
// Writes the binary STL (little-endian, 80-byte header, facets facing outwards).
void write_part_stl(const ZMap& map, std::ostream& out);

}  // namespace ncurve::sim
