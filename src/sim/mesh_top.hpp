// A mesh as a height field on a Z-map's grid: for each cell the highest point of the mesh on the
// vertical line through the cell's centre. An STL stock or fixture starts a map at it; a design
// solid is compared with the cut part on it (docs/verify.md).
#pragma once
#include <vector>

#include "sim/stl.hpp"
#include "sim/zmap.hpp"

namespace ncurve::sim {

// The mesh's bounding box; a mesh without a vertex gives an empty box.
Box mesh_box(const Mesh& mesh);

// For each cell of the grid (row by row, as ZMap::heights), the highest point of the mesh above
// its centre: each triangle's XY box rasterised onto the cells, its height at a centre inside it
// (edges included) by barycentric interpolation; -infinity where no triangle covers the centre.
// Triangles standing vertical cover no centre (their edges are the neighbours').
std::vector<double> mesh_top(const Mesh& mesh, const ZMap& grid);

// Starts each cell of a fresh map at the mesh's top there, a cell the mesh does not cover with no
// material (ZMap::start_cell): the map of an STL stock or fixture on its bounding box.
void start_at_mesh(ZMap& map, const Mesh& mesh);

}  // namespace ncurve::sim
