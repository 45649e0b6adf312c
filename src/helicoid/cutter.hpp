// A disc cutter as a surface of revolution: its axial profile (lines and arcs in the plane of
// radius rho from the cutter axis and position w along it), parametrised by arc length.
#pragma once
#include <string>
#include <vector>

#include "helicoid/profile.hpp"

namespace ncurve::helicoid {

struct ProfileElement {
  enum class Kind { line, arc } kind = Kind::line;
  V2 start, end;  // (rho, w)
  V2 centre;      // arc only
  double radius = 0;
  double a0 = 0, a1 = 0;  // arc only: polar angles of start and end about the centre, radians
  std::string region;     // "flank-", "corner", "flank+" ...
  double length() const;
};

class DiscCutter {
public:
  // Elements joined end to end, travelled so that the cutter's material is on the left; the
  // outward normal is on the right.
  explicit DiscCutter(std::vector<ProfileElement> elements);
  // Symmetric V insert with a round corner: outside diameter, corner radius, included angle
  // (degrees) and the radial depth of its flanks below the outside diameter.
  static DiscCutter v_insert(double diameter, double corner_radius, double included_angle, double flank_depth);
  // A general axial profile from a file of vertices `rho_mm, w_mm[, radius_mm]`, listed from the
  // -w side over the rim to the +w side. The piece from a vertex to the next is a line, or with a
  // radius an arc: > 0 convex (bulging outwards), < 0 concave. The convex arc at the outermost
  // point is the "corner" (the plane method's offset); the other pieces are line<k> and arc<k>.
  static DiscCutter from_file(const std::string& path);
  static DiscCutter from_text(const std::string& text, const std::string& origin);

  double length() const { return total_; }
  double outer_radius() const { return outer_; }
  const std::vector<ProfileElement>& elements() const { return elements_; }

  struct Point {
    V2 p;       // (rho, w)
    V2 normal;  // outward unit normal in (rho, w)
    V2 tangent; // unit, direction of growing arc length
    int element;
  };
  Point at(double s) const;  // s in [0, length()]
  // Distance from a point (rho, w) of a meridian half-plane to the profile: > 0 outside the
  // cutter's material, < 0 inside. For a point in space this is its distance to the surface.
  double signed_distance(V2 q) const;
  const std::string& region(double s) const { return elements_[at(s).element].region; }
  double corner_middle() const;  // arc length of the outermost point

  // A convex joint without a common tangent (the tip of a V without a corner radius, a vertex
  // between two lines of a cutter file): an edge of the cutter, whose normals fan from the one
  // before to the one after; a surface touching the edge has its normal in that fan.
  struct Vertex {
    double s;               // arc length
    V2 before, after;     // outward unit normals of the elements meeting there
    std::size_t element;    // the element after it
  };
  const std::vector<Vertex>& vertices() const { return vertices_; }

private:
  Point at_element(std::size_t i, double local) const;
  std::vector<ProfileElement> elements_;
  std::vector<double> starts_;
  std::vector<Point> ends_;  // each element's first and last point
  std::vector<Vertex> vertices_;
  double total_ = 0, outer_ = 0;
};

}  // namespace ncurve::helicoid
