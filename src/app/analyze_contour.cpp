#include "app/analyze_contour.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "base/bounds.hpp"

namespace ncurve::app {
namespace {

std::string where(const machine::Move& m) {
  return m.file ? fmt::format("{}:{}", m.file->name(), m.line) : fmt::format("line {}", m.line);
}

}  // namespace

// A radius-compensated move as programmed: from the programmed end of the move before to its own.
// An arc keeps its centre (concentric with the tool's), less the imaginary tip's shift on a lathe.
machine::Move as_programmed(const machine::Move& m, const machine::AxisVector& from, const std::array<double, 3>& tip) {
  machine::Move p = m;
  p.start = from;
  p.end = m.programmed_end;
  if (m.kind != machine::MoveKind::arc) {
    p.length = std::hypot(p.end[0] - p.start[0], p.end[1] - p.start[1], p.end[2] - p.start[2]);
    return p;
  }
  const machine::PlaneAxes pa = machine::plane_axes(m.plane);
  for (int a = 0; a < 3; ++a) p.center[a] = m.center[a] - tip[a];
  const double sp = p.start[pa.p] - p.center[pa.p], sq = p.start[pa.q] - p.center[pa.q];
  const double ep = p.end[pa.p] - p.center[pa.p], eq = p.end[pa.q] - p.center[pa.q];
  constexpr double kTwoPi = 2 * std::numbers::pi;
  double sweep = std::atan2(sp * eq - sq * ep, sp * ep + sq * eq);
  const bool full = std::fabs(m.sweep) > kTwoPi - 1e-9;
  if (m.sweep > 0 && (sweep <= 1e-12 || full)) sweep += kTwoPi;
  if (m.sweep < 0 && (sweep >= -1e-12 || full)) sweep -= kTwoPi;
  p.sweep = sweep;
  const double radius = (std::hypot(sp, sq) + std::hypot(ep, eq)) / 2;
  p.length = std::hypot(std::fabs(sweep) * radius, p.end[pa.n] - p.start[pa.n]);
  return p;
}

void ContourTee::on_move(const machine::Move& m) {
  ++moves;
  if (progress) progress->at(moves);
  planner->on_move(m);
  if (part) part->on_move(m);
  if (m.kind == machine::MoveKind::tool_change && profile->lathe()) {  // T: its offset's nose radius and tip
    auto it = profile->lathe_offsets.find(m.code % 100);
    const machine::LatheOffset o = it == profile->lathe_offsets.end() ? machine::LatheOffset{} : it->second;
    const machine::TipDirection d = machine::tip_direction(static_cast<int>(o.tip));
    tip = {d.x * (o.r + o.r_wear), 0, d.z * (o.r + o.r_wear)};
  }
  if (!m.is_motion()) return;
  const machine::AxisVector from = moved ? at_programmed : m.start;
  moved = true;
  at_programmed = m.compensated ? m.programmed_end : m.end;
  if (m.compensated && !m.corner) compensated = true;
  if (!contour || (m.kind != machine::MoveKind::line && m.kind != machine::MoveKind::arc)) return;
  // as programmed: a compensated move, and the cancel move after it from the programmed point
  if (programmed && (m.compensated || (m.kind == machine::MoveKind::line && from != m.start))) {
    if (m.corner) return;
    machine::Move c = m;
    if (!m.compensated) c.programmed_end = m.end;
    const machine::Move p = as_programmed(c, from, tip);
    if (p.length <= 0) return;  // a block the compensation made in two moves
    return keep(p);
  }
  keep(m);
}

void ContourTee::keep(const machine::Move& m) {
  if (plane_only && m.end[2] != m.start[2]) return;
  if (contour->size() >= max_moves)
    throw base::BoundExceeded(fmt::format("--curve keeps every contour move to measure it: more than {}, at {}: "
                                          "raise --max-moves",
                                          max_moves, where(m)));
  contour->push_back(m);
}

}  // namespace ncurve::app
