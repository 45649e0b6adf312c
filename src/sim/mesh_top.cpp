#include "sim/mesh_top.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncurve::sim {

Box mesh_box(const Mesh& mesh) {
  if (mesh.vertices.empty()) return {};
  Box b{mesh.vertices[0], mesh.vertices[0]};
  for (const Point3& p : mesh.vertices)
    for (int a = 0; a < 3; ++a) b.min[a] = std::min(b.min[a], p[a]), b.max[a] = std::max(b.max[a], p[a]);
  return b;
}

std::vector<double> mesh_top(const Mesh& mesh, const ZMap& grid) {
  const int nx = grid.nx();
  std::vector<double> top(static_cast<std::size_t>(nx) * grid.ny(), -std::numeric_limits<double>::infinity());
  for (const auto& t : mesh.triangles) {
    if (t[0] >= mesh.vertices.size() || t[1] >= mesh.vertices.size() || t[2] >= mesh.vertices.size()) continue;
    const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    // twice the signed XY area; a vertical triangle has none
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    const double scale = std::max({std::abs(b[0] - a[0]), std::abs(c[0] - a[0]), std::abs(b[1] - a[1]),
                                   std::abs(c[1] - a[1])});
    if (!(std::abs(area) > 1e-12 * scale * scale)) continue;
    // a centre on an edge is inside (the weights' rounding allowed for)
    const double slack = -1e-12;
    int j0, j1, i0, i1;
    grid.rows_of(std::min({a[1], b[1], c[1]}), std::max({a[1], b[1], c[1]}), j0, j1);
    grid.cells_of(std::min({a[0], b[0], c[0]}), std::max({a[0], b[0], c[0]}), i0, i1);
    for (int j = j0; j < j1; ++j) {
      const double y = grid.cell_y(j);
      double* row = top.data() + static_cast<std::size_t>(j) * nx;
      for (int i = i0; i < i1; ++i) {
        const double x = grid.cell_x(i);
        // barycentric weights of a, b, c at (x, y)
        const double wa = ((b[0] - x) * (c[1] - y) - (b[1] - y) * (c[0] - x)) / area;
        const double wb = ((c[0] - x) * (a[1] - y) - (c[1] - y) * (a[0] - x)) / area;
        const double wc = 1 - wa - wb;
        if (wa < slack || wb < slack || wc < slack) continue;
        row[i] = std::max(row[i], a[2] + wb * (b[2] - a[2]) + wc * (c[2] - a[2]));  // exact on a level triangle
      }
    }
  }
  return top;
}

void start_at_mesh(ZMap& map, const Mesh& mesh) {
  const std::vector<double> top = mesh_top(mesh, map);
  for (int j = 0; j < map.ny(); ++j)
    for (int i = 0; i < map.nx(); ++i) map.start_cell(i, j, top[static_cast<std::size_t>(j) * map.nx() + i]);
}

}  // namespace ncurve::sim
