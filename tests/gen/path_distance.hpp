// Test helpers: the distance from a point to a move as the control draws it, in the plane of two
// of its axes (no ncurve geometry: the closed forms of a segment and an arc).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "machine/move.hpp"

namespace ncurve::test {

inline double point_segment(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  const double s = len2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(px - ax - s * dx, py - ay - s * dy);
}

// A segment, or an arc about its centre, its radius going from the start's to the end's with the
// angle (as a control draws an arc whose ends lie at slightly different radii): across the arc
// where p's angle lies within the sweep, else to the nearer end.
inline double point_move(double px, double py, const machine::Move& m, int u, int v) {
  if (m.kind != machine::MoveKind::arc) return point_segment(px, py, m.start[u], m.start[v], m.end[u], m.end[v]);
  const double cu = m.center[u], cv = m.center[v];
  const double rs = std::hypot(m.start[u] - cu, m.start[v] - cv), re = std::hypot(m.end[u] - cu, m.end[v] - cv);
  const double a0 = std::atan2(m.start[v] - cv, m.start[u] - cu), ap = std::atan2(py - cv, px - cu);
  double along = m.sweep < 0 ? a0 - ap : ap - a0;  // from the start in the sweep's sense
  along = std::fmod(along + 4 * std::numbers::pi, 2 * std::numbers::pi);
  const double ends = std::min(std::hypot(px - m.start[u], py - m.start[v]), std::hypot(px - m.end[u], py - m.end[v]));
  if (along > std::fabs(m.sweep)) return ends;
  const double r = rs + (re - rs) * along / std::fabs(m.sweep);
  return std::min(ends, std::fabs(std::hypot(px - cu, py - cv) - r));
}

// The feed moves (lines and arcs) of a run.
inline std::vector<machine::Move> feed_moves(const std::vector<machine::Move>& moves) {
  std::vector<machine::Move> out;
  for (const auto& m : moves)
    if (m.kind == machine::MoveKind::line || m.kind == machine::MoveKind::arc) out.push_back(m);
  return out;
}

// The largest distance from the points (u, v) to the nearest of `moves`.
template <class Points>
double farthest(const Points& points, const std::vector<machine::Move>& moves, int u, int v) {
  double worst = 0;
  for (const auto& [pu, pv] : points) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& m : moves) nearest = std::min(nearest, point_move(pu, pv, m, u, v));
    worst = std::max(worst, nearest);
  }
  return worst;
}

}  // namespace ncurve::test
