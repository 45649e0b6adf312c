#include "sim/verifier.hpp"

#include "machine/arc_points.hpp"
#include "machine/rapid_path.hpp"
#include "sim/mesh_top.hpp"
#include "sim/stl_read.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
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

// The sweep of a tool's shape along a line or an XY arc, its tip lifted by `lift`, as the map takes
// it; none for an arc in G18/G19.
std::optional<Sweep> sweep_of(const machine::Move& m, const ToolShape& shape, double lift = 0) {
  Sweep s{shape, {m.start[0], m.start[1], m.start[2] + lift}, {m.end[0], m.end[1], m.end[2] + lift}, std::nullopt};
  if (m.kind != machine::MoveKind::arc) return s;
  if (m.plane != 17) return std::nullopt;
  Arc arc;
  arc.cx = m.center[0];
  arc.cy = m.center[1];
  arc.radius = std::hypot(s.a[0] - arc.cx, s.a[1] - arc.cy);
  arc.start_angle = std::atan2(s.a[1] - arc.cy, s.a[0] - arc.cx);
  arc.sweep = m.sweep;
  arc.z_start = s.a[2];
  arc.z_end = s.b[2];
  s.arc = arc;
  return s;
}

// The probe of a body (shape at offset above the tip) along the move; none when it cannot meet the
// map's material.
std::optional<Sweep> probe_of(const ZMap& map, const machine::Move& m, const ToolShape& shape, double offset) {
  const double low = std::min(m.start[2], m.end[2]) + offset;
  const Box& b = map.stock();
  const double reach = shape.radius();
  const double x0 = std::min(m.start[0], m.end[0]), x1 = std::max(m.start[0], m.end[0]);
  const double y0 = std::min(m.start[1], m.end[1]), y1 = std::max(m.start[1], m.end[1]);
  // quick rejections: above the map's top, or (a line) beside it
  if (low >= b.max[2]) return std::nullopt;
  if (m.kind != machine::MoveKind::arc &&
      (x1 + reach < b.min[0] || x0 - reach > b.max[0] || y1 + reach < b.min[1] || y0 - reach > b.max[1]))
    return std::nullopt;
  std::optional<Sweep> s = sweep_of(m, shape, offset);
  if (s) s->probe = true;
  return s;
}

// Where a cut or probe found the most material: the cell's centre at the depth reached.
Point3 where(const ZMap& map, const CutReport& r) { return {map.cell_x(r.i), map.cell_y(r.j), r.from - r.deepest}; }

}  // namespace

Finding finding_at(const machine::Move& m, const std::string& code, std::string message,
                   const std::array<double, 3>& at, double amount) {
  Finding f;
  f.diagnostic.severity = nc::Severity::warning;
  f.diagnostic.code = code;
  f.diagnostic.message = std::move(message);
  nc::Span& s = f.diagnostic.span;  // the block's line from its first non-blank column
  s.file = m.file;
  s.line = m.line;
  if (m.file && m.line != 0) {
    const std::string text = m.file->line(m.line);
    const std::size_t first = text.find_first_not_of(" \t");
    s.column = static_cast<std::uint32_t>(first == std::string_view::npos ? 1 : first + 1);
    s.length = static_cast<std::uint32_t>(std::max<std::size_t>(1, text.size() - std::min(first, text.size())));
  }
  f.at = at;
  f.amount = amount;
  return f;
}

VerifyTool verify_tool(const MillTool& t, bool from_library) {
  VerifyTool v{t, shape_of(t), from_library, {}};
  const double r = t.radius();
  if (t.shank_diameter / 2 > r + 1e-9) v.bodies.push_back({ToolShape::flat(t.shank_diameter / 2), t.flute_length, "shank"});
  double z = t.stick_out;
  for (const HolderSegment& h : t.holder) {
    // a cone widening upwards as four steps, each as wide as the cone at its bottom: inside it
    const int steps = h.cone() ? 4 : 1;
    for (int k = 0; k < steps; ++k) {
      const double d = h.lower + (h.upper - h.lower) * k / steps;
      if (d > 0) v.bodies.push_back({ToolShape::flat(d / 2), z + h.length * k / steps, "holder"});
    }
    z += h.length;
  }
  return v;
}

MillTools::MillTools(const ToolLibrary& library, const machine::MachineProfile& profile)
    : library_(library), profile_(profile) {}

