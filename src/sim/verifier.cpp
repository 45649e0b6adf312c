#include "sim/verifier.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ncurve::sim {

namespace {

ToolShape shape_of(const MillTool& t) {
  const double r = t.radius();
  switch (t.kind) {
    case MillKind::ball: return ToolShape::ball(r);
    case MillKind::bull_nose: return ToolShape::bull_nose(r, std::min(t.corner_radius, r));
    case MillKind::drill: case MillKind::chamfer: return ToolShape::cone(r, t.point_angle > 0 ? t.point_angle : 118);
    case MillKind::flat: case MillKind::tap: break;
  }
  return ToolShape::flat(r);
}

// The block of a move's line as a span: its first non-blank column to its end.
nc::Span block_span(const machine::Move& m) {
  nc::Span s;
  s.file = m.file;
  s.line = m.line;
  if (!m.file || m.line == 0) return s;
  const std::string_view text = m.file->line(m.line);
  const std::size_t first = text.find_first_not_of(" \t");
  s.column = static_cast<std::uint32_t>(first == std::string_view::npos ? 1 : first + 1);
  s.length = static_cast<std::uint32_t>(std::max<std::size_t>(1, text.size() - std::min(first, text.size())));
  return s;
}

}  // namespace

MillTools::MillTools(const ToolLibrary& library, const machine::MachineProfile& profile)
    : library_(library), profile_(profile) {}

const VerifyTool* MillTools::get(int number, int d_offset) {
  auto [it, fresh] = tools_.try_emplace(number);
  if (it->second) return &*it->second;
  if (const MillTool* m = library_.mill(number); m && m->diameter > 0) {
    it->second = VerifyTool{*m, shape_of(*m), true};
  } else if (const auto o = profile_.tool_offsets.find(d_offset); d_offset > 0 && o != profile_.tool_offsets.end()) {
    const double radius = profile_.offset_memory == machine::OffsetMemory::C ? o->second.d_geometry + o->second.d_wear
                                                                             : o->second.geometry + o->second.wear;
    if (radius > 0 && std::isfinite(radius)) {
      const MillTool t = default_mill_tool(radius);
      it->second = VerifyTool{t, shape_of(t), false};
    }
  }
  return it->second ? &*it->second : nullptr;
}

std::optional<Box> zmap_box(const Stock& stock) {
  if (const auto* b = std::get_if<AxisBox>(&stock)) return Box{b->min, b->max};
  if (const auto* c = std::get_if<Cylinder>(&stock)) {
    const double r = c->diameter / 2;
    return Box{{-r, -r, c->face - c->length}, {r, r, c->face}};
  }
  return std::nullopt;
}

namespace {
ZMap make_map(const Stock& stock, const VerifyOptions& o) {
  const std::optional<Box> box = zmap_box(stock);
  if (!box) throw std::invalid_argument("an STL stock is not simulated yet: give a box or a cylinder");
  ZMap map(*box, o.cell, o.min_cells);
  if (const auto* c = std::get_if<Cylinder>(&stock)) {  // no material outside the bar, nor in a tube's bore
    const double r2 = c->diameter * c->diameter / 4, in2 = c->inner_diameter * c->inner_diameter / 4;
    for (int j = 0; j < map.ny(); ++j)
      for (int i = 0; i < map.nx(); ++i) {
        const double d2 = map.cell_x(i) * map.cell_x(i) + map.cell_y(j) * map.cell_y(j);
        if (d2 > r2 || d2 < in2) map.clear_cell(i, j);
      }
  }
  map.report_cuts(true);
  return map;
}
}  // namespace

Verifier::Verifier(const Stock& stock, MillTools& tools, std::optional<int> spindle, VerifyOptions options)
    : map_(make_map(stock, options)), tools_(tools), options_(options) {
  if (spindle) {
    tool_number_ = *spindle;
    tool_ = tools_.get(*spindle, 0);
  }
}

void Verifier::on_move(const machine::Move& m) {
  using machine::MoveKind;
  switch (m.kind) {
    case MoveKind::tool_change: {
      tool_number_ = m.code;
      tool_ = tools_.get(m.code, m.d_offset);
      return;
    }
    case MoveKind::spindle: spindle_on_ = m.code == 3 || m.code == 4; return;
    case MoveKind::program_end: spindle_on_ = false; return;
    case MoveKind::rapid: case MoveKind::line: case MoveKind::arc: cut(m); return;
    default: return;
  }
}

