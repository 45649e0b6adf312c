// Polar coordinate interpolation (G12.1/G13.1; G112/G113 on a lathe) and cylindrical interpolation
// (G07.1; G107 on a lathe) as the FANUC 0i/15i/16i operator's manuals describe them
// (docs/polar-cylindrical.md). In either mode the program is a contour in a Cartesian plane: for
// G12.1 the linear axis (No.5460) and a hypothetical axis addressed by the rotary axis (No.5461),
// for G07.1 the surface of the cylinder of radius r developed flat, the rotary axis's angle read as
// the arc length r * angle. The interpreter moves in that plane (coords_.pos holds it: the hypothetical or
// developed coordinate sits in the slot of the linear axis it stands beside), cutter compensation
// offsets the contour there, and the path stage DevelopedConversion (path/developed_conversion.hpp)
// turns each move into the linear and rotary axes' moves.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine/g_codes.hpp"
#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {
constexpr double kDeg = 180 / std::numbers::pi;
const char* const kAxisLetters = "XYZABC";

}  // namespace

// G07.1 (71), G12.1 (121), G13.1 (131); G107 is G07.1's other name, G112 and G113 a lathe's.
bool Executor::developed_code(int g, std::uint16_t column) {
  if ((g == 1120 || g == 1130) && !profile_.lathe()) return false;  // G107 is on both
  if (g == 71 || g == 1070) return cylinder_code(column), true;
  if (g == 121 || g == 1120) return polar_start(column), true;
  // G13.1: outside the mode there is nothing to cancel
  if (!dev_) return true;
  if (!dev_->polar)
    alarm("PS0176", fmt::format("{} in cylindrical interpolation mode: cancel G07.1 with G07.1 {}0", g_name(g),
                                kAxisLetters[dev_->rotary]),
          column);
  for (const Cmd& c : cmds_)
    if (axis_index(c.letter) >= 0)
      alarm("PS0145", fmt::format("{} is given in a block of its own, without axis words", g_name(g)), c.column);
  if (compensating())
    alarm("PS0146", fmt::format("{} in cutter compensation mode: cancel G41/G42 with G40 inside the polar "
                                "coordinate interpolation mode first",
                                g_name(g)),
          column);
  end_developed();
  return true;
}

void Executor::polar_start(std::uint16_t column) {
  if (dev_)
    alarm(dev_->polar ? "PS0146" : "PS0176",
          dev_->polar ? "G12.1 in polar coordinate interpolation mode: it is on already"
                      : "G12.1 in cylindrical interpolation mode: cancel G07.1 first",
          column);
  const int n = static_cast<int>(profile_.axes.size());
  const int ln = profile_.polar_linear_axis, rn = profile_.polar_rotary_axis;
  if (ln < 1 || ln > n || rn < 1 || rn > n)
    alarm("PS0145", fmt::format("G12.1 needs the axes of the polar coordinate interpolation plane: set parameter "
                                "No.5460 (the linear axis) and No.5461 (the rotary axis) to their axis numbers, "
                                "1 to {} (axes {}); now {} and {}",
                                n, profile_.axes, ln, rn),
          column);
  const int lin = axis_index(profile_.axes[ln - 1]), rot = axis_index(profile_.axes[rn - 1]);
  if (lin > 2 || rot < 3 || !rotary_[rot])
    alarm("PS0145", fmt::format("G12.1: No.5460 must name a linear axis (X, Y or Z) and No.5461 a rotary axis "
                                "(No.1006#0 = 1); they name {} and {}",
                                profile_.axes[ln - 1], profile_.axes[rn - 1]),
          column);
  for (const Cmd& c : cmds_)
    if (axis_index(c.letter) >= 0)
      alarm("PS0145", "G12.1 is given in a block of its own, without axis words", c.column);
  if (compensating())
    alarm("PS0146", "G12.1 in cutter compensation mode: give G40 before G12.1 and start G41/G42 inside the mode",
          column);
  if (xf_on_) alarm("PS0146", "G12.1 with a coordinate transform on: cancel G16, G51, G51.1 or G68 first", column);
  if (modal_.cycle != 0) alarm("PS0146", "G12.1 in a drilling canned cycle: cancel it with G80 first", column);
  Developed d;
  d.polar = true;
  d.linear = lin;
  d.rotary = rot;
  d.slot = lin == 0 ? 1 : lin == 1 ? 2 : 0;  // the hypothetical axis: Xp-Yp, Yp-Zp or Zp-Xp plane
  d.p = lin;
  d.q = d.slot;
  d.saved_plane = modal_.plane;
  d.held = coords_.pos[d.slot];
  d.angle0 = coords_.pos[rot];  // "the angle of 0 for the position of the tool when G12.1 is specified"
  path_developed_.start(d, coords_.pos);
  coords_.pos[d.slot] = 0;  // "the virtual axis is at coordinate 0 immediately after G12.1"
  modal_.plane = lin == 0 ? 17 : lin == 1 ? 19 : 18;
  dev_ = d;
  developed_ = developed_hook_ = true;
}

