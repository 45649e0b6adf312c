// A Z-map of the stock for a 3-axis mill: one height per cell of a square grid over the stock's XY
// box, the height of the material on the vertical line through the cell's centre. A move lowers
// each cell it reaches to the lowest point of the tool's swept envelope on that line, computed
// per cell in closed form (or by an exact 1-D minimisation to kLowestTolerance): docs/verify.md.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sim/tool_shape.hpp"

namespace ncurve::sim {

using Point3 = std::array<double, 3>;

// A box stock, work coordinates, mm.
struct Box {
  Point3 min{}, max{};
};

// An arc in the XY plane (G17) from start_angle through sweep (radians, counter-clockwise
// positive), its height linear in the angle from z_start to z_end (a helix when they differ).
struct Arc {
  double cx = 0, cy = 0;
  double radius = 0;
  double start_angle = 0;
  double sweep = 0;
  double z_start = 0, z_end = 0;
};

// What one cut removed, when the map was asked to report it (report_cuts): material counts
// between the stock's bottom and top.
struct CutReport {
  double volume = 0;  // mm^3
  double deepest = 0; // the most material removed on one cell's line, mm
  int i = -1, j = -1; // that cell
  double from = 0;    // that cell's height before the cut
  bool removed() const { return deepest > 0; }
};

// A cut or a probe of a batch (ZMap::cut_batch): the tool's tip along the line from a to b, or
// along the arc where there is one.
struct Sweep {
  ToolShape tool;
  Point3 a{}, b{};
  std::optional<Arc> arc;
  bool probe = false;  // what it would remove, the map left as it is
  std::uint32_t mark = UINT32_MAX;  // a cut's id in ZMap::cut_by(), where the map marks its cuts
};

// A height found by minimising along a move (where no closed form is used) is within this of
// the exact lowest point, mm.
inline constexpr double kLowestTolerance = 1e-9;

// The XY box of an arc's tip path: its ends and the quadrant points it passes.
struct XYBox {
  double x0, x1, y0, y1;
};
XYBox arc_box(const Arc& arc);

// The lowest point of a tool's swept envelope on the vertical line through (x, y), the height a
// cell centred there would take (kUnreached where the tool does not pass over it).
double lowest_over(const ToolShape& tool, const Point3& a, const Point3& b, double x, double y);
double lowest_over(const ToolShape& tool, const Arc& arc, double x, double y);

class ZMap {
public:
  // cell 0: the stock's shorter side in min_cells cells
  static constexpr int kDefaultCells = 1000;
  static constexpr double kMostCells = 4e8;
  // A batch of this many sweeps is enough work to share between the cores (cut_batch).
  static constexpr std::size_t kBatchSweeps = 4096;
  // Throws std::invalid_argument for an empty box, a bad cell, or more than most_cells cells.
  explicit ZMap(const Box& stock, double cell = 0, int min_cells = kDefaultCells, double most_cells = kMostCells);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell() const { return cell_; }
  const Box& stock() const { return stock_; }
  double cell_x(int i) const { return x0_ + (i + 0.5) * cell_; }
  double cell_y(int j) const { return y0_ + (j + 0.5) * cell_; }

  // The height of cell (i, j): the stock top where nothing cut it, else the lowest tool point
  // over it (below the stock bottom where a tool went through).
  double height(int i, int j) const { return h_[static_cast<std::size_t>(j) * nx_ + i]; }
  // The height of the cell holding (x, y); NaN outside the map.
  double height_at(double x, double y) const;
  std::span<double> row(int j) { return {h_.data() + static_cast<std::size_t>(j) * nx_, static_cast<std::size_t>(nx_)}; }
  std::span<const double> heights() const { return h_; }

  // A cell of the box where the stock has no material (outside a bar): down to the bottom before
  // any cut, and not counted as removed.
  void clear_cell(int i, int j);
  // A cell of a fresh map whose material starts at `height` (an STL stock's surface; below the
  // bottom or -infinity: none), not counted as removed.
  void start_cell(int i, int j, double height);
  // Material removed, mm^3: each cell's column from the top down to its height (not below the bottom).
  double volume_removed() const;

  // Cut with a tool whose tip moves along a straight line from a to b.
  void cut_line(const ToolShape& tool, const Point3& a, const Point3& b);
  // Cut with a tool whose tip moves along an arc or helix in the XY plane.
  void cut_arc(const ToolShape& tool, const Arc& arc);

