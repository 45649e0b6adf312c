#include "sim/design_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace ncurve::sim {
namespace {

// The distance, in cells, from (i, j) to the nearest cell within `reach` cells for which
// `beyond(design top)` holds; infinity where none is.
template <class Beyond>
double nearest(std::span<const double> top, int nx, int ny, int i, int j, int reach, Beyond beyond) {
  double best2 = std::numeric_limits<double>::infinity();
  for (int ring = 1; ring <= reach; ++ring) {
    if (static_cast<double>(ring) * ring >= best2) break;  // every cell of this ring is farther
    const int jl = std::max(j - ring, 0), jh = std::min(j + ring, ny - 1);
    for (int jj = jl; jj <= jh; ++jj) {
      const bool edge_row = jj == j - ring || jj == j + ring;
      const int step = edge_row ? 1 : 2 * ring;
      for (int ii = i - ring; ii <= i + ring; ii += step) {
        if (ii < 0 || ii >= nx) continue;
        const double d2 = static_cast<double>(ii - i) * (ii - i) + static_cast<double>(jj - j) * (jj - j);
        if (d2 < best2 && d2 <= static_cast<double>(reach) * reach &&
            beyond(top[static_cast<std::size_t>(jj) * nx + ii]))
          best2 = d2;
      }
    }
  }
  return std::sqrt(best2);
}

struct Worst {
  double amount = 0;
  Point3 at{};
  double design = 0;
  std::uint32_t first = ZMap::kNoCut;  // the block's first cut, for the order of the findings
};

void keep(DesignExtreme& e, double amount, const Point3& at) {
  ++e.cells;
  if (amount > e.amount) e.amount = amount, e.at = at;
}

machine::Move at_block(const BlockAt& b) {
  machine::Move m;
  m.file = b.file;
  m.line = b.line;
  return m;
}

}  // namespace

DesignResult check_design(const DesignInputs& in) {
  DesignResult out;
  out.tol = in.tol;
  const ZMap& map = *in.map;
  const int nx = map.nx(), ny = map.ny();
  const double cell = map.cell(), bottom = map.stock().min[2];
  const double reach_cells = std::min(in.tol / cell + 2, 1e6);
  std::map<std::pair<const nc::SourceFile*, std::uint32_t>, Worst> gouges;  // by block
  Worst left;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      const double h = map.height(i, j), d = in.design_top[k];
      const Point3 at{map.cell_x(i), map.cell_y(j), h};
      const std::uint32_t by = k < in.cut_by.size() ? in.cut_by[k] : ZMap::kNoCut;
      if (h < d - in.tol && by != ZMap::kNoCut && by < in.blocks.size()) {
        // not past the vertical amount nor the search's reach
        const int reach = static_cast<int>(std::ceil(std::min((d - h) / cell, reach_cells)));
        const double amount =
            std::min(d - h, cell * nearest(in.design_top, nx, ny, i, j, reach, [h](double t) { return t <= h + kLowestTolerance; }));
        if (!(amount > in.tol)) continue;
        keep(out.gouge, amount, at);
        Worst& w = gouges[{in.blocks[by].file, in.blocks[by].line}];
        w.first = std::min(w.first, by);
        if (amount > w.amount) w = {amount, at, d, w.first};
      } else if (const double floor = std::max(d, bottom); h > floor + in.tol) {
        const int reach = static_cast<int>(std::ceil(std::min((h - floor) / cell, reach_cells)));
        const double amount =
            std::min(h - floor, cell * nearest(in.design_top, nx, ny, i, j, reach, [h](double t) { return t >= h - kLowestTolerance; }));
        if (!(amount > in.tol)) continue;
        keep(out.stock_left, amount, at);
        if (amount > left.amount) left = {amount, at, floor, 0};
      }
    }
  std::vector<std::pair<BlockAt, Worst>> ordered;  // in the program's order
  for (const auto& [block, w] : gouges) ordered.push_back({{block.first, block.second}, w});
  std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.second.first < b.second.first; });
  auto add = [&](Finding f) {
    if (out.findings.size() < in.max_findings) out.findings.push_back(std::move(f));
    else ++out.left_out;
  };
  for (const auto& [block, w] : ordered)
    add(finding_at(at_block(block), "NC2087",
                   fmt::format("the cut goes {:.3f} mm into the design {} at X{:.3f} Y{:.3f} Z{:.3f} (its top there "
                               "at Z{:.3f}), beyond --tol {:g} mm: a gouge",
                               w.amount, in.design_name, w.at[0], w.at[1], w.at[2], w.design, in.tol),
                   w.at, w.amount));
  if (out.stock_left.cells > 0)
    add(finding_at(at_block(in.last),
                   "NC2088",
                   fmt::format("at the end {:.3f} mm of stock is left on the design {} at X{:.3f} Y{:.3f} (the part "
                               "at Z{:.3f}, the design at Z{:.3f}), {} cells of {:g} mm beyond --tol {:g} mm",
                               left.amount, in.design_name, left.at[0], left.at[1], left.at[2], left.design,
                               out.stock_left.cells, cell, in.tol),
                   left.at, left.amount));
  return out;
}

}  // namespace ncurve::sim
