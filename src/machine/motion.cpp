// NC words that move the machine: coordinates, lines, arcs, reference returns.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/restore.hpp"
#include "machine/g_codes.hpp"
#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;

// axis_index() in line: it runs for every word of every block that moves.
int axis_of(char letter) {
  switch (letter) {
    case 'X': return 0;
    case 'Y': return 1;
    case 'Z': return 2;
    case 'A': return 3;
    case 'B': return 4;
    case 'C': return 5;
    default: return -1;
  }
}

// Whether an arc from (sx, sy) to (ex, ey) about its centre, of less than a quarter turn, stays in
// one quadrant with both ends clear of the axes by a millionth of a radian and more: it passes no
// quadrant point, and the angles' test, whose rounding is far smaller than that, would find none.
bool inside_one_quadrant(double sx, double sy, double ex, double ey, double sweep) {
  auto clear = [](double x, double y) { return std::fabs(x) > 1e-6 * std::fabs(y) && std::fabs(y) > 1e-6 * std::fabs(x); };
  return std::fabs(sweep) < 1.5 && clear(sx, sy) && clear(ex, ey) && (sx > 0) == (ex > 0) && (sy > 0) == (ey > 0);
}

}  // namespace

PlaneAxes plane_axes(int plane) {
  // a table, not a switch: called for every move of a compensated path
  static constexpr PlaneAxes kAxesOf[3] = {{0, 1, 2, 'I', 'J'}, {2, 0, 1, 'K', 'I'}, {1, 2, 0, 'J', 'K'}};
  return kAxesOf[plane == 18 ? 1 : plane == 19 ? 2 : 0];
}

const char* to_string(MoveKind k) {
  switch (k) {
    case MoveKind::rapid: return "rapid";
    case MoveKind::line: return "line";
    case MoveKind::arc: return "arc";
    case MoveKind::dwell: return "dwell";
    case MoveKind::tool_change: return "tool_change";
    case MoveKind::spindle: return "spindle";
    case MoveKind::coolant: return "coolant";
    case MoveKind::program_stop: return "program_stop";
    case MoveKind::program_end: return "program_end";
    case MoveKind::m_code: return "m_code";
  }
  return "?";
}

void Executor::set_origin() {
  const AxisVector delta = coords_.select(modal_.work_index);
  if (comp_) comp_->move_frame(delta);
}

// Reads axis words into target (work coordinates, mm). Returns whether any axis word was given.
bool Executor::axis_target(AxisVector& target, bool force_absolute) {
  if (developed_hook_) [[unlikely]] return developed_axis_target(target);  // G12.1, G07.1
  if (xf_hook_ && !force_absolute) return transformed_axis_target(target);  // G16, G51.1, G51, G68
  const bool lathe = profile_.lathe();
  const bool system_a = lathe && profile_.gcode_system == 'A';
  bool any = false;
  if (rolls_) roll_word_.fill(false);
  for (const Cmd& c : cmds_) {
    int a = axis_of(c.letter);
    bool incremental = modal_.incremental && !force_absolute;
    if (system_a && (c.letter == 'U' || c.letter == 'V' || c.letter == 'W')) {
      a = c.letter == 'U' ? 0 : c.letter == 'V' ? 1 : 2;
      incremental = true;
      if (!has_axis_[a]) a = -1;
    } else if (a >= 0 && !has_axis_[a]) {
      if (lathe && c.letter == 'C' && profile_.chamfer_address_c) continue;  // chamfering (chamfer.cpp)
      if (lathe && c.letter == 'A' && g76_reads_a_) continue;
      if (lathe && c.letter == 'A' && profile_.chamfer_address_c)
        alarm("NC9001", "the angle A of direct drawing dimension programming is not supported yet", c.column);
      alarm("PS0009", fmt::format("address {}: this machine has no {} axis{}", c.letter, c.letter,
                                  lathe && c.letter == 'C' ? " (chamfering takes I or K; C with No.3405#4 CCR = 1)" : ""),
            c.column);
    } else if (a < 0) {
      if (c.letter == 'U' || c.letter == 'V' || c.letter == 'W' || c.letter == 'E')
        alarm("PS0009", fmt::format("address {} has no meaning on this machine", c.letter), c.column);
      continue;
    }
    if (a < 0) continue;
    double v = rotary_[a] ? angle(c) : dimension(c);
    if (a == 0 && lathe && profile_.diameter_x) v /= 2;
    target[a] = incremental ? target[a] + v : v;
    if (rolls_ && !incremental && rotary_[a] && profile_.rotary[a].roll_over) roll_word_[a] = true, roll_value_[a] = v;
    any = true;
  }
  return any;
}

