// A batch of sweeps cut with the map's rows shared between the cores. A cell's height is the least
// of its sweeps', and every row is cut by one core with the batch's sweeps in order, so each row
// ends as the sweeps one after another would leave it and each sweep finds its rows as they would
// have been; the bands' reports of a sweep are merged in row order, as the one pass adds them.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "base/parallel.hpp"
#include "sim/zmap.hpp"

namespace ncurve::sim {

namespace {

// Below this much work (cells, weighted by cell_cost) a batch is cut on the caller's thread alone:
// waking the pool would cost more than it saves.
constexpr double kShareableWork = 2e5;
// Bands a core: more than one, so a core slowed by other work is made up for by the others.
constexpr std::size_t kBandsPerCore = 3;

// A cell's cost, roughly, against a line's closed forms (flat, ball, level, plunge): the arcs'
// trigonometry and the minimisations of sloping shaped tools.
double cell_cost(const Sweep& s) {
  if (s.arc) return 8;
  const bool closed = s.tool.kind() == ToolShape::Kind::flat || s.tool.kind() == ToolShape::Kind::ball ||
                      s.a[2] == s.b[2];
  return closed ? 1 : 8;
}

// The cells of a row a sweep may reach, at most.
double row_width(const Sweep& s, double cell) {
  const double r = s.tool.radius();
  const double span = s.arc ? 2 * s.arc->radius : std::abs(s.b[0] - s.a[0]);
  return std::min((span + 2 * r) / cell + 1, 1e9);
}

// What one band says of each sweep: its deepest cell, and its rows' volumes in row order.
struct BandReports {
  std::vector<CutReport> deepest;  // one a sweep (the volume is in volumes)
  std::vector<double> volumes;     // sweep after sweep
  std::vector<std::size_t> end;    // one a sweep: where its volumes end
};

}  // namespace

void ZMap::cut_batch(std::span<const Sweep> sweeps, std::span<CutReport> reports) {
  const std::size_t n = sweeps.size();
  const bool report = !reports.empty();
  last_ = {};
  // each sweep's rows, and the work on each row (a difference array)
  std::vector<std::array<int, 2>> rows(n, {0, 0});
  std::vector<double> work(static_cast<std::size_t>(ny_) + 1, 0.0);
  int first = ny_, last = 0;
  double total = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Sweep& s = sweeps[k];
    if (s.probe && !report) continue;
    int j0, j1;
    if (s.arc) arc_rows(s.tool, *s.arc, j0, j1);
    else line_rows(s.tool, s.a, s.b, j0, j1);
    if (j1 <= j0) continue;
    rows[k] = {j0, j1};
    const double w = cell_cost(s) * row_width(s, cell_);
    work[j0] += w;
    work[j1] -= w;
    total += w * (j1 - j0);
    first = std::min(first, j0);
    last = std::max(last, j1);
  }
  // bands of rows of about equal work
  std::vector<std::array<int, 2>> bands;
  // at least a few bands, so that one core splits and merges as many do
  const std::size_t most = total < kShareableWork ? 1 : std::max<std::size_t>(4, base::cores() * kBandsPerCore);
  double acc = 0, row_work = 0;
  for (int j = first, lo = first; j < last; ++j) {
    row_work += work[j];
    acc += row_work;
    if (j + 1 == last || acc >= total * static_cast<double>(bands.size() + 1) / static_cast<double>(most)) {
      bands.push_back({lo, j + 1});
      lo = j + 1;
    }
  }

  std::vector<BandReports> said(bands.size());
  base::for_each_on_cores(bands.size(), [&](std::size_t b) {
    std::vector<double> before;
    BandReports& out = said[b];
    // (the cells' heights before each row are kept to report, or to mark the cells a cut lowers)
    Pass p{bands[b][0], bands[b][1], report || !cut_by_.empty(), false, &before, report ? &out.volumes : nullptr, {},
           kNoCut};
    if (report) {
      out.deepest.assign(n, CutReport{});
      out.end.assign(n, 0);
    }
    for (std::size_t k = 0; k < n; ++k) {
      const Sweep& s = sweeps[k];
      if (rows[k][0] < p.hi && rows[k][1] > p.lo) {
        p.probe = s.probe;
        p.mark = s.mark;
        p.out = {};
        if (s.arc) pass_arc(s.tool, *s.arc, p);
        else pass_line(s.tool, s.a, s.b, p);
        if (report) out.deepest[k] = p.out;
      }
      if (report) out.end[k] = out.volumes.size();
    }
  });
  if (!report) return;

  // the bands in row order: the volumes added as the one pass adds them, the first deepest kept
  std::vector<std::size_t> at(bands.size(), 0);
  for (std::size_t k = 0; k < n; ++k) {
    CutReport r;
    for (std::size_t b = 0; b < bands.size(); ++b) {
      for (; at[b] < said[b].end[k]; ++at[b]) r.volume += said[b].volumes[at[b]];
      const CutReport& d = said[b].deepest[k];
      if (d.deepest > r.deepest) r = {r.volume, d.deepest, d.i, d.j, d.from};
    }
    reports[k] = r;
    if (!sweeps[k].probe) last_ = r;
  }
}

}  // namespace ncurve::sim
