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
  if (t_code) change_tool(*t_code);
}

void LatheSectionSink::change_tool(int t_code) {
  if (tool_) {
    const double v = section_.volume_removed();
    volume_by_tool_[tool_number_] += v - volume_at_change_;
    volume_at_change_ = v;
  }
  tool_number_ = lathe_tool_number(t_code);
  tool_ = nullptr;
  if (tool_number_ == 0) return;
  auto it = outlines_.find(t_code);
  if (it == outlines_.end()) {
    ToolOutline outline;
    if (auto t = tools_.tools.find(tool_number_); t != tools_.tools.end()) {
      outline = tool_outline(t->second, options_.size);
    } else {
      auto o = offsets_.find(t_code % 100);
      const machine::LatheOffset offset = o == offsets_.end() ? machine::LatheOffset{} : o->second;
      const double tip = offset.tip;
      outline = insert_outline(
          default_insert(offset.r + offset.r_wear, std::isfinite(tip) && tip >= 0 && tip <= 9 ? static_cast<int>(tip) : 0),
          options_.size);
    }
    it = outlines_.emplace(t_code, std::move(outline)).first;
  }
  tool_ = &it->second;
  if (!tool_ || tool_->empty()) tool_ = nullptr;
}

void LatheSectionSink::on_move(const machine::Move& m) {
  using machine::MoveKind;
  if (m.kind == MoveKind::tool_change) return change_tool(m.code);
  if (!m.is_motion()) return;
  if (!tool_) {
    ++counts_.no_tool;
    return;
  }
  if (m.kind == MoveKind::arc && m.plane != 18) {
    ++counts_.not_zx_arc;
    return;
  }
  if (m.kind == MoveKind::rapid) return rapid(m);
  if (section_.cut(*tool_, m)) ++counts_.cut;
  else ++counts_.not_finite;
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
    section_.cut(*tool_, leg);
    length += std::hypot(leg.end[0] - leg.start[0], leg.end[2] - leg.start[2]);
  }
  ++counts_.cut;
  const double removed = before - section_.area();
  if (!(removed > 1e-3 * std::max(length, 1.0))) return;
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
