// A 2-axis lathe's material removal: the stock's half-section in the ZX plane (Z along the spindle,
// X a radius >= 0, as in the moves) as integer polygons (Clipper), from which each move subtracts the
// region its tool's outline (insert_shape.hpp) sweeps. The part is that section revolved about Z.
// docs/verify.md, "Lathe: the half-section".
#pragma once
#include <memory>
#include <vector>

#include "geom/plane.hpp"
#include "machine/move.hpp"
#include "sim/insert_shape.hpp"
#include "sim/setup.hpp"
#include "sim/stl.hpp"

namespace ncurve::sim {

// The section's grid: its polygons' coordinates are whole multiples of this, mm.
inline constexpr double kSectionUnit = 1e-4;
// Every boundary point of the section lies within this of the boundary the exact round tools and
// arcs would cut, mm: the nose's chords (kChordError), an arc move's chords (kChordError) and the
// grid's rounding (half a unit on each axis).
inline constexpr double kSectionResolution = 2 * kChordError + kSectionUnit;
// The section holds Z within +-kSectionReach and X up to it, mm; a stock beyond is cut off there.
inline constexpr double kSectionReach = 10000;

// The queries, const as they are, apply the pending cuts: one thread at a time.
class LatheSection {
public:
  // The cuts are subtracted in batches of this many swept polygons (an arc makes one per chord),
  // merged pairwise before (bench_sim measures the choice: docs/performance.md).
  static constexpr int kDefaultBatch = 256;

  // The half-section of a bar or tube: Z from face - length to face, X from inner_diameter / 2 to
  // diameter / 2. A stock of no size (or a non-finite one) gives an empty section that nothing cuts.
  explicit LatheSection(const Cylinder& stock, int batch = kDefaultBatch);
  ~LatheSection();
  LatheSection(LatheSection&&) noexcept;
  LatheSection& operator=(LatheSection&&) noexcept;

  // Cuts with the tool of the given outline, its programmed point moving as the move does: a rapid or
  // a line (a thread cut as a line: the section cannot hold a helix) from start to end, or an arc of
  // the ZX plane (G18). Returns false, cutting nothing, for a move that is not motion, an arc in
  // another plane or a coordinate that is not finite.
  bool cut(const ToolOutline& tool, const machine::Move& m);
  // The same in the section's coordinates, geom::V2{z, x}: a straight move from a to b; an arc from a
  // to b about `centre` through `sweep` radians (positive from +Z towards +X, G03 on a lathe drawn
  // with X up), its radius going from |a - centre| to |b - centre| in proportion to the angle.
  void cut_line(const ToolOutline& tool, geom::V2 a, geom::V2 b);
  void cut_arc(const ToolOutline& tool, geom::V2 a, geom::V2 b, geom::V2 centre, double sweep);

  // The material the tool's outline would sweep along the move, not cut: its area (mm^2), its box and
  // its centroid (geom::V2{z, x}); none for a move that is not motion, an arc of another plane or a
  // coordinate that is not finite. A region that misses the section as it stood at the last flush
  // is answered without applying the cuts pending (the section only loses material).
  struct Overlap {
    double area = 0;
    geom::V2 lo{}, hi{}, centroid{};
  };
  Overlap overlap(const ToolOutline& tool, const machine::Move& m) const;

  // Applies the cuts still pending. Every query below does it first.
  void flush() const;

  const Cylinder& stock() const { return stock_; }
  double area() const;            // the section's area, mm^2
  double area_removed() const;    // the stock's less the section's, mm^2
  double volume() const;          // the part's volume by Pappus: 2 pi x the section's first moment about Z, mm^3
  double volume_removed() const;  // the stock's less the part's, mm^3

  // The section's boundary, mm, points as geom::V2{z, x}: outer boundaries counter-clockwise (Z to
  // the right, X up), holes clockwise.
  std::vector<std::vector<geom::V2>> polygons() const;
  // The largest and smallest radius of material on the line Z = z (the outer and inner contour); NaN
  // where there is none.
  double outer_radius(double z) const;
  // Every radius where the line Z = z crosses the section's boundary, in order.
  std::vector<double> crossings(double z) const;
  double inner_radius(double z) const;

  // The part: every contour of the section revolved about Z in `segments` equal steps (3 to 65536),
  // a closed mesh oriented outwards (a contour point on the axis is one vertex). Its volume is the
  // section's Pappus volume times segments sin(2 pi / segments) / (2 pi). Throws std::length_error
  // when its vertices would be 2^32 or more.
  Mesh mesh(int segments = 128) const;

private:
  struct State;
  Cylinder stock_;
  std::unique_ptr<State> s_;
};

}  // namespace ncurve::sim
