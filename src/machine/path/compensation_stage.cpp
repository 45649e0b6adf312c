#include "machine/path/compensation_stage.hpp"

#include "machine/interpreter.hpp"

namespace ncurve::machine {

void CompensationStage::offset(const Move& m) {
  const int plane = *modes_.plane;
  const PlaneAxes pa = plane_axes(plane);
  const bool in_plane = m.kind == MoveKind::arc ? m.plane == plane
                        : m.is_motion() && (m.start[pa.p] != m.end[pa.p] || m.start[pa.q] != m.end[pa.q]);
  if (!in_plane) {
    if (!*modes_.drop || !m.is_motion()) return comp_.other(m);
    // the tool leaves its vector for the programmed point though the block does not move in the plane
    plane_motion_ = true;
    comp_.cancel_without_motion(m);
    Move to = m;
    to.start = comp_.tool_now();
    to.length = line_length(to.start.data(), to.end.data());
    to.seconds = control_.rapid_seconds(to.start, to.end);
    return comp_.element(to, 0, 0);
  }
  plane_motion_ = true;
  const OffsetOfMove o = control_.offset_of_move(pa);
  int side = *modes_.suspended ? 0 : *modes_.side;
  if (o.mirrored) side = -side;
  if (o.tip) comp_.set_tip(*o.tip);
  double radius = o.radius;
  if (radius < 0) {
    radius = -radius;
    side = -side;
  }
  std::optional<V2> cancel = side == 0 ? *modes_.cancel_direction : std::nullopt;
  comp_.element(m, side, radius, cancel);
}

void CompensationStage::block_without_plane_motion(const Move& at, bool g40, bool g41) {
  if (g40) comp_.cancel_without_motion(at);
  else if (g41) comp_.startup_without_motion(at);
  else comp_.block_without_motion(at);
}

}  // namespace ncurve::machine
