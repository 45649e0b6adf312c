// The cut part against a design solid (`ncurve run --design part.stl`): on each cell of the Z-map,
// a gouge where the cut went below the design's top, stock left where material stands above it,
// each measured as a distance (the smaller of the vertical one and the horizontal one to the
// nearest cell on the other side of the design's surface at that height): docs/verify.md.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sim/finding.hpp"
#include "sim/verifier.hpp"
#include "sim/zmap.hpp"

namespace ncurve::sim {

// The worst of one kind: how much, where (the cell's centre at the part's height) and how many
// cells are beyond the tolerance.
struct DesignExtreme {
  double amount = 0;  // mm; 0: none
  Point3 at{};
  std::size_t cells = 0;
};

struct DesignResult {
  double tol = 0;
  DesignExtreme gouge, stock_left;
  std::vector<Finding> findings;  // NC2087 a block, NC2088 at the last block
  std::size_t left_out = 0;       // beyond max_findings: counted only
};

struct DesignInputs {
  const ZMap* map = nullptr;              // the cut part
  std::span<const double> design_top;     // mesh_top of the design on the map's grid
  std::span<const std::uint32_t> cut_by;  // ZMap::cut_by: the block that last lowered each cell
  std::span<const BlockAt> blocks;        // Verifier::cut_blocks
  BlockAt last;                           // Verifier::last_block: where stock left is said
  std::string design_name;                // the design file, in the messages
  double tol = 0.01;                      // mm
  std::size_t max_findings = 200;
};

// A gouge at cell c, whose part is at h below the design's top d there, is
// min(d - h, the distance from c to the nearest cell whose design top is at or below h); stock
// left, h above d (a cell the design does not cover: above the stock's bottom), is
// min(h - d, the distance to the nearest cell whose design top is at or above h). Cells are
// searched out to tol / cell + 2 cells; where none is found the vertical amount stands. A gouge
// needs a cut there (a cell no cut lowered is the stock as it came). Findings: NC2087 once a block
// (the one that last lowered the cells) with its worst cell, NC2088 once at the last block.
DesignResult check_design(const DesignInputs& in);

}  // namespace ncurve::sim
