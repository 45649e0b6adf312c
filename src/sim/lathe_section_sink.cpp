#include "sim/lathe_section_sink.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "machine/rapid_path.hpp"

namespace ncurve::sim {

LatheSectionSink::LatheSectionSink(LatheSection& section, ToolLibrary tools,
                                   std::map<int, machine::LatheOffset> offsets, std::optional<int> t_code,
                                   LatheSinkOptions options)
    : section_(section), tools_(std::move(tools)), offsets_(std::move(offsets)), options_(std::move(options)) {
  for (const Fixture& f : options_.fixtures) {
    const auto* box = std::get_if<AxisBox>(&f.shape);
    if (!box) {
      unchecked_fixtures_.push_back(f.name);
      continue;
    }
    const Cylinder ring = fixture_ring(*box);
    fixtures_.push_back({f.name, ring, LatheSection(ring)});
  }
  if (t_code) change_tool(*t_code);
}

Cylinder fixture_ring(const AxisBox& box) {
  auto nearest = [](double lo, double hi) { return lo > 0 ? lo : hi < 0 ? -hi : 0.0; };
  const double dx = nearest(box.min[0], box.max[0]), dy = nearest(box.min[1], box.max[1]);
  const double fx = std::max(std::fabs(box.min[0]), std::fabs(box.max[0]));
  const double fy = std::max(std::fabs(box.min[1]), std::fabs(box.max[1]));
  Cylinder c;
  c.inner_diameter = 2 * std::hypot(dx, dy);
  c.diameter = 2 * std::hypot(fx, fy);
  c.face = box.max[2];
  c.length = box.max[2] - box.min[2];
  return c;
}

std::vector<std::string> LatheSectionSink::fixtures_checked() const {
  std::vector<std::string> out;
  for (const FixtureRing& f : fixtures_)
    out.push_back(fmt::format("{}: checked, the ring Z{:g}..{:g} at radius {:g}..{:g}", f.name, f.ring.face - f.ring.length,
                              f.ring.face, f.ring.inner_diameter / 2, f.ring.diameter / 2));
  for (const std::string& n : unchecked_fixtures_) out.push_back(n + ": an STL fixture, not checked on a lathe yet");
  return out;
}

void LatheSectionSink::change_tool(int t_code) {
  if (tool_) {
    const double v = section_.volume_removed();
    volume_by_tool_[tool_number_] += v - volume_at_change_;
    volume_at_change_ = v;
  }
  tool_number_ = lathe_tool_number(t_code);
  tool_ = nullptr;
  holder_in_ = false;
  if (tool_number_ == 0) return;
  auto it = outlines_.find(t_code);
  if (it == outlines_.end()) {
    TurretTool tool;
    if (auto t = tools_.tools.find(tool_number_); t != tools_.tools.end()) {
      tool.cutting = tool_outline(t->second, options_.size);
      tool.bodies = lathe_bodies(t->second, tool.cutting);
      if (const auto* mill = std::get_if<MillTool>(&t->second)) {
        tool.what = "cutting end";
        const double f = mill->flute_length, r = mill->diameter / 2, top = f + std::max(mill->stick_out - f, 4 * r);
        if (f > 0 && r > 0 && std::isfinite(top) && top < 1e6) {
          tool.past_flutes.points = {{f, -r}, {top, -r}, {top, r}, {f, r}};
          tool.flute_length = f;
        }
        if (!mill->centre_cutting && r > 0) tool.no_centre = r;
      }
    } else {
      auto o = offsets_.find(t_code % 100);
      const machine::LatheOffset offset = o == offsets_.end() ? machine::LatheOffset{} : o->second;
      const double tip = offset.tip;
      tool.cutting = insert_outline(
          default_insert(offset.r + offset.r_wear, std::isfinite(tip) && tip >= 0 && tip <= 9 ? static_cast<int>(tip) : 0),
          options_.size);
    }
    it = outlines_.emplace(t_code, std::move(tool)).first;
  }
  tool_ = it->second.cutting.empty() ? nullptr : &it->second;
}

namespace {

// The length of the tip's path along a line or an arc of the ZX plane, mm.
double path_length(const machine::Move& m) {
  if (m.kind != machine::MoveKind::arc) return std::hypot(m.end[0] - m.start[0], m.end[2] - m.start[2]);
  const double r0 = std::hypot(m.start[0] - m.center[0], m.start[2] - m.center[2]);
  const double r1 = std::hypot(m.end[0] - m.center[0], m.end[2] - m.center[2]);
  return std::fabs(m.sweep) * std::max(r0, r1);
}

// Section area a finding needs along a path this long: 1 um across it, at least 1 mm of it (less is
// the grid's and the chords' rounding).
double area_limit(double length) { return 1e-3 * std::max(length, 1.0); }

}  // namespace

void LatheSectionSink::on_move(const machine::Move& m) {
  using machine::MoveKind;
  if (m.kind == MoveKind::tool_change) return change_tool(m.code);
  if (m.kind == MoveKind::spindle) spindle_on_ = m.code == 3 || m.code == 4;
  if (m.kind == MoveKind::program_end) spindle_on_ = false;
  if (!m.is_motion()) return;
  if (motions_++ >= options_.cut_moves) {
    ++counts_.after;
    return;
  }
  if (!tool_) {
    ++counts_.no_tool;
    return;
  }
  if (m.kind == MoveKind::arc && m.plane != 18) {
    ++counts_.not_zx_arc;
    return;
  }
  holder_was_ = holder_in_;
  holder_in_ = false;
  for (FixtureRing& f : fixtures_) {
    f.was = f.in;
    f.in = false;
  }
  if (m.kind == MoveKind::rapid) return rapid(m);
  if (!tool_->past_flutes.empty()) {  // before the cut: what the part above the flutes goes through
    const LatheSection::Overlap o = section_.overlap(tool_->past_flutes, m);
    if (o.area > area_limit(path_length(m)))
      find(m, "NC2081",
           fmt::format("T{} goes into material past its flutes ({:g} mm): {:.3f} mm^2 of the bar's half-section is "
                       "cut by its body above them, about Z{:.3f} radius {:.3f}; the chips cannot leave and the tool "
                       "breaks: peck, or a tool with longer flutes",
                       tool_number_, tool_->flute_length, o.area, o.centroid.x, o.centroid.y),
           {o.centroid.y, 0, o.centroid.x}, o.area);
  }
  if (tool_->no_centre > 0 && m.end[2] < m.start[2] &&
      std::fabs(m.end[0] - m.start[0]) < tool_->no_centre) {  // a plunge: does it meet material?
    const LatheSection::Overlap o = section_.overlap(tool_->cutting, m);
    if (o.area > area_limit(path_length(m)))
      find(m, "NC2082",
           fmt::format("T{} plunges into material towards the chuck, but does not cut at its centre: {:.3f} mm^2 of the "
                       "bar's half-section ahead of it; the core it cannot cut rubs its end: a centre-cutting tool, or "
                       "a drilled hole first",
                       tool_number_, o.area),
           {o.centroid.y, 0, o.centroid.x}, o.area);
  }
  const double before = spindle_on_ ? 0 : section_.area();  // the bar standing still: does this cut?
  if (!section_.cut(tool_->cutting, m)) {
    ++counts_.not_finite;
    return;
  }
  ++counts_.cut;
  if (!spindle_on_) {
    const double removed = before - section_.area();
    if (removed > area_limit(path_length(m)))
      find(m, "NC2083",
           fmt::format("a cut removes material with the spindle stopped (no M03/M04 since the start, or M05/M19 "
                       "before): {:.3f} mm^2 of the bar's half-section; the insert meets a bar standing still and "
                       "breaks: start the spindle before the cut",
                       removed),
           {m.end[0], m.end[1], m.end[2]}, removed);
  }
  check_bodies(m, m);
  check_fixtures(m, m);
}


void LatheSectionSink::check_bodies(const machine::Move& m, const machine::Move& piece) {
  const double limit = area_limit(path_length(piece));
  for (const LatheBody& body : tool_->bodies) {
    const LatheSection::Overlap o = section_.overlap(body.outline, piece);
    if (!(o.area > limit)) continue;
    holder_in_ = true;
    if (holder_was_) return;  // the same contact going on: said at the move that made it
    find(m, "NC2085",
         fmt::format("the {} of T{} meets the bar: {:.3f} mm^2 of the half-section inside it along the move, about "
                     "Z{:.3f} radius {:.3f} (Z{:.3f}..{:.3f}, radius {:.3f}..{:.3f}): a crash; cut less deep at once or "
                     "hold the insert so that the holder clears the part",
                     body.what, tool_number_, o.area, o.centroid.x, o.centroid.y, o.lo.x, o.hi.x, o.lo.y, o.hi.y),
         {o.centroid.y, 0, o.centroid.x}, o.area);
    return;
  }
}

void LatheSectionSink::check_fixtures(const machine::Move& m, const machine::Move& piece) {
  const double limit = area_limit(path_length(piece));
  for (FixtureRing& f : fixtures_) {
    auto touch = [&](const ToolOutline& outline, const char* what) {
      const LatheSection::Overlap o = f.section.overlap(outline, piece);
      if (!(o.area > limit)) return false;
      f.in = true;
      if (f.was) return true;  // the same contact going on: said at the move that made it
      find(m, "NC2086",
           fmt::format("T{}'s {} meets the fixture '{}': {:.3f} mm^2 of its ring inside the {} along the move, about "
                       "Z{:.3f} radius {:.3f} (Z{:.3f}..{:.3f}, radius {:.3f}..{:.3f}): a crash",
                       tool_number_, what, f.name, o.area, what, o.centroid.x, o.centroid.y, o.lo.x, o.hi.x, o.lo.y,
                       o.hi.y),
           {o.centroid.y, 0, o.centroid.x}, o.area);
      return true;
    };
    if (touch(tool_->cutting, tool_->what)) continue;
    for (const LatheBody& b : tool_->bodies)
      if (touch(b.outline, b.what)) break;
  }
}

void LatheSectionSink::rapid(const machine::Move& m) {
  for (int a : {0, 2})
    if (!std::isfinite(m.start[a]) || !std::isfinite(m.end[a])) {
      ++counts_.not_finite;
      return;
    }
  // as the machine moves it: X (a radius in the moves, and its rapid rate the slide's) and Z each at
  // its own rate, a leg between corners; the section's area before and after says whether it went
  // through material
  const std::vector<machine::AxisVector> path =
      options_.profile ? machine::rapid_path(m.start, m.end, *options_.profile) : std::vector{m.start, m.end};
  const double before = section_.area();
  double length = 0;
  machine::Move leg = m;
  for (std::size_t k = 1; k < path.size(); ++k) {
    leg.start = path[k - 1];
    leg.end = path[k];
    section_.cut(tool_->cutting, leg);
    length += path_length(leg);
    check_bodies(m, leg);
    check_fixtures(m, leg);
  }
  ++counts_.cut;
  const double removed = before - section_.area();
  if (!(removed > area_limit(length))) return;
  const std::string corner =
      path.size() > 2 ? fmt::format(" by its corner at Z{:.3f} radius {:.3f} (each axis at its own rapid rate)",
                                    path[1][2], path[1][0])
                      : std::string();
  const double volume = 2 * std::numbers::pi * removed * std::max(0.5 * (m.start[0] + m.end[0]), 0.0);
  find(m, "NC2080",
       fmt::format("a rapid removes material: {:.3f} mm^2 of the bar's half-section (about {:.1f} mm^3) on its way from "
                   "Z{:.3f} at radius {:.3f} to Z{:.3f} at radius {:.3f}{}; at rapid rate the insert or the part breaks: "
                   "feed into material (G01) or keep the rapid clear",
                   removed, volume, m.start[2], m.start[0], m.end[2], m.end[0], corner),
       {m.end[0], m.end[1], m.end[2]}, removed);
}

void LatheSectionSink::find(const machine::Move& m, const char* code, std::string message,
                            const std::array<double, 3>& at, double amount) {
  if (!found_at_.insert({code, m.file, m.line}).second) return;  // once a block and code
  if (findings_.size() >= 200) {
    ++left_out_;
    return;
  }
  findings_.push_back(finding_at(m, code, std::move(message), at, amount));
}

std::map<int, double> LatheSectionSink::volume_by_tool() const {
  std::map<int, double> v = volume_by_tool_;
  if (tool_) v[tool_number_] += section_.volume_removed() - volume_at_change_;
  return v;
}

}  // namespace ncurve::sim
