// Test helper: solids as meshes built from closed forms (boxes, prisms) and written as STL files.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/stl.hpp"

namespace ncurve::test {

// Adds the quad a b c d (counter-clockwise seen from outside) as two triangles.
inline void add_quad(sim::Mesh& m, const sim::Point3& a, const sim::Point3& b, const sim::Point3& c,
                     const sim::Point3& d) {
  const auto n = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), {a, b, c, d});
  m.triangles.push_back({n, n + 1, n + 2});
  m.triangles.push_back({n, n + 2, n + 3});
}

// A prism over the rectangle x0..x1, y0..y1 from z = bottom up to a top that is a plane through
// (x0, top0) and (x1, top1) along X (a box when top0 == top1): closed, facing outwards.
inline sim::Mesh prism(double x0, double x1, double y0, double y1, double bottom, double top0, double top1) {
  sim::Mesh m;
  add_quad(m, {x0, y0, bottom}, {x0, y1, bottom}, {x1, y1, bottom}, {x1, y0, bottom});  // bottom, facing -Z
  add_quad(m, {x0, y0, top0}, {x1, y0, top1}, {x1, y1, top1}, {x0, y1, top0});          // top
  add_quad(m, {x0, y0, bottom}, {x1, y0, bottom}, {x1, y0, top1}, {x0, y0, top0});      // -Y side
  add_quad(m, {x1, y1, bottom}, {x0, y1, bottom}, {x0, y1, top0}, {x1, y1, top1});      // +Y side
  add_quad(m, {x0, y1, bottom}, {x0, y0, bottom}, {x0, y0, top0}, {x0, y1, top0});      // -X side
  add_quad(m, {x1, y0, bottom}, {x1, y1, bottom}, {x1, y1, top1}, {x1, y0, top1});      // +X side
  return m;
}

inline sim::Mesh box_mesh(double x0, double x1, double y0, double y1, double z0, double z1) {
  return prism(x0, x1, y0, y1, z0, z1, z1);
}

// A file in the tests' temporary folder holding the mesh as a binary STL; its path.
inline std::string stl_file(const std::string& name, const sim::Mesh& mesh) {
  const std::string path = ::testing::TempDir() + name;
  sim::write_stl(path, mesh, name);
  return path;
}

}  // namespace ncurve::test