const VerifyTool* MillTools::get(int number, int d_offset) {
  auto [it, fresh] = tools_.try_emplace(number);
  if (it->second) return &*it->second;
  if (const MillTool* m = library_.mill(number); m && m->diameter > 0) {
    it->second = verify_tool(*m, true);
  } else if (const auto o = profile_.tool_offsets.find(d_offset); d_offset > 0 && o != profile_.tool_offsets.end()) {
    const double radius = profile_.offset_memory == machine::OffsetMemory::C ? o->second.d_geometry + o->second.d_wear
                                                                             : o->second.geometry + o->second.wear;
    if (radius > 0 && std::isfinite(radius)) {
      const MillTool t = default_mill_tool(radius);
      it->second = verify_tool(t, false);
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
  std::optional<Box> box = zmap_box(stock);
  std::optional<Mesh> mesh;  // an STL stock: the map on its box, each cell from its top
  if (const auto* stl = std::get_if<StlFile>(&stock)) box = mesh_box(mesh.emplace(read_stl(stl->path, stl->scale)));
  double cell = o.cell;
  const double lx = box->max[0] - box->min[0], ly = box->max[1] - box->min[1];
  if (cell == 0 && lx > 0 && ly > 0) {  // the shorter side in min_cells cells, coarser if that is too many
    cell = std::min(lx, ly) / o.min_cells;
    if (lx * ly / (cell * cell) > o.most_cells) cell = std::sqrt(lx * ly / o.most_cells) * (1 + 1e-9);
  }
  ZMap map(*box, cell, o.min_cells, o.most_cells);
  if (const auto* c = std::get_if<Cylinder>(&stock)) {  // no material outside the bar, nor in a tube's bore
    const double r2 = c->diameter * c->diameter / 4, in2 = c->inner_diameter * c->inner_diameter / 4;
    for (int j = 0; j < map.ny(); ++j)
      for (int i = 0; i < map.nx(); ++i) {
        const double d2 = map.cell_x(i) * map.cell_x(i) + map.cell_y(j) * map.cell_y(j);
        if (d2 > r2 || d2 < in2) map.clear_cell(i, j);
      }
  }
  if (mesh) start_at_mesh(map, *mesh);
  map.report_cuts(true);
  return map;
}
}  // namespace

Verifier::Verifier(const Stock& stock, MillTools& tools, std::optional<int> spindle, VerifyOptions options,
                   const std::vector<Fixture>& fixtures)
    : map_(make_map(stock, options)), tools_(tools), options_(options) {
  for (const Fixture& f : fixtures) {
    // the fixture's own map on the stock's cells (at least two a side), probed and never cut; an
    // STL's on its box, each cell from the mesh's top down
    std::optional<Mesh> mesh;
    Box box;
    if (const auto* b = std::get_if<AxisBox>(&f.shape)) box = {b->min, b->max};
    else box = mesh_box(mesh.emplace(read_stl(std::get<StlFile>(f.shape).path, std::get<StlFile>(f.shape).scale)));
    const double cell = std::min({map_.cell(), (box.max[0] - box.min[0]) / 2, (box.max[1] - box.min[1]) / 2});
    fixtures_.push_back({f.name, ZMap(box, cell)});
    if (mesh) start_at_mesh(fixtures_.back().map, *mesh);
  }
  if (spindle) {
    tool_number_ = *spindle;
    tool_ = tools_.get(*spindle, 0);
  }
}

void Verifier::on_setup(const machine::Setup& s) {
  if (!reference_found_) origin_ = s.origin;
}

// NC2089: reference position 1 (where G28 takes the tool and where a machine starts) inside the
// stock in the work coordinates in force: the profile's reference point or work offsets, or the
// setup's stock, are not the machine's. The spindle's gauge point is checked, which the tool's
// tip is at or below.
void Verifier::check_reference(const machine::Move& m) {
  const machine::AxisVector origin = *origin_;
  origin_.reset();
  const machine::AxisVector& ref = options_.profile->reference_points[0];
  const Point3 p{ref[0] - origin[0], ref[1] - origin[1], ref[2] - origin[2]};
  // the material over the point as the map holds it (an STL stock's top, no material outside a bar)
  const double depth = map_.height_at(p[0], p[1]) - p[2];
  if (p[2] < map_.stock().min[2] || !(depth > kFindingDepth)) return;
  find(m, "NC2089",
       fmt::format("the machine's reference position 1 is inside the stock in the work coordinates in force: "
                   "X{:.3f} Y{:.3f} Z{:.3f}, {:.3f} mm below the stock's top; G28 would drive the tool into the part "
                   "and the machine starts there: give the machine's own reference point and work offsets in the "
                   "profile ([reference_points], [work_offsets]) or the stock where it is clamped (the setup)",
                   p[0], p[1], p[2], depth),
       p, depth);
  reference_found_ = true;
}

void Verifier::on_move(const machine::Move& m) {
  using machine::MoveKind;
  if (m.line != 0) last_block_ = {m.file, m.line};
  if (origin_ && options_.profile && options_.check_reference && m.is_motion()) {
    flush();  // the findings in the moves' order
    check_reference(m);
  }
  switch (m.kind) {
    case MoveKind::tool_change: {
      flush();
      tool_number_ = m.code;
      tool_ = tools_.get(m.code, m.d_offset);
      holder_in_stock_ = false;
      return;
    }
    case MoveKind::spindle: flush(); spindle_on_ = m.code == 3 || m.code == 4; return;
    case MoveKind::program_end: flush(); spindle_on_ = false; return;
    case MoveKind::rapid:
      if (options_.profile && !options_.profile->linear_rapid && motions_ < options_.cut_moves) {
        // as the machine moves it: each axis at its own rate, a piece between corners
        const auto path = machine::rapid_path(m.start, m.end, *options_.profile);
        ++motions_;
        machine::Move piece = m;
        for (std::size_t k = 1; k < path.size(); ++k) {
          piece.start = path[k - 1];
          piece.end = path[k];
          cut(piece);
        }
        return;
      }
      [[fallthrough]];
    case MoveKind::line: case MoveKind::arc:
      if (motions_++ >= options_.cut_moves) {
        ++counts_.after;
        return;
      }
      if (m.kind == MoveKind::arc && m.plane != 17) {  // G18/G19: as chords within kArcChord of the arc
        machine::Move chord = m;
        chord.kind = MoveKind::line;
        machine::arc_points(m, kArcChord, [&](const machine::AxisVector& p) {
          chord.end = p;
          cut(chord);
          chord.start = p;
        });
        return;
      }
      cut(m);
      return;
    default: return;
  }
}

// Queues the move's cut and its bodies' probes; the checks are made when the batch is cut.
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
  std::optional<Sweep> s = sweep_of(m, tool_->shape);
  if (!s) {
    ++counts_.not_xy_arc;
    return;
  }
  if (options_.mark_cells) {  // the block, once for consecutive moves of it
    if (cut_blocks_.empty() || !(cut_blocks_.back() == BlockAt{m.file, m.line})) cut_blocks_.push_back({m.file, m.line});
    map_.mark_cuts(static_cast<std::uint32_t>(cut_blocks_.size() - 1));
    s->mark = static_cast<std::uint32_t>(cut_blocks_.size() - 1);
  }
  if (log_) log_->add(tool_->shape, s->a, s->b, s->arc, m);
  ++counts_.cut;
  queued_.push_back({m, batch_.size(), body_probes_.size()});
  batch_.push_back(std::move(*s));
  for (const ToolBody& body : tool_->bodies) {
    std::optional<Sweep> p = probe_of(map_, m, body.shape, body.offset);
    body_probes_.push_back(p ? batch_.size() : kNoProbe);
    if (p) batch_.push_back(std::move(*p));
  }
  if (batch_.size() >= ZMap::kBatchSweeps) flush();
}

