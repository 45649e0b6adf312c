// Tool position offset of a mill, G45..G48 (group 00, one-shot): the travel of each axis commanded
// in the block is increased (G45), decreased (G46), increased by twice (G47) or decreased by twice
// (G48) the tool offset value. FANUC 0i-MF / 30i-B operator's manual, "Tool position offset";
// docs/position-offset.md.
#include <fmt/format.h>

#include <cmath>

#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {
// G45 +1, G46 -1, G47 +2, G48 -2: the multiple of the offset added along the travel's direction.
double offset_factor(int g) {
  switch (g) {
    case 45: return 1;
    case 46: return -1;
    case 47: return 2;
    default: return -2;
  }
}
}  // namespace

// After the block's G codes: what the control does with G45..G48 besides moving.
void Executor::check_position_offset(const std::vector<int>& one_shot) {
  const int g = position_offset_;
  std::uint16_t column = 0;
  for (const Cmd& c : cmds_)
    if (c.letter == 'G' && std::lround(c.value) == g) column = c.column;
  if (compensating())
    alarm("PS0042", fmt::format("G{} (tool position offset) in cutter compensation mode (G41/G42): cancel it with "
                                "G40 first",
                                g),
          column);
  if (!one_shot.empty())
    alarm("NC9001", fmt::format("G{} with another group 00 code (G04, G10, G28, G30, G53, G92, ...) in one block is "
                                "not supported yet",
                                g),
          column);
  if (modal_.cycle != 0) {  // the manual: "G45 to G48 are ignored in canned cycle mode"
    warn_once("NC2014",
              fmt::format("G{} in canned cycle mode (G{}) is ignored, as on the control: give the tool position "
                          "offset before the cycle and cancel it after G80",
                          g, modal_.cycle),
              column);
    position_offset_ = 0;
    return;
  }
  if (xf_on_)
    alarm("NC9001", fmt::format("G{} (tool position offset) under polar coordinates, mirror image, scaling or "
                                "coordinate rotation is not supported yet",
                                g),
          column);
  if (rolls_ || extra_axes_)
    for (const Cmd& c : cmds_)
      if (const int a = axis_index(c.letter); a >= 3 && has_axis_[a])
        alarm("NC9001", fmt::format("G{} on the rotary axis {} is not supported yet", g, c.letter), c.column);
}

// The block's target with the offset: each axis word's travel from the tool's position grows by the
// factor times the offset along its own direction. A zero travel moves by the offset in G91 (the
// sign of "X-0" gives the direction) and not at all in G90. Arcs: 1/4 and 3/4 circles by I, J, K,
// whose centre offset grows the same way.
void Executor::apply_position_offset(AxisVector& target) {
  const int g = position_offset_;
  const bool by_h = profile_.position_offset_by_h;
  const double l = offset_factor(g) * (by_h ? length_offset(h_) : radius_offset(d_));
  const double tol = profile_.increment * 0.5;
  auto grown = [&](double travel, double sign) { return travel + sign * l; };
  const AxisVector programmed = target;
  for (const Cmd& c : cmds_) {
    const int a = axis_index(c.letter);
    if (a < 0 || a >= 3 || !has_axis_[a]) continue;
    const double travel = programmed[a] - coords_.pos[a];
    if (std::fabs(travel) > tol) target[a] = coords_.pos[a] + grown(travel, travel > 0 ? 1 : -1);
    else if (modal_.incremental) target[a] = coords_.pos[a] + grown(0, std::signbit(c.value) ? -1 : 1);
  }
  if (modal_.motion != 2 && modal_.motion != 3) return;
  const PlaneAxes pa = plane_axes(modal_.plane);
  std::uint16_t column = 0;
  for (const Cmd& c : cmds_)
    if (c.letter == 'G' && std::lround(c.value) == g) column = c.column;
  if (has('R'))
    alarm("NC9002", fmt::format("G{} on an arc given by R: the manual applies the tool position offset to arcs given "
                                "by {} and {} (1/4 and 3/4 circles) only; ncurve stops here",
                                g, pa.ip, pa.iq),
          word('R').column);
  const double ip = has(pa.ip) ? dimension(word(pa.ip)) : 0.0;
  const double iq = has(pa.iq) ? dimension(word(pa.iq)) : 0.0;
  const double dp = programmed[pa.p] - coords_.pos[pa.p], dq = programmed[pa.q] - coords_.pos[pa.q];
  // a 1/4 or 3/4 circle starting on an axis through its centre: one centre offset, the end point
  // that far from the start along both plane axes, on the centre's line
  const bool along_p = std::fabs(iq) <= tol && std::fabs(ip) > tol && std::fabs(dp - ip) <= tol;
  const bool along_q = std::fabs(ip) <= tol && std::fabs(iq) > tol && std::fabs(dq - iq) <= tol;
  const double r = std::fabs(ip) + std::fabs(iq);
  const bool quarter = (along_p || along_q) && std::fabs(std::fabs(dp) - r) <= tol && std::fabs(std::fabs(dq) - r) <= tol;
  if (!quarter)
    alarm("NC9002", fmt::format("G{} on an arc that is not a 1/4 or 3/4 circle starting on an axis through its "
                                "centre: the manual allows the tool position offset on such arcs only; ncurve stops "
                                "here",
                                g),
          column);
  xf_arc_ = true;  // arc() takes this centre offset instead of the block's I J K
  xf_arc_offset_ = {along_p ? grown(ip, ip > 0 ? 1 : -1) : 0.0, along_q ? grown(iq, iq > 0 ? 1 : -1) : 0.0};
}

}  // namespace ncurve::machine
