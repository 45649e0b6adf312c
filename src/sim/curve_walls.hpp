// The cut part's walls against a nominal curve of the XY plane: at points along the curve, the
// wall the tools left is found on the curve's normal, exactly (from the cuts, not the map's cells),
// and compared with the design's wall: how far the cut went beyond it (a gouge) or stopped short
// (stock left). docs/verify.md, "Against a curve".
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "geom/curve.hpp"
#include "sim/cut_log.hpp"
#include "sim/finding.hpp"

namespace ncurve::sim {

enum class WallDesign {
  // the tool's axis was to follow the curve: the design is the groove the tool cuts along it, its
  // walls the curve moved each way by the tool's radius at the measuring level
  groove,
  // the curve is the part's edge (a contour cut with G41/G42): the design's wall is the curve
  // itself, on the side away from the tool
  edge,
};

struct WallOptions {
  WallDesign design = WallDesign::groove;
  double tol = 0.01;              // a lathe's points name their cut only beyond it (and at the extremes)
  double top = 0;                 // the stock's top: each wall is measured halfway from the cut's floor up to it
  double spacing = 0.01;          // between the curve's points measured, mm (fewer when max_points would pass)
  std::size_t max_points = 20000;
  std::size_t min_points = 500;
};

struct WallPoint {
  double t = 0;          // the curve's parameter
  double x = 0, y = 0;   // the curve's point
  double nx = 0, ny = 0; // the unit normal to the side measured
  double level = 0;      // the height the wall is measured at
  double design_offset = 0;  // the design's wall from the curve along the normal (a groove's half width)
  double error = 0;      // mm along the normal: + beyond the design's wall (a gouge), - short of it (stock left)
  std::int64_t cut = -1; // the cut that made the wall there
};

struct WallReport {
  WallDesign design = WallDesign::groove;
  bool turned = false;            // a lathe's: the points' x is Z and y the radius (section_walls.hpp)
  std::vector<WallPoint> points;  // the walls measured
  std::size_t not_cut = 0;        // curve points the tool never reached (no groove, or no edge cut there)
  std::size_t no_design = 0;      // a groove's side where the curve turns tighter than the tool: no offset wall
  double largest_gouge = 0;       // the largest + error, mm
  double largest_left = 0;        // the largest - error, as a positive number, mm
  std::int64_t gouge_at = -1, left_at = -1;  // indices into points
  double rms = 0;
  std::size_t beyond(double tol) const;
  // Sets the largest errors, where they are and the rms from the points.
  void summarize();
};

// Throws std::runtime_error when the curve has no extent in XY.
WallReport measure_walls(const CutLog& cuts, const geom::Curve& curve, const WallOptions& options);

// The block of a wall point's `cut` (its file and line).
using BlockOf = std::function<std::pair<const nc::SourceFile*, std::uint32_t>(std::int64_t cut)>;
BlockOf block_of(const CutLog& cuts);

// NC2087 (a gouge beyond tol) and NC2088 (stock left beyond tol), one per block and code at its
// worst point, in the order of the points' cuts.
std::vector<Finding> wall_findings(const BlockOf& block, const WallReport& walls, double tol);

// The curve's parameters at about equal steps of its length in the plane of `at` (t -> u, v),
// as many as the options ask. Throws std::runtime_error when the curve has no length there.
std::vector<double> points_along(const geom::Curve& curve, const WallOptions& options,
                                 const std::function<std::array<double, 2>(double t)>& at);

}  // namespace ncurve::sim
