// A lathe's single cutting cycles and G76's passes (turning.hpp).
#include "machine/cycles/turning.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncurve::machine::turn {

namespace {
constexpr double kDeg = std::numbers::pi / 180;

// a rapid or a feed to `to`, unless the tool is there
void go(CycleOutput& out, bool rapid, const AxisVector& to) {
  if (to == out.position()) return;
  if (rapid) out.rapid(to);
  else out.feed(to);
}
}  // namespace

void thread_pass(const AxisVector& end, double out_x, const Thread& t, double start_angle, CycleOutput& out) {
  const AxisVector from = out.position();
  const double dz = std::fabs(end[2] - from[2]);
  const double run = std::min(t.chamfer * 0.1 * t.lead, dz);
  if (run <= 0) return out.thread(end, t.lead, start_angle);
  AxisVector chamfer = end;
  for (int a = 0; a < kAxes; ++a) chamfer[a] = end[a] - (end[a] - from[a]) * run / dz;
  const double theta = (t.chamfer_angle == 0 ? 45 : t.chamfer_angle) * kDeg;
  const double away = out_x > end[0] ? 1.0 : out_x < end[0] ? -1.0 : 0.0;
  AxisVector pulled = end;
  pulled[0] = chamfer[0] + away * run * std::tan(theta);
  if (chamfer != from) {
    out.thread(chamfer, t.lead, start_angle);
    start_angle = -1;
  }
  out.thread(pulled, t.lead, start_angle);
}

namespace {
struct Corners {
  AxisVector p1, p3;  // the ends of (1) and (3)
};
Corners corners(const SingleCycle& c, const AxisVector& a) {
  Corners k{a, c.end};
  if (c.code == 94) {
    k.p1[2] = c.end[2] + c.r;
    k.p3[2] = a[2];
  } else {
    k.p1[0] = c.end[0] + c.r;
    k.p3[0] = a[0];
  }
  return k;
}
}  // namespace

void single_cycle(const SingleCycle& c, CycleOutput& out) {
  const AxisVector a = out.position();
  const Corners k = corners(c, a);
  go(out, true, k.p1);
  if (c.code == 92) thread_pass(c.end, a[0], c.thread, c.start_angle, out);
  else go(out, false, c.end);
  go(out, c.code == 92, k.p3);
  out.returning();
  go(out, true, a);
}

int start_side(const SingleCycle& c, const AxisVector& a) {
  const AxisVector p1 = corners(c, a).p1;
  const double dp = c.end[2] - p1[2], dq = c.end[0] - p1[0];
  const double cross = dp * (a[0] - p1[0]) - dq * (a[2] - p1[2]);
  return cross > 0 ? 1 : cross < 0 ? -1 : 0;
}

std::vector<double> thread_depths(const MultipleThreading& c) {
  const double rough_end = c.height - c.allowance;
  std::vector<double> depths;
  for (double last = 0, n = 1; rough_end > last; ++n) {
    double d = std::max(c.first * std::sqrt(n), last + c.min_depth);
    if (d >= rough_end) d = rough_end;
    depths.push_back(d);
    last = d;
    if (depths.size() > kMaxThreadPasses) throw TooManyPasses();
  }
  for (int k = 0; k < std::max(c.finish_count, 1); ++k) depths.push_back(c.height);
  return depths;
}

void multiple_threading(const MultipleThreading& c, const std::vector<double>& depths, CycleOutput& out) {
  const AxisVector a = out.position();
  const AxisVector& end = c.end;
  const double away = a[0] > end[0] ? 1.0 : a[0] < end[0] ? -1.0 : 0.0;  // from the root toward the crest
  const double back = end[2] > a[2] ? -1.0 : end[2] < a[2] ? 1.0 : 0.0;  // against the cutting direction
  const double flank = std::tan(c.tool_angle / 2.0 * kDeg);
  for (double d : depths) {
    const double x = away * (c.height - d), z = back * (c.height - d) * flank;
    AxisVector from = a, to = end;
    from[0] = end[0] + c.taper + x;
    from[2] = a[2] + z;
    to[0] += x;
    to[2] += z;
    go(out, true, from);
    thread_pass(to, a[0], c.thread, c.start_angle, out);
    AxisVector up = out.position();
    up[0] = a[0];
    go(out, true, up);
    go(out, true, a);
  }
}

}  // namespace ncurve::machine::turn