void Executor::motion(const AxisVector& target) {
  bool swap = false;  // a mirror image reverses arcs: G02 and G03 swap
  if (xf_hook_ && (modal_.motion == 2 || modal_.motion == 3)) swap = transform_arc_words();
  switch (modal_.motion) {
    case 0: linear(MoveKind::rapid, target); break;
    case 1: linear(MoveKind::line, target); break;
    case 2: arc(target, !swap); break;
    case 3: arc(target, swap); break;
    case 33: thread_block(target); break;  // G33: a mill's, or G32 of lathe systems B/C (threading.cpp)
    case 60: single_direction(target); break;  // G60 modal (No.5431#0 MDL = 1)
    default: lathe_motion(target); break;  // G32/G90/G92/G94 (lathe_cycles.cpp)
  }
  xf_arc_ = false;
}

void Executor::emit(Move& m) {
  count_block_move();
  m.program = prog_ ? prog_->number : -1;
  m.file = prog_ ? prog_->file.get() : nullptr;
  m.line = block_ ? block_->line : 0;
  m.feed_per_rev = modal_.feed_per_rev || m.threading;
  m.spindle = speed_;
  m.d_offset = d_;
  m.exact_stop = modal_.exact_stop || exact_stop_once_;
  m.lookahead = modal_.look_ahead || modal_.exact_stop_code == 611;
  m.macro_statements = statements_since_;
  m.nc_blocks = nc_blocks_since_;
  statements_since_ = nc_blocks_since_ = 0;
  if (shape_moves_) {  // a cycle reading its shape: the motions are kept, not made
    if (m.is_motion()) shape_moves_->push_back(m);
    return;
  }
  if (modal_.css && speed_ > 0 && (m.kind == MoveKind::line || m.kind == MoveKind::arc)) [[unlikely]]
    check_css_spindle_limit(m);
  if (profile_.lathe() && !developed_ && (m.kind == MoveKind::line || m.kind == MoveKind::arc)) check_centre_line(m);
  path_corner_.on_move(m);
}

CornerContext Executor::corner_context() const {
  return {prog_, block_, result_.stats.blocks, modal_.comp_side, d_, lathe_offset_};
}

void Executor::set_offset_numbers(int d, int lathe_offset) { d_ = d, lathe_offset_ = lathe_offset; }

void Executor::move_held() {
  if (compensating()) path_comp_.note_plane_motion();
}

OffsetOfMove Executor::offset_of_move(const PlaneAxes& pa) const {
  OffsetOfMove o;
  o.mirrored = xf_on_ && xf_.reverses(pa.p, pa.q);
  if (profile_.lathe()) {
    o.radius = nose_radius();
    o.tip = developed_ ? V2{} : nose_tip();  // G12.1, G07.1: the tool's centre
  } else {
    o.radius = radius_offset(d_);
  }
  return o;
}

// Rapid axes move independently: the slowest axis sets the time (an axis that does not move, none).
double Executor::rapid_seconds(const AxisVector& from, const AxisVector& to) const {
  double slowest = 0;
  for (int a = 0; a < kAxes; ++a) {
    const double d = std::fabs(to[a] - from[a]);
    if (d != 0 && profile_.rapid_rate[a] > 0) slowest = std::max(slowest, d / profile_.rapid_rate[a]);
  }
  return slowest * 60.0;
}

AxisVector Executor::machine_shift() const {
  AxisVector shift{};
  for (int a = 0; a < kAxes; ++a) shift[a] = coords_.origin[a] + coords_.tool_shift[a];
  return shift;
}

V2 Executor::nose_tip_now() const { return developed_ ? V2{} : nose_tip(); }

// After each NC block in offset mode: a G40 (or G41/G42 from cancel mode) without motion in the
// plane ends (starts) the offset by the start-up type's rule; any other block without such motion
// is one the read-ahead must look past.
void Executor::end_of_block_compensation(bool g40, bool g41) {
  if (!path_comp_.block_moved_in_plane()) {
    Move at;
    at.kind = modal_.motion == 0 ? MoveKind::rapid : MoveKind::line;
    at.plane = static_cast<std::uint8_t>(modal_.plane);
    at.start = at.end = coords_.pos;
    at.feed = feed_;
    at.feed_per_rev = modal_.feed_per_rev;
    at.spindle = speed_;
    at.file = prog_ ? prog_->file.get() : nullptr;
    at.line = block_ ? block_->line : 0;
    at.program = prog_ ? prog_->number : -1;
    path_comp_.block_without_plane_motion(at, g40, g41);
  }
  path_comp_.end_block();
  cancel_direction_.reset();
}