void Verifier::flush() {
  if (queued_.empty()) return;
  reports_.resize(batch_.size());
  map_.cut_batch(batch_, reports_);
  std::vector<CutReport> bodies(tool_->bodies.size());
  for (const Queued& q : queued_) {
    const machine::Move& m = q.move;
    const CutReport& r = reports_[q.cut];
    if (r.removed()) volume_by_tool_[tool_number_] += r.volume;
    if (r.deepest > kFindingDepth) check(m, r);
    if (!tool_->bodies.empty()) {
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        const std::size_t p = body_probes_[q.bodies + k];
        bodies[k] = p == kNoProbe ? CutReport{} : reports_[p];
      }
      check_bodies(m, bodies);
    }
    if (!fixtures_.empty()) check_fixtures(m);
  }
  queued_.clear();
  batch_.clear();
  body_probes_.clear();
}

CutReport Verifier::probe(ZMap& map, const machine::Move& m, const ToolShape& shape, double offset) {
  const std::optional<Sweep> s = probe_of(map, m, shape, offset);
  if (!s) return {};
  return s->arc ? map.probe_arc(shape, *s->arc) : map.probe_line(shape, s->a, s->b);
}

void Verifier::check_bodies(const machine::Move& m, std::span<const CutReport> body_probes) {
  const bool was_in = holder_in_stock_;
  holder_in_stock_ = false;
  for (std::size_t k = 0; k < tool_->bodies.size(); ++k) {
    const ToolBody& body = tool_->bodies[k];
    const CutReport& r = body_probes[k];
    if (!(r.deepest > kFindingDepth)) continue;
    holder_in_stock_ = true;
    if (was_in) return;  // the same contact going on: said at the move that made it
    const std::string what = std::string(body.what) == "shank"
                                 ? fmt::format("the shank (D{:g}, wider than the cut D{:g})", tool_->tool.shank_diameter,
                                               tool_->tool.diameter)
                                 : fmt::format("the holder ({:g} mm above the tip)", body.offset);
    find(m, "NC2085",
         fmt::format("{} of T{} runs {:.3f} mm into the stock at X{:.3f} Y{:.3f} (the stock there is at Z{:.3f}): "
                     "a longer stick-out or a slimmer holder reaches",
                     what, tool_number_, r.deepest, map_.cell_x(r.i), map_.cell_y(r.j), r.from),
         where(map_, r), r.deepest);
    return;  // the lowest body that touches says it
  }
}

