// What stands for a setup's missing parts: the default stock box from the moves, and the defaults
// in words for the summary.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/setup.hpp"

namespace ncurve::sim {
namespace {

// The extent of a move's path, XYZ: a line's two ends; an arc's ends and the quadrant points of
// its circle that its sweep passes, its normal axis linear from start to end (a helix).
AxisBox extent(const machine::Move& m) {
  AxisBox b;
  for (int i = 0; i < 3; ++i) {
    b.min[i] = std::min(m.start[i], m.end[i]);
    b.max[i] = std::max(m.start[i], m.end[i]);
  }
  if (m.kind != machine::MoveKind::arc || m.sweep == 0) return b;
  const machine::PlaneAxes a = machine::plane_axes(m.plane);
  const double cp = m.center[a.p], cq = m.center[a.q];
  const double r = std::max(std::hypot(m.start[a.p] - cp, m.start[a.q] - cq), std::hypot(m.end[a.p] - cp, m.end[a.q] - cq));
  const double from = std::atan2(m.start[a.q] - cq, m.start[a.p] - cp);
  const double lo = std::min(from, from + m.sweep), hi = std::max(from, from + m.sweep);
  // the quadrant angles k * 90 degrees within [lo, hi]
  for (double k = std::ceil(lo / (std::numbers::pi / 2)); k * (std::numbers::pi / 2) <= hi; ++k) {
    const int quadrant = static_cast<int>(std::fmod(std::fmod(k, 4) + 4, 4));
    const double dp = quadrant == 0 ? r : quadrant == 2 ? -r : 0;
    const double dq = quadrant == 1 ? r : quadrant == 3 ? -r : 0;
    b.min[a.p] = std::min(b.min[a.p], cp + dp);
    b.max[a.p] = std::max(b.max[a.p], cp + dp);
    b.min[a.q] = std::min(b.min[a.q], cq + dq);
    b.max[a.q] = std::max(b.max[a.q], cq + dq);
  }
  return b;
}

}  // namespace

void DefaultStockBox::on_move(const machine::Move& m) {
  if (m.kind == machine::MoveKind::tool_change) tool_ = m.code;
  if (m.kind != machine::MoveKind::line && m.kind != machine::MoveKind::arc) return;
  const double r = std::max(tool_radius_(tool_, m.d_offset), 0.0);
  AxisBox e = extent(m);
  for (int i = 0; i < 3; ++i) e.min[i] -= r;
  for (int i = 0; i < 2; ++i) e.max[i] += r;
  if (!box_) {
    box_ = e;
    top_ = m.start[2];
    return;
  }
  for (int i = 0; i < 3; ++i) {
    box_->min[i] = std::min(box_->min[i], e.min[i]);
    box_->max[i] = std::max(box_->max[i], e.max[i]);
  }
  top_ = std::max(top_, m.start[2]);
}

std::optional<AxisBox> DefaultStockBox::box() const {
  if (!box_) return std::nullopt;
  AxisBox b = *box_;
  b.max[2] = top_;
  return b;
}

std::optional<AxisBox> default_stock_box(std::span<const machine::Move> moves,
                                         const std::function<double(int)>& tool_radius, int first_tool) {
  DefaultStockBox finder([&](int t, int) { return tool_radius(t); }, first_tool);
  for (const machine::Move& m : moves) finder.on_move(m);
  return finder.box();
}

std::vector<std::string> setup_defaults(const SetupFile* setup, bool lathe) {
  std::vector<std::string> lines;
  if ((!setup || !setup->stock) && lathe)
    lines.push_back("stock: the bar about the spindle axis out to the largest radius a cutting move starts from, "
                    "its face at the largest Z one starts from, as long as the cuts reach towards the chuck");
  else if (!setup || !setup->stock)
    lines.push_back("stock: the box around the cutting moves, widened by the tool's radius to the sides and below, "
                    "its top the highest level a cutting move starts from");
  if (!setup || setup->fixtures.empty()) lines.push_back("fixtures: none");
  if (!setup || !setup->tool_in_spindle)
    lines.push_back("tool in the spindle at the start: none; the first tool change (M06, a lathe's T) puts one in");
  lines.push_back(setup && !setup->tools.tools.empty()
                      ? "a tool not in the library: a flat end mill of the radius of the D offset in force when it "
                        "first cuts (on a lathe an insert of its offset's nose radius and imaginary tip)"
                      : "tools: no library: each tool is a flat end mill of the radius of the D offset in force when "
                        "it first cuts (on a lathe an insert of its offset's nose radius and imaginary tip)");
  if (setup)
    for (const std::string& d : setup->defaulted) lines.push_back(d);
  return lines;
}

}  // namespace ncurve::sim
