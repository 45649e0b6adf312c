// The coordinate transform modes of a FANUC mill, as the 0i-MF / 30i-B operator's manuals describe
// them: polar coordinate command (G15/G16, group 17), programmable mirror image (G50.1/G51.1,
// group 22), scaling (G50/G51, group 11) and coordinate system rotation (G68/G69, group 16).
// A programmed point goes through polar -> mirror -> scaling -> rotation (transforms.hpp); cutter
// compensation then offsets the transformed path. The machine's position (coords_.pos) is always the
// transformed one; the programmed position is its inverse image.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "machine/g_codes.hpp"
#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {
const char* const kAxisLetters = "XYZABC";

}  // namespace

// Codes a transform mode forbids: "In coordinate system rotation mode [programmable mirror image
// mode], G codes related to reference position return (G27, G28, G29, G30, etc.) and those for
// changing the coordinate system (G52 to G59, G92, etc.) must not be specified", and the plane
// must not change in G68 mode (PS0144). Scaling is held to the same rule.
void Executor::check_code_in_transform(int g, std::uint16_t column) const {
  if (!xf_.active()) return;
  if ((g == 170 || g == 180 || g == 190) && xf_.rotating && g / 10 != xf_rotation_plane_)
    alarm("PS0144", fmt::format("the plane cannot change (G{}) in coordinate system rotation mode (G68 in the "
                                "G{} plane): cancel the rotation with G69 first",
                                g / 10, xf_rotation_plane_),
          column);
  const GCode* row = g_code(g, g_machine(profile_));
  const GKind kind = row ? row->kind : GKind::none;
  const bool reference = kind == GKind::reference;
  const bool coordinates = kind == GKind::coordinate_change || kind == GKind::coordinate_setting;
  if (!reference && !coordinates) return;
  const char* mode = xf_.rotating    ? "coordinate system rotation mode (G68): cancel it with G69"
                     : xf_.scaling   ? "scaling mode (G51): cancel it with G50"
                                     : "programmable mirror image mode (G51.1): cancel it with G50.1";
  // in scaling, PS0300 ILLEGAL COMMAND IN SCALING; rotation and mirror image name no alarm
  alarm(xf_.scaling ? "PS0300" : "PS0010",
        fmt::format("{} ({}) cannot be given in {} first{}", g_name(g),
                    reference ? "reference position return" : "coordinate system change", mode,
                    xf_.scaling ? "" : " (the manual forbids it and names no alarm; ncurve stops here)"),
        column);
}

