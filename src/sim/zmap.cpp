#include "sim/zmap.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ncurve::sim {

ZMap::ZMap(const Box& stock, double cell, int min_cells, double most_cells) : stock_(stock) {
  const double lx = stock.max[0] - stock.min[0], ly = stock.max[1] - stock.min[1];
  if (!(lx > 0 && ly > 0 && stock.max[2] >= stock.min[2])) throw std::invalid_argument("the stock box is empty");
  if (cell == 0) {
    if (min_cells < 1) throw std::invalid_argument("a Z-map needs at least one cell a side");
    cell = std::min(lx, ly) / min_cells;
  }
  if (!(cell > 0) || !std::isfinite(cell)) throw std::invalid_argument("a Z-map's cell size must be positive");
  const double nx = std::ceil(lx / cell - 1e-9), ny = std::ceil(ly / cell - 1e-9);
  if (!(nx * ny <= most_cells))  // (NaN too)
    throw std::invalid_argument(
        fmt::format("a Z-map of {:.0f} x {:.0f} cells is more than the {:.0f} allowed", nx, ny, most_cells));
  cell_ = cell;
  inv_cell_ = 1 / cell;
  nx_ = static_cast<int>(nx);
  ny_ = static_cast<int>(ny);
  // the grid centred on the stock (it overhangs by under a cell where the size is not a multiple)
  x0_ = stock.min[0] - (nx_ * cell - lx) / 2;
  y0_ = stock.min[1] - (ny_ * cell - ly) / 2;
  h_.assign(static_cast<std::size_t>(nx_) * ny_, stock.max[2]);
  steps_.resize(static_cast<std::size_t>(nx_));
  for (int k = 0; k < nx_; ++k) steps_[k] = k * cell_;
}

double ZMap::height_at(double x, double y) const {
  const double fi = std::floor((x - x0_) / cell_), fj = std::floor((y - y0_) / cell_);
  if (!(fi >= 0 && fi < nx_ && fj >= 0 && fj < ny_)) return std::numeric_limits<double>::quiet_NaN();
  return height(static_cast<int>(fi), static_cast<int>(fj));
}

void ZMap::clear_cell(int i, int j) { start_cell(i, j, stock_.min[2]); }

void ZMap::start_cell(int i, int j, double height) {
  double& h = h_[static_cast<std::size_t>(j) * nx_ + i];
  const double top = stock_.max[2], bottom = stock_.min[2];
  const double to = height > bottom ? height : bottom;  // NaN: none
  if (!(to < h)) return;
  absent_ += (std::clamp(h, bottom, top) - std::clamp(to, bottom, top)) * cell_ * cell_;
  h = to;
}

void ZMap::mark_cuts(std::uint32_t id) {
  if (cut_by_.empty()) cut_by_.assign(h_.size(), kNoCut);
  cut_id_ = id;
  report_ = true;
}

double ZMap::volume_removed() const {
  const double top = stock_.max[2], bottom = stock_.min[2];
  double sum = 0;
  for (double h : h_) sum += top - std::max(std::min(h, top), bottom);
  return sum * cell_ * cell_ - absent_;
}

void ZMap::cut_line(const ToolShape& tool, const Point3& a, const Point3& b) {
  Pass p{0, ny_, report_, false, &before_, nullptr, {}, cut_id_};
  pass_line(tool, a, b, p);
  last_ = p.out;
}

void ZMap::cut_arc(const ToolShape& tool, const Arc& arc) {
  Pass p{0, ny_, report_, false, &before_, nullptr, {}, cut_id_};
  pass_arc(tool, arc, p);
  last_ = p.out;
}

CutReport ZMap::probe_line(const ToolShape& tool, const Point3& a, const Point3& b) {
  Pass p{0, ny_, true, true, &before_, nullptr, {}, kNoCut};
  pass_line(tool, a, b, p);
  return p.out;
}

CutReport ZMap::probe_arc(const ToolShape& tool, const Arc& arc) {
  Pass p{0, ny_, true, true, &before_, nullptr, {}, kNoCut};
  pass_arc(tool, arc, p);
  return p.out;
}

void ZMap::before_row(const double* h, int n, Pass& p) const {
  if (p.report) p.before->assign(h, h + n);
}

void ZMap::after_row(double* h, int i0, int j, int n, Pass& p) {
  if (!p.report) return;
  if (!p.probe && !cut_by_.empty()) {
    std::uint32_t* by = cut_by_.data() + static_cast<std::size_t>(j) * nx_ + i0;
    for (int k = 0; k < n; ++k)
      if (h[k] < (*p.before)[k]) by[k] = p.mark;
  }
  const double top = stock_.max[2], bottom = stock_.min[2];
  const std::vector<double>& before = *p.before;
  CutReport& out = p.out;
  double removed_sum = 0;
  for (int k = 0; k < n; ++k) {
    const double was = std::min(before[k], top);
    if (h[k] >= was || was <= bottom) continue;
    const double removed = was - std::max(h[k], bottom);
    removed_sum += removed;
    if (removed > out.deepest) out = {out.volume, removed, i0 + k, j, before[k]};
  }
  const double volume = removed_sum * cell_ * cell_;
  out.volume += volume;
  if (p.volumes && volume != 0) p.volumes->push_back(volume);
  if (p.probe) std::copy(before.begin(), before.begin() + n, h);
}

void ZMap::rows_of(double yl, double yh, int& j0, int& j1) const {
  j0 = j1 = 0;
  if (!(yl <= yh)) return;
  // centres y0 + (j + 0.5) cell in [yl, yh]
  const double a = std::ceil((yl - y0_) / cell_ - 0.5), b = std::floor((yh - y0_) / cell_ - 0.5);
  j0 = static_cast<int>(std::clamp(a, 0.0, static_cast<double>(ny_)));
  j1 = static_cast<int>(std::clamp(b + 1, 0.0, static_cast<double>(ny_)));
}

}  // namespace ncurve::sim