// The imaginary tool tip from the nose centre, in the G18 plane (Z, X as a radius), for the
// active offset set's tip number and nose radius.
V2 Executor::nose_tip() const {
  auto it = lathe_offsets_.find(lathe_offset_);
  if (it == lathe_offsets_.end()) return {};
  const TipDirection d = tip_direction(static_cast<int>(it->second.tip));
  const double r = nose_radius();
  return {d.z * r, d.x * r};
}

// The active offset set's nose radius, geometry plus wear.
double Executor::nose_radius() const {
  auto it = lathe_offsets_.find(lathe_offset_);
  return it == lathe_offsets_.end() ? 0.0 : it->second.r + it->second.r_wear;
}

void Executor::emit_event(MoveKind kind, int code) {
  Move m;
  m.kind = kind;
  m.code = code;
  m.start = m.end = coords_.pos;
  m.plane = static_cast<std::uint8_t>(modal_.plane);
  emit(m);
}

void Executor::linear(MoveKind kind, const AxisVector& target) {
  Move m;
  linear_into(m, kind, target);
}

void Executor::linear_into(Move& m, MoveKind kind, const AxisVector& target) {
  m.kind = kind;
  m.start = coords_.pos;
  m.end = target;
  m.plane = static_cast<std::uint8_t>(modal_.plane);
  m.length = line_length(coords_.pos.data(), target.data());
  if (kind == MoveKind::line) {
    if (feed_ <= 0) alarm("PS0011", "feed rate is zero: give F before or in the first G01/G02/G03 block");
    if (tool_changed_) [[unlikely]] check_tool_length(target[2]);
    m.feed = feed_;
    const double fed = extra_axes_ ? combined_length(coords_.pos, target, m.length) : m.length;  // F on every axis
    m.seconds = feed_seconds(fed, coords_.pos[0], target[0]);
    clamp_cutting_feed(m, fed);
  } else {
    m.feed = 0;
    m.seconds = rapid_seconds(coords_.pos, target);
  }
  coords_.pos = target;
  if (rolls_) wrap_rotary();
  emit(m);
}