// G07.1 C<r>: on with the cylinder's radius r, off with C0.
void Executor::cylinder_code(std::uint16_t column) {
  const Cmd* axis = nullptr;
  for (const Cmd& c : cmds_) {
    if (axis_index(c.letter) < 0) continue;
    if (axis) alarm("PS0175", "G07.1 names one rotary axis and the cylinder's radius (G07.1 C57.299)", c.column);
    axis = &c;
  }
  if (!axis) alarm("PS0175", "G07.1 names the rotary axis and the cylinder's radius (G07.1 C57.299; C0 cancels)", column);
  const int a = axis_index(axis->letter);
  if (!has_axis_[a] || !rotary_[a])
    alarm("PS0175", fmt::format("G07.1 {}: cylindrical interpolation needs a rotary axis (No.1006#0 = 1)", axis->letter),
          axis->column);
  const double r = dimension(*axis);
  if (r == 0) {
    developed_hook_ = true;  // the word is no move
    if (!dev_) return;
    if (dev_->polar)
      alarm("PS0146", "G07.1 in polar coordinate interpolation mode: cancel G12.1 with G13.1 first", column);
    if (dev_->rotary != a)
      alarm("PS0175", fmt::format("G07.1 {}0: the cylindrical interpolation mode is on for {}", axis->letter,
                                  kAxisLetters[dev_->rotary]),
            axis->column);
    if (compensating())
      alarm("PS0176", "G07.1 cancel in cutter compensation mode: cancel G41/G42 with G40 inside the mode first",
            column);
    end_developed();
    return;
  }
  if (r < 0) alarm("PS0175", "G07.1: the cylinder's radius is negative", axis->column);
  if (dev_)
    alarm(dev_->polar ? "PS0146" : "PS0176",
          dev_->polar ? "G07.1 in polar coordinate interpolation mode: cancel G12.1 with G13.1 first"
                      : "G07.1 in cylindrical interpolation mode: cancel it (G07.1 C0) before giving a new radius",
          column);
  const int parallel = profile_.rotary[a].parallel;
  if (parallel < 5)
    alarm("PS0175", fmt::format("G07.1 {}: set parameter No.1022 of {} to 5, 6 or 7 (the axis it is parallel to: "
                                "X, Y or Z); it is {}",
                                axis->letter, axis->letter, parallel),
          axis->column);
  const int slot = parallel - 5;
  const PlaneAxes pa = plane_axes(modal_.plane);
  if (pa.p != slot && pa.q != slot)
    alarm("PS0175", fmt::format("G07.1 {}: {} stands for {} (No.1022 = {}), which is not in the G{} plane: select "
                                "the plane of {} and the other linear axis before G07.1",
                                axis->letter, axis->letter, kAxisLetters[slot], parallel, modal_.plane, kAxisLetters[slot]),
          column);
  if (compensating())
    alarm("PS0176", "G07.1 in cutter compensation mode: give G40 before G07.1 and start G41/G42 inside the mode",
          column);
  if (xf_on_) alarm("PS0176", "G07.1 with a coordinate transform on: cancel G16, G51, G51.1 or G68 first", column);
  if (modal_.cycle != 0) alarm("PS0176", "G07.1 in a drilling canned cycle: cancel it with G80 first", column);
  if (modal_.motion == 0)
    alarm("PS0176", "G07.1 in G00 mode: cylindrical interpolation moves by G01, G02 and G03 only; give G01 in a "
                    "block before G07.1",
          column);
  Developed d;
  d.polar = false;
  d.rotary = a;
  d.slot = slot;
  d.p = pa.p;
  d.q = pa.q;
  d.radius = r;
  d.saved_plane = modal_.plane;
  const AxisVector machine = coords_.pos;
  if (has_axis_[slot]) {  // the linear axis the rotary axis stands beside keeps moving in a free slot
    d.held = coords_.pos[slot];
    for (int k = 0; k < 3 && d.spare < 0; ++k)
      if (!has_axis_[k] && k != slot) d.spare = k;
    if (d.spare >= 0) coords_.pos[d.spare] = coords_.pos[slot];
  }
  coords_.pos[slot] = coords_.pos[a] / kDeg * r;
  path_developed_.start(d, machine);
  dev_ = d;
  developed_ = developed_hook_ = true;
}

