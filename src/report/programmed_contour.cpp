#include "report/programmed_contour.hpp"

#include <cmath>
#include <numbers>

namespace ncurve::report {

std::optional<ProgrammedContour::Piece> ProgrammedContour::on_motion(const machine::Move& m, std::array<double, 2> tip) {
  if (!started_ || m.start != last_end_) programmed_ = m.start;  // a jump (G92 ...): the program is where the tool is
  started_ = true;
  last_end_ = m.end;
  if (m.corner) return std::nullopt;
  Piece p;
  p.start = programmed_;
  programmed_ = m.compensated ? m.programmed_end : m.end;
  p.end = programmed_;
  // a compensated move, or the one cancelling the offset (from the tool centre to a programmed point)
  if (!m.compensated && m.start == p.start) return std::nullopt;
  if (!m.compensated || m.kind != machine::MoveKind::arc) return p;
  // the compensated arc is concentric with the programmed one, moved by the imaginary tip on a lathe
  p.arc = true;
  p.centre = m.center;
  p.centre[2] -= tip[0];
  p.centre[0] -= tip[1];
  const machine::PlaneAxes pa = machine::plane_axes(m.plane);
  const auto& c = p.centre;
  const double a0 = std::atan2(p.start[pa.q] - c[pa.q], p.start[pa.p] - c[pa.p]);
  const double a1 = std::atan2(p.end[pa.q] - c[pa.q], p.end[pa.p] - c[pa.p]);
  constexpr double turn = 2 * std::numbers::pi;
  double sweep = a1 - a0;
  if (std::fabs(m.sweep) > turn - 1e-9) {
    sweep = m.sweep > 0 ? turn : -turn;
  } else if (m.sweep < 0) {
    while (sweep >= -1e-12) sweep -= turn;
    while (sweep < -turn) sweep += turn;
  } else {
    while (sweep <= 1e-12) sweep += turn;
    while (sweep > turn) sweep -= turn;
  }
  p.sweep = sweep;
  return p;
}

}  // namespace ncurve::report