void Verifier::cut(const machine::Move& m) {
  for (int a = 3; a < machine::kAxes; ++a)
    if (m.start[a] != m.end[a]) {
      ++counts_.rotary;
      return;
    }
  if (!tool_ && tool_number_ > 0) tool_ = tools_.get(tool_number_, m.d_offset);
  if (!tool_) {
    ++counts_.no_tool;
    return;
  }
  const Point3 a{m.start[0], m.start[1], m.start[2]}, b{m.end[0], m.end[1], m.end[2]};
  if (m.kind != machine::MoveKind::arc) {
    map_.cut_line(tool_->shape, a, b);
  } else if (m.plane == 17) {
    Arc arc;
    arc.cx = m.center[0];
    arc.cy = m.center[1];
    arc.radius = std::hypot(a[0] - arc.cx, a[1] - arc.cy);
    arc.start_angle = std::atan2(a[1] - arc.cy, a[0] - arc.cx);
    arc.sweep = m.sweep;
    arc.z_start = a[2];
    arc.z_end = b[2];
    map_.cut_arc(tool_->shape, arc);
  } else {
    ++counts_.not_xy_arc;
    return;
  }
  ++counts_.cut;
  const CutReport& r = map_.last_cut();
  if (!r.removed()) return;
  volume_by_tool_[tool_number_] += r.volume;
  check(m, r);
}

void Verifier::check(const machine::Move& m, const CutReport& r) {
  const MillTool& t = tool_->tool;
  const double x = map_.cell_x(r.i), y = map_.cell_y(r.j);
  if (m.kind == machine::MoveKind::rapid) {
    find(m, "NC2080",
         fmt::format("a rapid removes material: {:.3f} mm deep at X{:.3f} Y{:.3f} (the stock there was at Z{:.3f}); "
                     "at rapid rate the tool or the part breaks: feed into material (G01) or keep the rapid clear",
                     r.deepest, x, y, r.from),
         r, r.deepest);
    return;
  }
  if (t.flute_length > 0 && r.deepest > t.flute_length + 1e-9)
    find(m, "NC2081",
         fmt::format("T{} cuts {:.3f} mm deep at X{:.3f} Y{:.3f}, deeper than its flute length {:g} mm: the shank "
                     "rubs the material above the flutes",
                     tool_number_, r.deepest, x, y, t.flute_length),
         r, r.deepest);
  const double horizontal = std::hypot(m.end[0] - m.start[0], m.end[1] - m.start[1]);
  if (!t.centre_cutting && m.kind == machine::MoveKind::line && m.end[2] < m.start[2] && horizontal < t.radius())
    find(m, "NC2082",
         fmt::format("T{} does not cut at its centre (centre_cutting = false) and plunges {:.3f} mm into material at "
                     "X{:.3f} Y{:.3f}: ramp or helix in, or drill a start hole",
                     tool_number_, r.deepest, x, y),
         r, r.deepest);
  if (!spindle_on_)
    find(m, "NC2083",
         fmt::format("T{} cuts with the spindle stopped ({:.3f} mm deep at X{:.3f} Y{:.3f}): no M03/M04 since the "
                     "last M05, M19 or the start",
                     tool_number_, r.deepest, x, y),
         r, r.deepest);
  if (t.max_spindle_speed > 0 && m.spindle > t.max_spindle_speed && !speed_warned_[tool_number_]) {
    speed_warned_[tool_number_] = true;
    find(m, "NC2084",
         fmt::format("T{} cuts at S{:g}, over its max_spindle_speed {:g} rev/min (the setup's tool library)",
                     tool_number_, m.spindle, t.max_spindle_speed),
         r, m.spindle);
  }
}

void Verifier::find(const machine::Move& m, const char* code, std::string message, const CutReport& r,
                    double amount) {
  if (!found_at_.insert({code, m.file, m.line}).second) return;  // once a block
  if (findings_.size() >= options_.max_findings) {
    ++left_out_;
    return;
  }
  Finding f;
  f.diagnostic.severity = nc::Severity::warning;
  f.diagnostic.code = code;
  f.diagnostic.message = std::move(message);
  f.diagnostic.span = block_span(m);
  f.at = {map_.cell_x(r.i), map_.cell_y(r.j), r.from - r.deepest};
  f.amount = amount;
  findings_.push_back(std::move(f));
}

}  // namespace ncurve::sim