void Verifier::check_fixtures(const machine::Move& m) {
  for (FixtureMap& f : fixtures_) {
    CutReport r = probe(f.map, m, tool_->shape, 0);
    const char* what = "cutting end";
    for (std::size_t k = 0; !(r.deepest > kFindingDepth) && k < tool_->bodies.size(); ++k) {
      r = probe(f.map, m, tool_->bodies[k].shape, tool_->bodies[k].offset);
      what = tool_->bodies[k].what;
    }
    const bool was_in = f.touched;
    f.touched = r.deepest > kFindingDepth;
    if (!f.touched || was_in) continue;  // a contact going on was said at the move that made it
    const std::string message =
        fmt::format("T{}'s {} meets the fixture '{}' at X{:.3f} Y{:.3f}, {:.3f} mm below its top: a crash",
                    tool_number_, what, f.name, f.map.cell_x(r.i), f.map.cell_y(r.j), r.deepest);
    find(m, "NC2086", message, where(f.map, r), r.deepest);
  }
}

std::vector<std::string> Verifier::fixtures_checked() const {
  std::vector<std::string> out;
  for (const auto& f : fixtures_) out.push_back(f.name + ": checked");
  return out;
}

void Verifier::check(const machine::Move& m, const CutReport& r) {
  const MillTool& t = tool_->tool;
  const double x = map_.cell_x(r.i), y = map_.cell_y(r.j);
  if (m.kind == machine::MoveKind::rapid) {
    find(m, "NC2080",
         fmt::format("a rapid removes material: {:.3f} mm deep at X{:.3f} Y{:.3f} (the stock there was at Z{:.3f}); "
                     "at rapid rate the tool or the part breaks: feed into material (G01) or keep the rapid clear",
                     r.deepest, x, y, r.from),
         where(map_, r), r.deepest);
    return;
  }
  if (t.flute_length > 0 && r.deepest > t.flute_length + 1e-9)
    find(m, "NC2081",
         fmt::format("T{} cuts {:.3f} mm deep at X{:.3f} Y{:.3f}, deeper than its flute length {:g} mm: the shank "
                     "rubs the material above the flutes",
                     tool_number_, r.deepest, x, y, t.flute_length),
         where(map_, r), r.deepest);
  const double horizontal = std::hypot(m.end[0] - m.start[0], m.end[1] - m.start[1]);
  if (!t.centre_cutting && m.kind == machine::MoveKind::line && m.end[2] < m.start[2] && horizontal < t.radius())
    find(m, "NC2082",
         fmt::format("T{} does not cut at its centre (centre_cutting = false) and plunges {:.3f} mm into material at "
                     "X{:.3f} Y{:.3f}: ramp or helix in, or drill a start hole",
                     tool_number_, r.deepest, x, y),
         where(map_, r), r.deepest);
  if (!spindle_on_)
    find(m, "NC2083",
         fmt::format("T{} cuts with the spindle stopped ({:.3f} mm deep at X{:.3f} Y{:.3f}): no M03/M04 since the "
                     "last M05, M19 or the start",
                     tool_number_, r.deepest, x, y),
         where(map_, r), r.deepest);
  if (t.max_spindle_speed > 0 && m.spindle > t.max_spindle_speed && !speed_warned_[tool_number_]) {
    speed_warned_[tool_number_] = true;
    find(m, "NC2084",
         fmt::format("T{} cuts at S{:g}, over its max_spindle_speed {:g} rev/min (the setup's tool library)",
                     tool_number_, m.spindle, t.max_spindle_speed),
         where(map_, r), m.spindle);
  }
}

void Verifier::find(const machine::Move& m, const char* code, std::string message, const Point3& at, double amount) {
  if (!found_at_.insert({code, m.file, m.line}).second) return;  // once a block
  if (findings_.size() >= options_.max_findings) {
    ++left_out_;
    return;
  }
  findings_.push_back(finding_at(m, code, std::move(message), at, amount));
}

}  // namespace ncurve::sim
