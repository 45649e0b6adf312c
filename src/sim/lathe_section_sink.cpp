#include "sim/lathe_section_sink.hpp"

#include <cmath>

namespace ncurve::sim {

LatheSectionSink::LatheSectionSink(LatheSection& section, ToolLibrary tools,
                                   std::map<int, machine::LatheOffset> offsets, std::optional<int> t_code,
                                   InsertSize size)
    : section_(section), tools_(std::move(tools)), offsets_(std::move(offsets)), size_(size) {
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
      outline = tool_outline(t->second, size_);
    } else {
      auto o = offsets_.find(t_code % 100);
      const machine::LatheOffset offset = o == offsets_.end() ? machine::LatheOffset{} : o->second;
      const double tip = offset.tip;
      outline = insert_outline(
          default_insert(offset.r + offset.r_wear, std::isfinite(tip) && tip >= 0 && tip <= 9 ? static_cast<int>(tip) : 0),
          size_);
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
  if (section_.cut(*tool_, m)) ++counts_.cut;
  else ++counts_.not_finite;
}

std::map<int, double> LatheSectionSink::volume_by_tool() const {
  std::map<int, double> v = volume_by_tool_;
  if (tool_) v[tool_number_] += section_.volume_removed() - volume_at_change_;
  return v;
}

}  // namespace ncurve::sim
