#include "sim/stl.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "io/output_file.hpp"

namespace ncurve::sim {

namespace {

void put_u32(std::string& s, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

void put_f32(std::string& s, double v) {
  static_assert(std::numeric_limits<float>::is_iec559);
  put_u32(s, std::bit_cast<std::uint32_t>(static_cast<float>(v)));
}

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

bool is_closed(const Mesh& mesh) {
  // each directed edge once; its reverse present
  std::unordered_map<std::uint64_t, int> edges;
  edges.reserve(mesh.triangles.size() * 3);
  auto key = [](std::uint32_t a, std::uint32_t b) { return (static_cast<std::uint64_t>(a) << 32) | b; };
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (++edges[key(t[k], t[(k + 1) % 3])] > 1) return false;
  for (const auto& [e, n] : edges)
    if (!edges.contains(key(static_cast<std::uint32_t>(e), static_cast<std::uint32_t>(e >> 32)))) return false;
  return true;
}

double enclosed_volume(const Mesh& mesh) {
  double v = 0;
  for (const auto& t : mesh.triangles) {
    if (t[0] >= mesh.vertices.size() || t[1] >= mesh.vertices.size() || t[2] >= mesh.vertices.size()) continue;
    const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Point3 bc = cross(b, c);
    v += a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2];
  }
  return v / 6;
}

void write_stl(std::ostream& out, const Mesh& mesh, std::string_view title) {
  if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("an STL file holds at most 2^32 - 1 triangles");
  for (const auto& p : mesh.vertices)
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw std::invalid_argument("a mesh vertex is not a finite number");
  std::string s = "ncurve binary STL: ";
  s.append(title.substr(0, kStlHeaderBytes - std::min(s.size(), kStlHeaderBytes)));
  s.resize(kStlHeaderBytes, ' ');
  put_u32(s, static_cast<std::uint32_t>(mesh.triangles.size()));
  s.reserve(s.size() + mesh.triangles.size() * kStlTriangleBytes);
  for (const auto& t : mesh.triangles) {
    for (auto i : t)
      if (i >= mesh.vertices.size()) throw std::invalid_argument("a mesh triangle names a vertex out of range");
    const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    Point3 n = cross(sub(b, a), sub(c, a));
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x = len > 0 ? x / len : 0;
    for (double x : n) put_f32(s, x);
    for (const Point3* p : {&a, &b, &c})
      for (double x : *p) put_f32(s, x);
    s.push_back(0), s.push_back(0);
  }
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
}

void write_stl(const std::string& path, const Mesh& mesh, std::string_view title) {
  io::OutputFile file(path);
  write_stl(file.stream(), mesh, title);
  file.commit();
}

}  // namespace ncurve::sim