// The block's G15/G16, G50.1/G51.1, G50/G51 and G68/G69, after its other G codes (so that its
// plane and G90/G91 count). Cancels first, then mirror, scaling, rotation: the manual's order.
// G51.1, G50.1, G51 and G68 take the block's axis words as data: the block does not move.
void Executor::transform_codes(std::vector<int>& one_shot) {
  auto given = [&](int g) { return std::find(g_codes_.begin(), g_codes_.end(), g) != g_codes_.end(); };
  auto column_of = [&](int g) {
    for (const Cmd& c : cmds_)
      if (c.letter == 'G' && std::lround(c.value * 10) == g) return c.column;
    return std::uint16_t{0};
  };
  auto order = [&](int g, const char* what) {  // PS0300 in scaling (ILLEGAL COMMAND IN SCALING), else none named
    alarm(xf_.scaling ? "PS0300" : "PS0010",
          fmt::format("{} cannot be given in {} mode: mirror image, scaling and rotation are given in that order "
                      "and cancelled in the reverse order{}",
                      g_name(g), what, xf_.scaling ? "" : " (the manual names no alarm; ncurve stops here)"),
          column_of(g));
  };
  auto not_in_compensation = [&](int g) {
    if (compensating())
      alarm("NC9001", fmt::format("{} in cutter compensation mode is not supported yet: give it before G41/G42 "
                                  "or after G40",
                                  g_name(g)),
            column_of(g));
  };
  if (given(150)) modal_.polar = false;
  if (given(690) && xf_.rotating) {
    xf_.rotating = false;
    xf_rotation_deg_ = 0;
    xf_cancelled_ = true;  // "the first move command after G69 must be specified as an absolute command"
  }
  if (given(500) && xf_.scaling) {
    if (xf_.rotating) order(500, "coordinate system rotation (G68)");
    not_in_compensation(500);
    xf_.scaling = false;
    xf_.factor.fill(1);
  }
  if (given(501)) {
    if (xf_.rotating || xf_.scaling) order(501, xf_.rotating ? "coordinate system rotation (G68)" : "scaling (G51)");
    if (xf_.mirroring()) not_in_compensation(501);
    bool any = false;
    for (const Cmd& c : cmds_) {
      const int a = axis_index(c.letter);
      if (a < 0) continue;
      if (!has_axis_[a])
        alarm("PS0009", fmt::format("address {}: this machine has no {} axis", c.letter, c.letter), c.column);
      xf_.mirrored[a] = false;  // the value is ignored
      any = true;
    }
    if (!any) xf_.mirrored.fill(false);
    one_shot.push_back(501);
  }
  if (given(160)) modal_.polar = true;
  if (given(511)) {
    if (xf_.rotating || xf_.scaling) order(511, xf_.rotating ? "coordinate system rotation (G68)" : "scaling (G51)");
    not_in_compensation(511);
    for (const Cmd& c : cmds_) {
      const int a = axis_index(c.letter);
      if (a < 0) continue;
      if (!has_axis_[a])
        alarm("PS0009", fmt::format("address {}: this machine has no {} axis", c.letter, c.letter), c.column);
      xf_.mirrored[a] = true;
      xf_.mirror_at[a] = dimension(c);  // the position of the mirror, as a coordinate
    }
    one_shot.push_back(511);
  }
  if (given(510)) {
    if (xf_.rotating) order(510, "coordinate system rotation (G68)");
    not_in_compensation(510);
    // P I J K count 0.00001 (No.5400#7 SCR = 0) or 0.001; with a decimal point they are the factor
    const double unit = profile_.scaling_unit_coarse ? 0.001 : 0.00001;
    const char* unit_text = profile_.scaling_unit_coarse ? "0.001" : "0.00001";
    auto magnification = [&](char letter, int fallback, bool negative_allowed) {
      double units = fallback;
      if (has(letter)) {
        const Cmd& c = word(letter);
        units = c.literal && !c.decimal_point ? c.value : std::round(c.value / unit);
      }
      if (std::fabs(units) < 1 || std::fabs(units) > 999999 || (units < 0 && !negative_allowed))
        alarm("PS0142",
              has(letter)
                  ? fmt::format("scaling magnification {}{} is out of range: {} to 999999 units of {} (No.5400#7 SCR)",
                                letter, word(letter).value, negative_allowed ? "-999999 .. -1 or 1" : "1", unit_text)
                  : fmt::format("G51 without {}: the magnification of parameter No.{} is {} (1 to 999999 units of {})",
                                letter, negative_allowed ? 5421 : 5411, fallback, unit_text),
              has(letter) ? word(letter).column : column_of(510));
      return units * unit;
    };
    AxisVector factor{1, 1, 1, 1, 1, 1};
    if (profile_.scaling_per_axis) {
      if (has('P'))
        warn("NC2011", "G51 P: this machine scales each axis by I, J, K (No.5400#6 XSC = 1); P is not read",
             word('P').column);
      for (int a = 0; a < 3; ++a)
        if (has_axis_[a]) factor[a] = magnification("IJK"[a], profile_.scaling_axis_default, true);
    } else {
      if (has('I') || has('J') || has('K'))
        warn("NC2011", "G51 I J K: per-axis magnifications need No.5400#6 XSC = 1; every axis is scaled by P "
                       "(or No.5411)",
             column_of(510));
      const double p = magnification('P', profile_.scaling_default, false);
      for (int a = 0; a < 3; ++a)
        if (has_axis_[a]) factor[a] = p;
    }
    // the centre: X Y Z as absolute coordinates (through the mirror), else the tool's position
    AxisVector centre = coords_.pos;
    for (int a = 0; a < 3; ++a)
      if (has_axis_[a] && has(kAxisLetters[a])) {
        const double c = dimension(word(kAxisLetters[a]));
        centre[a] = xf_.mirrored[a] ? 2 * xf_.mirror_at[a] - c : c;
      }
    xf_.scaling = true;
    xf_.factor = factor;
    xf_.scale_centre = centre;
    one_shot.push_back(510);
  }
  if (given(680)) {
    if (compensating() && xf_.scaling)
      alarm("PS0010", "G68 in cutter compensation mode with scaling on: the manual says to give G68 before "
                      "G41/G42 (it names no alarm; ncurve stops here)",
            column_of(680));
    const PlaneAxes pa = plane_axes(modal_.plane);
    double angle = profile_.rotation_default_deg;  // No.5410 when R is left out
    if (has('R')) {
      const Cmd& r = word('R');
      const double deg = r.literal && !r.decimal_point && !profile_.decimal_calculator ? r.value * profile_.increment
                                                                                      : r.value;
      const bool add = profile_.rotation_angle_by_g90_g91 && modal_.incremental;  // No.5400#0 RIN
      angle = add ? xf_rotation_deg_ + deg : deg;
    }
    xf_rotation_deg_ = angle;
    // the centre: the plane's two axis words as absolute coordinates, passed through the mirror and
    // the scaling ("the coordinate value of the rotation center will also be scaled"); else the tool
    AxisVector given_centre{};
    for (int a : {pa.p, pa.q})
      if (has(kAxisLetters[a])) given_centre[a] = dimension(word(kAxisLetters[a]));
    const AxisVector mapped = xf_.mirror_and_scale(given_centre);
    xf_.centre = {has(kAxisLetters[pa.p]) ? mapped[pa.p] : coords_.pos[pa.p],
                  has(kAxisLetters[pa.q]) ? mapped[pa.q] : coords_.pos[pa.q]};
    // a mirror on one axis of the plane reverses the direction of rotation
    xf_.angle_deg = xf_.mirrored[pa.p] != xf_.mirrored[pa.q] ? -angle : angle;
    xf_.p = pa.p;
    xf_.q = pa.q;
    xf_.rotating = true;
    xf_rotation_plane_ = modal_.plane;
    xf_cancelled_ = false;
    one_shot.push_back(680);
  }
  xf_on_ = modal_.polar || xf_.active();
  xf_hook_ = xf_on_ || xf_cancelled_;
}

