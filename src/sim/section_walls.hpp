// A turned part's surface against a profile curve (the walls of curve_walls.hpp on a lathe): at
// points along the curve the section's boundary nearest the curve on the radial line through the
// point is its surface, and the error is taken along the curve's normal; the material's side of the
// surface there (below it for an outside profile, above it in a bore) says which way is a gouge.
// docs/verify.md, "Against a curve".
#pragma once
#include <cstdint>
#include <vector>

#include "geom/approx.hpp"
#include "machine/move.hpp"
#include "sim/curve_walls.hpp"
#include "sim/lathe_section.hpp"

namespace ncurve::sim {

// A lathe's feed moves as the tool tip's path in (Z, radius), each with its block: the move nearest a
// wall point is taken as the one that made it.
class ProfileMoves final : public machine::MoveSink {
public:
  void on_move(const machine::Move& m) override;
  // The segment nearest (z, r), -1 when there is none; its block by block().
  std::int64_t nearest(double z, double r) const;
  BlockOf block() const;

private:
  struct Segment {
    double z0, r0, z1, r1;
    const nc::SourceFile* file;
    std::uint32_t line;
  };
  std::vector<Segment> segments_;
};

// Measures the section against the curve placed by `place` (machine X the radius, Z along the
// spindle). A point whose normal is within 6 degrees of the Z axis (a face) is not measured
// (no_design: a radius read there says nothing of it); where no material is left at the point's Z
// the whole radius is the gouge.
WallReport measure_section_walls(const LatheSection& section, const ProfileMoves& moves, const geom::Curve& curve,
                                 const geom::Placement& place, const WallOptions& options);

}  // namespace ncurve::sim
