// Seed 000's shape-error models beside the measured deviation, block by block: Yang's chord
// height, the radial "Joshi" error along rays from the curve's centre, and the arc-length
// estimates of Narayan and Khan against the true arc length. The models are about chords: arcs
// (G02/G03) carry the measured values only, their model fields NaN.
#pragma once
#include <cstdint>
#include <vector>

#include "gen/generate.hpp"

namespace ncurve::gen {

struct BlockShape {
  std::uint32_t line = 0;  // source line of the block
  bool arc_move = false;   // G02/G03
  double t0 = 0, t1 = 0;   // curve parameters nearest its ends
  double deviation = 0;    // measured: largest distance from the curve over [t0, t1] to the chord, mm
  double chord = 0;        // mm
  double arc = 0;          // length of the curve over [t0, t1], mm
  double radius = 0;       // radius of curvature at the middle of [t0, t1], mm (infinite where straight)
  double yang = 0;         // chord height from a = sqrt(8Rh - 4h^2): h = R - sqrt(R^2 - a^2/4), mm
  double joshi = 0;        // largest distance along a ray from the centre between the curve and the chord, mm
  double narayan = 0;      // arc length for a circle through the ends about the centre: L*phi / (2 sin(phi/2)), mm
  double khan = 0;         // arc length = pi / (2 sqrt 2) * chord, mm
};

struct ModelError {
  double max = 0;        // the model's largest value, mm
  double max_error = 0;  // largest |model - truth| over the blocks, mm
  double max_relative = 0;  // largest |model - truth| / truth (blocks where truth > 0)
  std::uint32_t line = 0;   // source line of the block of max_error
  std::size_t block = 0;    // its place in the contour, from 0 (a macro loop repeats one line)
};

struct ShapeModels {
  geom::Vec3 centre{};  // machine coordinates of the centre the radial models use (the curve's origin)
  std::vector<BlockShape> blocks;
  std::size_t lines = 0;  // blocks the models apply to
  double arc_length = 0, narayan_length = 0, khan_length = 0;  // totals, mm
  ModelError yang, joshi;       // against the measured deviation
  ModelError narayan, khan;     // against the true arc length
};

// `measured` is measure(contour, curve, o, ...) of the same contour.
ShapeModels shape_models(const std::vector<machine::Move>& contour, const geom::Curve& curve, const Options& o,
                         const Stats& measured);

}  // namespace ncurve::gen