// axis_target under G16 or a transform: the words are read in program coordinates (from the
// programmed position, the inverse image of the machine's), polar words made Cartesian, then the
// point is transformed. Axes the transform leaves alone keep their exact value.
bool Executor::transformed_axis_target(AxisVector& target) {
  struct Restore {
    bool& flag;
    bool saved;
    ~Restore() { flag = saved; }
  } restore{xf_hook_, xf_hook_};
  xf_hook_ = false;  // the plain reader below
  if (!xf_on_) {  // only the move after G69 is still to be checked
    const bool any = axis_target(target);
    if (any) {
      if (modal_.incremental)
        warn("NC2012", "an incremental move right after G69: the manual says the first move after G69 must be "
                       "absolute (the control does not move correctly); ncurve moves by the increment from the "
                       "tool's position");
      xf_cancelled_ = false;
      restore.saved = false;
    }
    return any;
  }
  xf_cancelled_ = false;
  restore.saved = true;
  const AxisVector work = target;
  AxisVector prog = xf_.active() ? xf_.invert(target) : target;
  const AxisVector start = prog;
  const bool any = axis_target(prog);
  const bool g92 = std::find(g_codes_.begin(), g_codes_.end(), 920) != g_codes_.end();
  if (modal_.polar && !g92) {  // G16: the plane's first axis word is the radius, the second the angle
    const PlaneAxes pa = plane_axes(modal_.plane);
    const char rl = kAxisLetters[pa.p], al = kAxisLetters[pa.q];
    std::optional<double> radius, angle;
    if (has(rl)) radius = dimension(word(rl));
    if (has(al)) angle = dimension_raw(word(al));  // degrees: no inch conversion
    if (radius || angle) {
      const V2 at = polar_point({start[pa.p], start[pa.q]}, radius, angle, modal_.incremental);
      prog[pa.p] = at.x;
      prog[pa.q] = at.y;
    }
  }
  if (!xf_.active()) {
    target = prog;
    return any;
  }
  AxisVector out = xf_.apply(prog);
  for (int a = 0; a < kAxes; ++a)
    if (std::fabs(out[a] - work[a]) < 1e-9) out[a] = work[a];
  target = out;
  return any;
}

