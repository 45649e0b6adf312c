// Reading an STL file, binary or ASCII, into a sim::Mesh: a setup's STL stock or fixture, or the
// design solid of `ncurve run --design` (docs/verify.md, docs/setup.md).
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "sim/stl.hpp"

namespace ncurve::sim {

// The most triangles read from one file (a binary STL of 500 MB, 840 MB as a Mesh): a larger file
// is refused before anything is allocated for it.
inline constexpr std::size_t kMostStlTriangles = 10'000'000;

// The mesh of an STL file's bytes, every coordinate times `scale` (25.4: a file in inches); three
// vertices a triangle (no vertex shared), the normals ignored. A file whose size is exactly that of
// a binary STL of its count is read as binary, else one starting with "solid" as ASCII. Throws
// std::runtime_error "ORIGIN: error: ..." ("ORIGIN:line:column: error: ..." in an ASCII file)
// saying what is wrong: too short, a count that does not match the size, a coordinate that is not
// a finite number, a word out of place, no triangle, all triangles in one plane (not a solid).
Mesh parse_stl(std::string_view bytes, const std::string& origin, double scale = 1);
// The same from a file; its size is checked before it is read.
Mesh read_stl(const std::string& path, double scale = 1);

}  // namespace ncurve::sim
