#include "sim/zmap_sink.hpp"

#include <cmath>

namespace ncurve::sim {

ZMapSink::ZMapSink(ZMap& map, std::map<int, ToolShape> tools, std::optional<int> spindle)
    : map_(map), tools_(std::move(tools)) {
  if (spindle) {
    auto it = tools_.find(*spindle);
    if (it != tools_.end()) tool_ = &it->second;
  }
}

void ZMapSink::on_move(const machine::Move& m) {
  using machine::MoveKind;
  if (m.kind == MoveKind::tool_change) {
    auto it = tools_.find(m.code);
    tool_ = it == tools_.end() ? nullptr : &it->second;
    return;
  }
  if (!m.is_motion()) return;
  if (!tool_) {
    ++counts_.no_tool;
    return;
  }
  const Point3 a{m.start[0], m.start[1], m.start[2]}, b{m.end[0], m.end[1], m.end[2]};
  if (m.kind != MoveKind::arc) {
    map_.cut_line(*tool_, a, b);
  } else if (m.plane == 17) {
    Arc arc;
    arc.cx = m.center[0];
    arc.cy = m.center[1];
    arc.radius = std::hypot(a[0] - arc.cx, a[1] - arc.cy);
    arc.start_angle = std::atan2(a[1] - arc.cy, a[0] - arc.cx);
    arc.sweep = m.sweep;
    arc.z_start = a[2];
    arc.z_end = b[2];
    map_.cut_arc(*tool_, arc);
  } else {
    ++counts_.not_xy_arc;
    return;
  }
  ++counts_.cut;
}

}  // namespace ncurve::sim
