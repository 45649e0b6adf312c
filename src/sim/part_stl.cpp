#include "sim/part_stl.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace ncurve::sim {

namespace {

using V3 = std::array<double, 3>;

class StlOut {
public:
  explicit StlOut(std::ostream& out) : out_(out) {}
  // A triangle a, b, c counter-clockwise seen from outside.
  void add(const V3& a, const V3& b, const V3& c) {
    const V3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    V3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x = len > 0 ? x / len : 0;
    char rec[50];
    float f[12];
    for (int k = 0; k < 3; ++k) {
      f[k] = static_cast<float>(n[k]);
      f[3 + k] = static_cast<float>(a[k]);
      f[6 + k] = static_cast<float>(b[k]);
      f[9 + k] = static_cast<float>(c[k]);
    }
    std::memcpy(rec, f, 48);
    rec[48] = rec[49] = 0;
    buffer_.append(rec, 50);
    if (buffer_.size() >= (1u << 20)) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

private:
  std::ostream& out_;
  std::string buffer_;
};

}  // namespace

PartGrid part_grid(const ZMap& map, int most) {
  PartGrid g;
  const int step = std::max({1, (map.nx() + most - 1) / most, (map.ny() + most - 1) / most});
  g.nx = (map.nx() + step - 1) / step;
  g.ny = (map.ny() + step - 1) / step;
  g.bottom = map.stock().min[2];
  g.top = map.stock().max[2];
  g.dx = g.dy = map.cell() * step;
  // each point at the middle of its block of cells (the last block may be narrower)
  auto middle = [&](int k, int n, auto centre) { return (centre(k * step) + centre(std::min((k + 1) * step, n) - 1)) / 2; };
  g.x0 = middle(0, map.nx(), [&](int i) { return map.cell_x(i); });
  g.y0 = middle(0, map.ny(), [&](int j) { return map.cell_y(j); });
  g.heights.assign(static_cast<std::size_t>(g.nx) * g.ny, static_cast<float>(g.top));
  for (int j = 0; j < map.ny(); ++j)
    for (int i = 0; i < map.nx(); ++i) {
      float& h = g.heights[static_cast<std::size_t>(j / step) * g.nx + i / step];
      h = std::min(h, static_cast<float>(std::clamp(map.height(i, j), g.bottom, g.top)));
    }
  return g;
}

std::uint64_t part_stl_triangles(const ZMap& map) {
  const std::uint64_t nx = static_cast<std::uint64_t>(map.nx()), ny = static_cast<std::uint64_t>(map.ny());
  if (nx < 2 || ny < 2) return 12;  // a box
  const std::uint64_t boundary = 2 * (nx - 1) + 2 * (ny - 1);
  return 2 * (nx - 1) * (ny - 1) + 2 * boundary + boundary;  // top, walls, bottom fan
}

void write_part_stl(const ZMap& map, std::ostream& out) {
  const Box& s = map.stock();
  const double top = s.max[2], bottom = s.min[2];
  char header[80] = {};
  const std::string title = "ncurve part: the stock cut on a Z-map";
  std::memcpy(header, title.data(), title.size());
  out.write(header, 80);
  const std::uint64_t count = part_stl_triangles(map);
  const std::uint32_t n32 = static_cast<std::uint32_t>(std::min<std::uint64_t>(count, UINT32_MAX));
  out.write(reinterpret_cast<const char*>(&n32), 4);
  StlOut stl(out);
  const int nx = map.nx(), ny = map.ny();
  if (nx < 2 || ny < 2) {  // too few cells for a surface: the stock box at its lowest height
    double z = top;
    for (double h : map.heights()) z = std::min(z, h);
    z = std::clamp(z, bottom, top);
    const V3 c[8] = {{s.min[0], s.min[1], bottom}, {s.max[0], s.min[1], bottom}, {s.max[0], s.max[1], bottom},
                     {s.min[0], s.max[1], bottom}, {s.min[0], s.min[1], z},      {s.max[0], s.min[1], z},
                     {s.max[0], s.max[1], z},      {s.min[0], s.max[1], z}};
    const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                          {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    for (const auto& t : f) stl.add(c[t[0]], c[t[1]], c[t[2]]);
    stl.flush();
    return;
  }
  // vertex (i, j): the cell's centre, the outer ones moved onto the stock's edge
  auto x_of = [&](int i) { return i == 0 ? s.min[0] : i == nx - 1 ? s.max[0] : map.cell_x(i); };
  auto y_of = [&](int j) { return j == 0 ? s.min[1] : j == ny - 1 ? s.max[1] : map.cell_y(j); };
  auto top_at = [&](int i, int j) { return V3{x_of(i), y_of(j), std::clamp(map.height(i, j), bottom, top)}; };
  auto low_at = [&](int i, int j) { return V3{x_of(i), y_of(j), bottom}; };
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const V3 a = top_at(i, j), b = top_at(i + 1, j), c = top_at(i + 1, j + 1), d = top_at(i, j + 1);
      stl.add(a, b, c);
      stl.add(a, c, d);
    }
  // the boundary counter-clockwise seen from above: along the bottom row, up the right, back, down
  std::vector<std::array<int, 2>> ring;
  for (int i = 0; i < nx - 1; ++i) ring.push_back({i, 0});
  for (int j = 0; j < ny - 1; ++j) ring.push_back({nx - 1, j});
  for (int i = nx - 1; i > 0; --i) ring.push_back({i, ny - 1});
  for (int j = ny - 1; j > 0; --j) ring.push_back({0, j});
  const V3 centre{(s.min[0] + s.max[0]) / 2, (s.min[1] + s.max[1]) / 2, bottom};
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const auto p = ring[k], q = ring[(k + 1) % ring.size()];
    // the wall faces out of the counter-clockwise ring: p low, q low, q top, p top
    stl.add(low_at(p[0], p[1]), low_at(q[0], q[1]), top_at(q[0], q[1]));
    stl.add(low_at(p[0], p[1]), top_at(q[0], q[1]), top_at(p[0], p[1]));
    stl.add(centre, low_at(q[0], q[1]), low_at(p[0], p[1]));  // the bottom, facing down
  }
  stl.flush();
}

}  // namespace ncurve::sim
