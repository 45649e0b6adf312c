// Moves about the reference positions: G27 check, G29 return through the G28/G30 intermediate
// point, and G92.1 workpiece coordinate system preset (docs/reference-moves.md).
#include <fmt/format.h>

#include <cmath>

#include "base/restore.hpp"
#include "machine/executor.hpp"
#include "machine/word_values.hpp"

namespace ncurve::machine {

namespace {
constexpr const char* kAxisLetters = "XYZABC";
}

unsigned Executor::block_axes() const {
  const bool system_a = profile_.lathe() && profile_.gcode_system == 'A';
  unsigned axes = 0;
  for (const Cmd& c : cmds_) {
    int a = axis_index(c.letter);
    if (system_a && (c.letter == 'U' || c.letter == 'V' || c.letter == 'W')) a = c.letter == 'U' ? 0 : c.letter == 'V' ? 1 : 2;
    if (a >= 0 && has_axis_[a]) axes |= 1u << a;
  }
  return axes;
}

// A G28, G30, G29 or G53 naming an axis of the offset plane leaves the compensation vector on its
// first move, even one that stays put in the plane (docs/compensation-spec.md section 6).
bool Executor::names_plane_axis() const {
  const PlaneAxes pa = plane_axes(modal_.plane);
  return (block_axes() & ((1u << pa.p) | (1u << pa.q))) != 0;
}

// The control keeps the intermediate point of each axis a G28, G30 or G30.1 names, in work
// coordinates: after a change of coordinate system it lies at the same coordinates of the new one.
void Executor::remember_intermediate(const AxisVector& mid) {
  const unsigned axes = block_axes();
  for (int a = 0; a < kAxes; ++a)
    if (axes & (1u << a)) intermediate_[a] = mid[a];
  intermediate_axes_ |= axes;
}

// NC2074: a reference position return that takes the tool towards the part. A return is there to
// take the tool away from the part: the reference point sits where the machine builder put it, at
// the top of a mill's Z travel and at the far ends of a lathe's X and Z. A mill's return whose Z
// goes down, a lathe's whose X comes nearer the spindle centre line (work X0; the tool on the +X
// side, as X up) or whose Z goes towards the chuck (-Z) and that ends at or behind the face of the
// work zero (Z <= 0: the part lies behind it, the workpiece zero on its finished face as the
// manuals draw it; in front of the face the tool is clear of the part) is an intermediate point
// the program put below (inside) the tool, or a reference point the profile puts there (a profile
// whose work offsets are 0 has its work zero at the reference point). Each leg of the return is
// checked, once a block.
void Executor::check_return_direction(int g, int point, const AxisVector& from, const AxisVector& mid,
                                      const AxisVector& ref) {
  const double tol = profile_.increment * 0.5 + 1e-9;
  const bool lathe = profile_.lathe();
  const char* unit = modal_.inch ? "in" : "mm";
  // the axes a leg moves towards the part (a bit per axis) and what it does on them
  auto towards = [&](const AxisVector& a, const AxisVector& b, unsigned& axes) {
    std::string s;
    auto add = [&](int axis, const std::string& what) {
      s += s.empty() ? what : " and " + what;
      axes |= 1u << axis;
    };
    if (lathe) {
      if (b[2] > tol) return s;  // ends in front of the face
      const double in = std::fabs(a[0]) - std::fabs(b[0]);
      if (has_axis_[0] && in > tol)
        add(0, fmt::format("{:.3f} {}{} in X towards the spindle centre line", program_units(0, in), unit,
                           profile_.diameter_x ? " on the diameter" : ""));
      if (has_axis_[2] && a[2] - b[2] > tol)
        add(2, fmt::format("{:.3f} {} in -Z towards the chuck", program_units(2, a[2] - b[2]), unit));
    } else if (has_axis_[2] && a[2] - b[2] > tol) {
      add(2, fmt::format("{:.3f} {} down (-Z) towards the part", program_units(2, a[2] - b[2]), unit));
    }
    return s;
  };
  unsigned axes1 = 0, axes2 = 0;
  const std::string leg1 = towards(from, mid, axes1), leg2 = towards(mid, ref, axes2);
  if (leg1.empty() && leg2.empty()) return;

  const std::string code = g == 280 ? "G28" : g == 301 ? "G30.1" : fmt::format("G30 P{}", point + 1);
  const std::string target = point < 0 ? "the floating reference position" : fmt::format("reference position {}", point + 1);
  auto where = [&](const AxisVector& p, unsigned axes, bool machine) {
    std::string s;
    for (int a = 0; a < kAxes; ++a)
      if (axes & (1u << a)) {
        const double v = machine ? p[a] + coords_.origin[a] + coords_.tool_shift[a] : p[a];
        s += fmt::format("{}{}{:.3f}", s.empty() ? "" : " ", kAxisLetters[a], program_units(a, v));
      }
    return s;
  };
  const char* side = lathe ? "nearer the part than the tool" : "below the tool";
  std::string message;
  if (!leg1.empty()) {
    const std::string straight = !lathe ? fmt::format("G91 {} Z0", code)
                                 : profile_.gcode_system == 'A' ? fmt::format("{} U0 W0", code)
                                                                : fmt::format("G91 {} X0 Z0", code);
    message = fmt::format("{} rapids {} to its intermediate point {}, which the block's axis words put {} (G90: a "
                          "position in work coordinates); the tool passes through it on its way to {}, and {} goes "
                          "there straight from where the tool is",
                          code, leg1, where(mid, axes1, false), side, target, straight);
  }
  if (!leg2.empty()) {
    const std::string source = point < 0 ? "[reference_points] floating" : fmt::format("[reference_points] \"{}\"", point + 1);
    message += fmt::format("{} rapids {} to {}: the reference point is {}: the profile puts it at machine {} ({}), "
                           "which is {} in the work coordinates in force, and the tool stood at {}; a return should "
                           "take the tool away from the part: give the machine's own reference point and work offsets "
                           "in the profile ([reference_points], [work_offsets])",
                           message.empty() ? code : "; then it", leg2, target, side, where(ref, axes2, true), source,
                           where(ref, axes2, false), where(mid, axes2, false));
  }
  std::uint16_t column = 0;
  for (const Cmd& c : cmds_)
    if (c.letter == 'G' && round_int(c.value * 10) == g) column = c.column;
  warn_once("NC2074", message, column);
}

// G27 IP: positioning at rapid to IP, then each axis named must stand at reference position 1
// (machine coordinates, the tool offsets included: an active offset puts it elsewhere), else PS0092.
void Executor::reference_check() {
  AxisVector target = coords_.pos;
  if (!axis_target(target)) return;
  if (compensating())
    alarm("NC9001", "G27 in cutter compensation mode is not supported yet: cancel the compensation with G40 first, "
                    "as the manual asks");
  if (rolls_) roll_over(target);
  linear(MoveKind::rapid, target);
  const unsigned axes = block_axes();
  const double tolerance = profile_.increment * 0.5 + 1e-9;
  for (int a = 0; a < kAxes; ++a) {
    if (!(axes & (1u << a))) continue;
    const double machine = coords_.pos[a] + coords_.origin[a] + coords_.tool_shift[a];
    const double reference = profile_.reference_points[0][a];
    if (std::fabs(machine - reference) <= tolerance) continue;
    const char* offset = coords_.tool_shift[a] != 0 ? "; the tool offset in force moves it by " : "";
    alarm("PS0092", fmt::format("G27: the {} axis is at {:.4f} (machine coordinates), not at reference position 1 "
                                "({:.4f}){}{}",
                                kAxisLetters[a], program_units(a, machine), program_units(a, reference), offset,
                                coords_.tool_shift[a] != 0 ? fmt::format("{:.4f}: cancel it before G27",
                                                                  program_units(a, coords_.tool_shift[a]))
                                                    : ""));
  }
}

// G29 IP: the axes named go at rapid to the intermediate point of the last G28/G30/G30.1, then to
// IP (G91, U, W: from the intermediate point). An axis no G28/G30 has named has no intermediate
// point: it moves in the second step only. In offset mode the vector is cancelled at the
// intermediate point, as in G28, and restored at the end point.
void Executor::return_from_reference() {
  if (intermediate_axes_ == 0)
    alarm("PS0305", "G29 needs an intermediate position: no G28, G30 or G30.1 has been given since power-on");
  const unsigned axes = block_axes();
  if (axes == 0) return;
  AxisVector mid = coords_.pos;
  for (int a = 0; a < kAxes; ++a)
    if ((axes & intermediate_axes_) & (1u << a)) mid[a] = intermediate_[a];
  AxisVector target = mid;  // an incremental word counts from the intermediate point
  axis_target(target);
  if (rolls_) roll_over(target);
  {
    base::RestoreOnExit<bool> restore(comp_suspended_), restore_drop(comp_drop_);
    comp_suspended_ = true;
    comp_drop_ = names_plane_axis();
    linear(MoveKind::rapid, mid);
  }
  linear(MoveKind::rapid, target);
}

// G92.1 IP 0 (G50.3 on a system A lathe): the axes named go back to the workpiece coordinate system
// the work zero offsets give, without the shift of G92 (G50) and G52.
void Executor::workpiece_preset() {
  const unsigned axes = block_axes();
  AxisVector check = coords_.pos;
  axis_target(check, true);  // PS0009 for an axis the machine lacks
  for (const Cmd& c : cmds_) {
    const int a = axis_index(c.letter);
    if (a >= 0 && has_axis_[a] && c.value != 0)
      warn("NC2041", fmt::format("{}: the preset takes {}0 and sets the workpiece coordinate system its offsets give; "
                                 "the value is not used",
                                 profile_.lathe() && profile_.gcode_system == 'A' ? "G50.3" : "G92.1", c.letter),
           c.column);
  }
  for (int a = 0; a < kAxes; ++a)
    if (axes & (1u << a)) coords_.shift[a] = coords_.local[a] = 0;
  set_origin();
}

}  // namespace ncurve::machine