  // From now on each cut_line and cut_arc reports what it removed in last_cut() (a copy of each
  // row it changes is kept for the comparison).
  void report_cuts(bool on) { report_ = on; }
  const CutReport& last_cut() const { return last_; }
  // From now on each cut (not a probe) marks the cells it lowers with `id` (turns report_cuts on):
  // cut_by() has, per cell, the id of the cut that last lowered it, kNoCut where none did.
  static constexpr std::uint32_t kNoCut = UINT32_MAX;
  void mark_cuts(std::uint32_t id);
  std::span<const std::uint32_t> cut_by() const { return cut_by_; }
  // What a cut would remove, leaving the map as it is: where a body that must not cut (a holder,
  // a fixture's tool) would meet the material.
  CutReport probe_line(const ToolShape& tool, const Point3& a, const Point3& b);
  CutReport probe_arc(const ToolShape& tool, const Arc& arc);

  // The sweeps in order, as cut_line, cut_arc, probe_line and probe_arc one after another would
  // make them, the map's rows shared between the cores: the same heights to the bit (a cell's
  // height is the least of its sweeps', and each row sees its sweeps in order). reports: empty (the
  // probes are then skipped), or one a sweep, what each would have reported: the reports of a
  // row's band merged as the one pass over all rows would have found them. last_cut() is then the
  // last cut's report.
  void cut_batch(std::span<const Sweep> sweeps, std::span<CutReport> reports = {});

  // The rows j0..j1-1 that a band of y may touch, and the cells i0..i1-1 of a row whose centres
  // lie in [xl, xh] (empty when i1 <= i0).
  void rows_of(double yl, double yh, int& j0, int& j1) const;
  // (by the inverse of the cell: a caller pads its bounds by more than that rounding)
  void cells_of(double xl, double xh, int& i0, int& i1) const {
    i0 = i1 = 0;
    if (!(xl <= xh)) return;
    const double a = std::ceil((xl - x0_) * inv_cell_ - 0.5), b = std::floor((xh - x0_) * inv_cell_ - 0.5);
    i0 = static_cast<int>(std::clamp(a, 0.0, static_cast<double>(nx_)));
    i1 = static_cast<int>(std::clamp(b + 1, 0.0, static_cast<double>(nx_)));
  }

private:
  // One cut or probe over the rows lo..hi-1: what it keeps and what it reports.
  struct Pass {
    int lo = 0, hi = 0;
    bool report = false, probe = false;
    std::vector<double>* before = nullptr;   // a row's heights before its kernel
    std::vector<double>* volumes = nullptr;  // where kept: each row's volume removed, in row order
    CutReport out;
    std::uint32_t mark = kNoCut;  // where cut_by_ is kept: the id of the cells a cut lowers
  };
  void pass_line(const ToolShape& tool, const Point3& a, const Point3& b, Pass& p);
  void pass_arc(const ToolShape& tool, const Arc& arc, Pass& p);
  // The rows j0..j1-1 a pass visits.
  void line_rows(const ToolShape& tool, const Point3& a, const Point3& b, int& j0, int& j1) const;
  void arc_rows(const ToolShape& tool, const Arc& arc, int& j0, int& j1) const;
  // Cells i0..i1-1 widened, within the row, to a whole number of the vector kernels' steps (a
  // vector of eight cells): no scalar remainder is run, and a cell added beyond the reach is left
  // as it is.
  static constexpr int kVectorCells = 8;
  void whole_vectors(int& i0, int& i1) const {
    const int n = (i1 - i0 + kVectorCells - 1) / kVectorCells * kVectorCells;
    i1 = std::min(nx_, i0 + n);
    i0 = std::max(0, i1 - n);
  }
  // Around a row's kernel: keep the cells' heights before it, then add what it removed.
  void before_row(const double* h, int n, Pass& p) const;
  void after_row(double* h, int i0, int j, int n, Pass& p);

  Box stock_;
  double cell_ = 0, inv_cell_ = 0;
  std::vector<double> steps_;  // k * cell for the cells of a row: the line kernels' offsets (no integer in their loops)
  int nx_ = 0, ny_ = 0;
  double x0_ = 0, y0_ = 0;
  std::vector<double> h_;
  bool report_ = false;
  double absent_ = 0;  // the columns clear_cell emptied, mm^3
  CutReport last_;
  std::vector<double> before_;
  std::vector<std::uint32_t> cut_by_;  // empty until mark_cuts
  std::uint32_t cut_id_ = kNoCut;
};

}  // namespace ncurve::sim