void Executor::arc(const AxisVector& target, bool clockwise) {
  if (feed_ <= 0) alarm("PS0011", "feed rate is zero: give F before or in the first G01/G02/G03 block");
  if (tool_changed_) [[unlikely]] check_tool_length(target[2]);
  const PlaneAxes pa = plane_axes(modal_.plane);
  if (profile_.lathe() && modal_.plane != 18 && !developed_) alarm("PS0021", "a lathe cuts arcs in the G18 (ZX) plane only");
  const double sp = coords_.pos[pa.p], sq = coords_.pos[pa.q];
  const double ep = target[pa.p], eq = target[pa.q];
  const double tol = profile_.increment * 0.5 + 1e-9;
  double cp, cq;
  bool full = false;
  if (has('R')) {
    double r = xf_arc_ ? xf_arc_r_ : dimension(word('R'));  // scaled under G51
    double dx = ep - sp, dy = eq - sq;
    double d = std::hypot(dx, dy);
    if (d < tol) {
      // R with the end point at the start point: FANUC makes no move
      coords_.pos = target;
      return;
    }
    if (r == 0) alarm("PS0023", "arc radius R is zero", word('R').column);
    double half = d / 2;
    if (half > std::fabs(r) + profile_.arc_radius_tolerance)  // no circle of radius R: the centre is the midpoint
      warn_once("NC2016",
                fmt::format("arc radius R{} is smaller than half the distance to the end point ({:.4f} {} against "
                            "{:.4f}): the control puts the centre on the chord's midpoint and cuts a half circle of "
                            "that radius (PS0023 is for R0 only)",
                            word('R').value, std::fabs(r) / (modal_.inch ? 25.4 : 1), modal_.inch ? "in" : "mm",
                            half / (modal_.inch ? 25.4 : 1)),
                word('R').column);
    double h = std::sqrt(std::max(0.0, r * r - half * half));
    // centre left of the chord for G03 with R > 0, right for G02
    double sign = (clockwise ? -1.0 : 1.0) * (r > 0 ? 1.0 : -1.0);
    cp = sp + dx / 2 - sign * h * dy / d;
    cq = sq + dy / 2 + sign * h * dx / d;
  } else {
    double off_p = 0, off_q = 0;
    if (!has(pa.ip) && !has(pa.iq)) {  // No.3403#5 CIR
      if (profile_.arc_without_centre_alarm)
        alarm("PS0022", "G02/G03 needs R or the centre offsets (I, J, K) of the plane (No.3403#5 CIR = 1)");
      warn_once("NC2015", "G02/G03 without R or the centre offsets (I, J, K) of the plane: the control moves to "
                          "the end point by linear interpolation (No.3403#5 CIR = 0)");
      return linear(MoveKind::line, target);
    }
    auto offset = [&](char letter, int axis) {
      if (!has(letter)) return 0.0;
      double v = dimension(word(letter));  // I on a lathe is a radius value
      (void)axis;
      return v;
    };
    off_p = xf_arc_ ? xf_arc_offset_.x : offset(pa.ip, pa.p);  // transformed under G51.1/G51/G68
    off_q = xf_arc_ ? xf_arc_offset_.y : offset(pa.iq, pa.q);
    cp = sp + off_p;
    cq = sq + off_q;
    full = std::hypot(ep - sp, eq - sq) < tol;
  }
  double rs = std::hypot(sp - cp, sq - cq);
  double re = std::hypot(ep - cp, eq - cq);
  if (rs < tol) alarm("PS0023", "arc radius is zero");
  if (std::fabs(re - rs) > profile_.arc_radius_tolerance)
    alarm("PS0020", fmt::format("arc end point is off the circle: start radius {:.4f} mm, end radius {:.4f} mm "
                                "(more than the No.3410 limit {:.4f} mm)",
                                rs, re, profile_.arc_radius_tolerance));
  double a0 = std::atan2(sq - cq, sp - cp);
  double a1 = std::atan2(eq - cq, ep - cp);
  double sweep = a1 - a0;
  if (full) sweep = clockwise ? -kTwoPi : kTwoPi;
  else if (clockwise) {
    while (sweep >= 0) sweep -= kTwoPi;
  } else {
    while (sweep <= 0) sweep += kTwoPi;
  }
  Move m;
  m.kind = MoveKind::arc;
  m.clockwise = clockwise;
  m.plane = static_cast<std::uint8_t>(modal_.plane);
  m.start = coords_.pos;
  m.end = target;
  m.center = {coords_.pos[0], coords_.pos[1], coords_.pos[2]};
  m.center[pa.p] = cp;
  m.center[pa.q] = cq;
  m.center[pa.n] = coords_.pos[pa.n];
  m.sweep = sweep;
  double planar = std::fabs(sweep) * (rs + re) / 2;
  double dn = target[pa.n] - coords_.pos[pa.n];
  m.length = dn == 0 ? std::fabs(planar) : std::hypot(planar, dn);  // hypot(x, 0) is |x|, exactly
  m.feed = feed_;
  // Helical interpolation: F is the feed along the arc in the plane, the linear axis following at
  // F x its travel / the arc's length (the manuals' helical interpolation; parameter HTG = 0, factory)
  m.seconds = arc_feed_seconds(m, planar);
  clamp_cutting_feed(m, planar);
  // extents: the quadrant points the arc passes (in G12.1/G07.1 the machine's moves give them)
  const bool no_quadrant_point = inside_one_quadrant(sp - cp, sq - cq, ep - cp, eq - cq, sweep);
  for (int k = 0; k < 4 && !developed_ && !no_quadrant_point; ++k) {
    double ang = k * std::numbers::pi / 2;
    double rel = std::remainder(ang - a0, kTwoPi);
    double along = sweep > 0 ? (rel < 0 ? rel + kTwoPi : rel) : (rel > 0 ? kTwoPi - rel : -rel);
    if (along < std::fabs(sweep)) {
      AxisVector p = coords_.pos;
      p[pa.p] = cp + rs * std::cos(ang);
      p[pa.q] = cq + rs * std::sin(ang);
      path_stats_.note_extent(p);
    }
  }
  coords_.pos = target;
  if (rolls_) wrap_rotary();
  emit(m);
}

