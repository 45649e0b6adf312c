// A triangle mesh and its binary STL file: the cut part of a mill or a lathe written as a closed
// surface (issue 36's `--part part.stl`).
#pragma once
#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace ncurve::sim {

using Point3 = std::array<double, 3>;

// An indexed triangle mesh, mm. Each triangle's vertices run counter-clockwise seen from outside
// the solid (its normal by the right-hand rule points out).
struct Mesh {
  std::vector<Point3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Whether the mesh is closed and consistently oriented: every edge a -> b of a triangle is used by
// exactly one other triangle, as b -> a. An empty mesh is closed.
bool is_closed(const Mesh& mesh);

// The signed volume the mesh encloses (the divergence theorem: the sum of each triangle's tetrahedron
// with the origin), mm^3; positive for a closed mesh oriented outwards.
double enclosed_volume(const Mesh& mesh);

// The STL header of 80 bytes: "ncurve binary STL: " and the title, cut to fit and padded with spaces
// (never starting with "solid", which readers take for an ASCII STL).
inline constexpr std::size_t kStlHeaderBytes = 80;
inline constexpr std::size_t kStlTriangleBytes = 50;

// The binary STL of the mesh: the header, the triangle count (little-endian uint32), then per
// triangle its unit normal and three vertices as little-endian float32 and a zero attribute word.
// Throws std::invalid_argument for a vertex index out of range, a non-finite vertex or more than
// 2^32 - 1 triangles.
void write_stl(std::ostream& out, const Mesh& mesh, std::string_view title = "");
// The same to a file, written whole or not at all (io::OutputFile); throws io::OutputError.
void write_stl(const std::string& path, const Mesh& mesh, std::string_view title = "");

}  // namespace ncurve::sim
