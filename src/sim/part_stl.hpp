// The cut part of a Z-map as a closed binary STL: its top surface through the cells' centres
// (heights held between the stock's bottom and top; the outer row of vertices on the stock's edge),
// four walls down to the bottom and the bottom face, all triangles sharing their edges.
#pragma once
#include <cstdint>
#include <ostream>

#include "sim/zmap.hpp"

namespace ncurve::sim {

// How many triangles write_part_stl writes for the map.
std::uint64_t part_stl_triangles(const ZMap& map);
// Writes the binary STL (little-endian, 80-byte header, facets facing outwards).
void write_part_stl(const ZMap& map, std::ostream& out);

}  // namespace ncurve::sim