void Executor::dwell() {
  double seconds = 0;
  std::uint16_t column = 0;
  if (has('P')) {
    seconds = integer(word('P'), "P of G04 (milliseconds)") / 1000.0;
    column = word('P').column;
  } else if (has('X') || has('U')) {
    const Cmd& c = has('X') ? word('X') : word('U');
    double v = c.value;
    if (c.literal && !c.decimal_point && !profile_.decimal_calculator) v *= 0.001;  // X1000 = 1 s
    seconds = v;
    column = c.column;
  }
  if (seconds < 0) alarm("PS0006", "a dwell time takes no minus sign", column);
  Move m;
  m.kind = MoveKind::dwell;
  m.start = m.end = coords_.pos;
  m.seconds = seconds;
  emit(m);
}

void Executor::reference_return(int g) {
  int point = 0;
  if (g == 300) {
    point = has('P') ? integer(word('P'), "P of G30") - 1 : 1;
    if (point < 1 || point > 3) alarm("PS0046", "G30 P must be 2, 3 or 4", word('P').column);
  }
  if (g == 301 && !profile_.floating_reference)
    alarm("NC9001", "G30.1 (floating reference position return) needs the floating reference position, which the "
                    "operator sets on the control (No.1244): give it in the profile as [reference_points] floating");
  AxisVector mid = coords_.pos;
  bool any = axis_target(mid);
  if (!any) return;
  if (rolls_) roll_over(mid);
  remember_intermediate(mid);  // for G29 (reference_moves.cpp)
  const AxisVector from = coords_.pos;
  // in offset mode the vector is cancelled at the intermediate point and restored at the next move
  const base::RestoreOnExit<bool> restore(comp_suspended_);
  comp_suspended_ = true;
  {
    const base::RestoreOnExit<bool> restore_drop(comp_drop_);
    comp_drop_ = names_plane_axis();
    linear(MoveKind::rapid, mid);
  }
  AxisVector ref = coords_.pos;
  for (const Cmd& c : cmds_) {
    int a = axis_index(c.letter);
    if (profile_.lathe() && profile_.gcode_system == 'A') {
      if (c.letter == 'U') a = 0;
      if (c.letter == 'W') a = 2;
    }
    if (a < 0 || !has_axis_[a]) continue;
    ref[a] = (g == 301 ? *profile_.floating_reference : profile_.reference_points[point])[a] - coords_.origin[a] - coords_.tool_shift[a];
  }
  const AxisVector reached = coords_.pos;  // the intermediate point as the move left the tool
  linear(MoveKind::rapid, ref);
  check_return_direction(g, g == 301 ? -1 : point, from, reached, coords_.pos);
}

void Executor::machine_coordinate_move() {
  if (modal_.incremental) return;  // G53 is ignored under G91, as on FANUC
  AxisVector target = coords_.pos;
  AxisVector machine{};
  for (int a = 0; a < kAxes; ++a) machine[a] = coords_.pos[a] + coords_.origin[a] + coords_.tool_shift[a];
  AxisVector given = machine;
  if (!axis_target(given, true)) return;
  for (int a = 0; a < kAxes; ++a) target[a] = given[a] - coords_.origin[a] - coords_.tool_shift[a];
  for (int a = 0; a < kAxes; ++a)
    if (given[a] == machine[a]) target[a] = coords_.pos[a];
  // G53 in offset mode: the vector is cancelled, restored at the next move
  const base::RestoreOnExit<bool> restore(comp_suspended_), restore_drop(comp_drop_);
  comp_suspended_ = true;
  comp_drop_ = names_plane_axis();
  linear(MoveKind::rapid, target);
}

void Executor::set_coordinate_system(int g) {
  AxisVector given = coords_.pos;
  if (g == 520) {  // G52: local coordinate system, absolute offsets from the work zero
    AxisVector zero{};
    AxisVector offs = zero;
    bool any = false;
    for (const Cmd& c : cmds_) {
      int a = axis_index(c.letter);
      if (a < 0 || !has_axis_[a]) continue;
      double v = dimension(c);
      if (a == 0 && profile_.lathe() && profile_.diameter_x) v /= 2;
      offs[a] = v;
      any = true;
    }
    if (!any) return;
    for (const Cmd& c : cmds_) {
      int a = axis_index(c.letter);
      if (a >= 0 && has_axis_[a]) coords_.local[a] = offs[a];
    }
    set_origin();
    return;
  }
  if (g == 500 && !has('X') && !has('Z') && !has('U') && !has('W')) return;
  // G92 (G50 on a system A lathe): the current point gets the given coordinates
  if (!axis_target(given)) return;
  comp_->move_frame(coords_.set_current(given, block_axes()));
}

}  // namespace ncurve::machine