// An arc under a transform: R scaled by the plane's larger factor ("an ellipse is not made"), the
// centre offsets I J K mapped as the path is (each axis by its own factor: unequal factors leave
// the end point off the circle, PS0020 as for any such arc). A mirror (or a negative factor) on
// one axis of the plane reverses the arc. In G16 mode an arc is given by R.
bool Executor::transform_arc_words() {
  const PlaneAxes pa = plane_axes(modal_.plane);
  if (modal_.polar && !has('R') && (has(pa.ip) || has(pa.iq)))
    alarm("PS0022", fmt::format("in polar coordinate mode (G16) give the arc's radius with R: {} and {} are not "
                                "read as polar coordinates",
                                pa.ip, pa.iq));
  xf_arc_ = xf_.active();
  if (!xf_arc_) return false;
  if (xf_.rotating && modal_.plane != xf_rotation_plane_)
    alarm("PS0144", fmt::format("an arc in the G{} plane in coordinate system rotation mode of the G{} plane",
                                modal_.plane, xf_rotation_plane_));
  if (has('R')) xf_arc_r_ = dimension(word('R')) * xf_.radius_factor(pa.p, pa.q);
  AxisVector offset{};
  if (has(pa.ip)) offset[pa.p] = dimension(word(pa.ip));
  if (has(pa.iq)) offset[pa.q] = dimension(word(pa.iq));
  const AxisVector w = xf_.apply_vector(offset);
  xf_arc_offset_ = {w[pa.p], w[pa.q]};
  return xf_.reverses(pa.p, pa.q);
}

// Canned cycle point R and Z (along Z, G17) under mirror or scaling: the programmed levels mapped
// as Z coordinates. Q and the peck distances d are not scaled (the manual).
void Executor::transformed_cycle_levels(int axis, double& r_level, double& z_level) const {
  auto z_of = [&](double z, bool forward) {
    AxisVector v{};
    v[axis] = z;
    return (forward ? xf_.apply(v) : xf_.invert(v))[axis];
  };
  const double initial = z_of(cycle_initial_[axis], false);
  const double r = !cycle_r_ ? initial : modal_.incremental ? initial + *cycle_r_ : *cycle_r_;  // cleared: 0 incremental
  const double z = !cycle_z_ ? r : modal_.incremental ? r + *cycle_z_ : *cycle_z_;
  r_level = z_of(r, true);
  z_level = z_of(z, true);
}

V2 Executor::transformed_plane_vector(V2 v) const {
  if (!xf_.active()) return v;
  const PlaneAxes pa = plane_axes(modal_.plane);
  AxisVector w{};
  w[pa.p] = v.x;
  w[pa.q] = v.y;
  w = xf_.apply_vector(w);
  return {w[pa.p], w[pa.q]};
}

AxisVector Executor::program_position() const { return xf_.active() ? xf_.invert(coords_.pos) : coords_.pos; }

}  // namespace ncurve::machine