void Executor::end_developed() {
  coords_.pos = path_developed_.machine();
  path_developed_.stop();
  modal_.plane = dev_->saved_plane;
  dev_.reset();
  developed_ = false;  // developed_hook_ stays for the block's axis words (G07.1 C0)
  if (rolls_) wrap_rotary();
}

void Executor::check_code_in_developed(int g, std::uint16_t column) const {
  const GCode* row = g_code(g, g_machine(profile_));
  if (!row || row->kind == GKind::none) return;
  // lathe system A G50 with axis words sets the coordinate system; G50 S alone clamps the spindle
  if (row->kind == GKind::coordinate_setting_with_axes && !(has('X') || has('Z') || has('U') || has('W'))) return;
  const char* what = to_string(row->kind);
  if (!what) return;
  if (!dev_->polar && g == 170 + 10 * (dev_->saved_plane - 17)) return;  // the plane in force
  alarm(dev_->polar ? "PS0146" : "PS0176",
        fmt::format("{} ({}) cannot be given in {} mode: cancel it with {} first", g_name(g), what,
                    dev_->polar ? "polar coordinate interpolation (G12.1)" : "cylindrical interpolation (G07.1)",
                    dev_->polar ? "G13.1" : fmt::format("G07.1 {}0", kAxisLetters[dev_->rotary])),
        column);
}

// The block's axis words in the programmed plane: the rotary axis's address is the hypothetical
// axis (polar: a length, a radius value even where X is a diameter) or the angle on the cylinder
// (G07.1: degrees, made the arc length r * angle).
bool Executor::developed_axis_target(AxisVector& target) {
  const bool radius_word = std::ranges::any_of(g_codes_, [](int g) { return g == 71 || g == 1070; });
  if (!dev_) {  // the block that cancelled G07.1
    developed_hook_ = false;
    return radius_word ? false : axis_target(target);
  }
  if (radius_word) return false;  // G07.1 C<r>: the word is the radius
  const Developed& d = *dev_;
  const bool lathe = profile_.lathe();
  const bool system_a = lathe && profile_.gcode_system == 'A';
  const char* mode = d.polar ? "polar coordinate interpolation (G12.1)" : "cylindrical interpolation (G07.1)";
  const char* code = d.polar ? "PS0146" : "PS0176";
  if (rolls_) roll_word_.fill(false);
  if (corner_on_ || (lathe && modal_.motion == 1 && (has('I') || has('K') || has('R'))))
    alarm("NC9001", fmt::format("chamfering and corner R in {} mode are not supported yet", mode));
  if (!d.polar && (modal_.motion == 2 || modal_.motion == 3) && (has('I') || has('J') || has('K')))
    alarm("PS0022", "in cylindrical interpolation mode (G07.1) an arc is given by its radius R, not by I, J, K");
  bool any = false;
  for (const Cmd& c : cmds_) {
    int a = axis_index(c.letter);
    bool incremental = modal_.incremental;
    if (system_a && (c.letter == 'U' || c.letter == 'V' || c.letter == 'W' || (c.letter == 'H' && d.rotary == 5))) {
      a = c.letter == 'U' ? 0 : c.letter == 'V' ? 1 : c.letter == 'W' ? 2 : 5;
      incremental = true;
    }
    if (a < 0) continue;
    if (!has_axis_[a])
      alarm("PS0009", fmt::format("address {}: this machine has no {} axis", c.letter, kAxisLetters[a]), c.column);
    int slot = a;
    double v = 0;
    if (a == d.rotary) {
      slot = d.slot;
      v = d.polar ? dimension(c) : angle(c) / kDeg * d.radius;
    } else {
      if (a == d.slot) {
        if (d.spare < 0)
          alarm("NC9001", fmt::format("moving {} in {} mode on this machine is not supported yet ({} stands in its "
                                      "place in the plane)",
                                      kAxisLetters[a], mode, kAxisLetters[d.rotary]),
                c.column);
        slot = d.spare;
      }
      v = rotary_[a] ? angle(c) : dimension(c);
      if (a == 0 && lathe && profile_.diameter_x) v /= 2;
    }
    target[slot] = incremental ? target[slot] + v : v;
    any = true;
  }
  if (any && (modal_.motion == 0 || modal_.motion > 3))
    alarm(code, fmt::format("{} mode moves by G01, G02 or G03 only (the modal motion is {})", mode,
                            modal_.motion == 0 ? "G00" : "a lathe cycle or threading"));
  return any;
}

}  // namespace ncurve::machine
