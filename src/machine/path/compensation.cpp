#include "machine/path/compensation.hpp"

#include "machine/executor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ncurve::machine {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEps = 1e-9;

V2 plane_point(const AxisVector& v, const PlaneAxes& pa) { return {v[pa.p], v[pa.q]}; }

// The unit tangent of a line from s to e, and of an arc about c turning dir (+1 counter-clockwise) at p.
V2 line_tangent(V2 s, V2 e) { return sqrt_unit(e - s); }
V2 arc_tangent(V2 p, V2 c, int dir) { return static_cast<double>(dir) * sqrt_unit(perp(p - c)); }

}  // namespace

TipDirection tip_direction(int tip) {
  static constexpr int kX[10] = {0, 1, 1, -1, -1, 0, 1, 0, -1, 0};
  static constexpr int kZ[10] = {0, 1, -1, -1, 1, 1, 0, -1, 0, 0};
  if (tip < 0 || tip > 9) return {};
  return {kX[tip], kZ[tip]};
}

V2 RadiusCompensation::Elem::tangent_at(V2 p) const { return arc ? arc_tangent(p, c, dir) : line_tangent(s, e); }

RadiusCompensation::Elem RadiusCompensation::make(const Move& m, int side, double radius) const {
  Elem el;
  make_into(el, m, side, radius);
  return el;
}

// Sets every field of el, a slot that may hold an earlier element, for the move m; the geometry
// from the move's values at hand, not read back from the slot (as set_tangents() would).
RadiusCompensation::Elem& RadiusCompensation::make_into(Elem& el, const Move& m, int side, double radius) const {
  el.move = m;
  const bool arc = m.kind == MoveKind::arc;
  const V2 s = plane_point(m.start, pa_), e = plane_point(m.end, pa_);
  el.arc = arc;
  el.s = s;
  el.e = e;
  el.side = side;
  el.r = radius;
  el.cancel_direction.reset();
  if (arc) {
    const V2 c = {m.center[pa_.p], m.center[pa_.q]};
    const int dir = m.sweep >= 0 ? 1 : -1;
    el.c = c;
    el.R = sqrt_norm(s - c);
    el.dir = dir;
    el.ts = arc_tangent(s, c, dir);
    el.te = arc_tangent(e, c, dir);
  } else {
    el.c = {};
    el.R = 0;
    el.dir = 1;
    el.ts = el.te = line_tangent(s, e);
  }
  return el;
}

// The offset curves of a and b (a on side_a by ra, b on side_b by rb) meet nearest `near`.
std::optional<V2> RadiusCompensation::intersect(const Elem& a, int side_a, double ra, const Elem& b, int side_b,
                                                double rb, V2 near) const {
  auto offset_line = [](const Elem& el, int side, double r) {
    V2 d = el.t_start();
    return std::pair<V2, V2>{el.s + (side * r) * perp(d), d};
  };
  auto offset_radius = [](const Elem& el, int side, double r) { return el.R - side * el.dir * r; };
  geom::MeetingPoints candidates;
  if (!a.arc && !b.arc) {
    auto [p1, d1] = offset_line(a, side_a, ra);
    auto [p2, d2] = offset_line(b, side_b, rb);
    return line_line(p1, d1, p2, d2);
  }
  if (!a.arc || !b.arc) {
    const bool a_line = !a.arc;
    const Elem& ln = a_line ? a : b;
    const Elem& ci = a_line ? b : a;
    auto [p, d] = offset_line(ln, a_line ? side_a : side_b, a_line ? ra : rb);
    double R = offset_radius(ci, a_line ? side_b : side_a, a_line ? rb : ra);
    if (R <= 0) return std::nullopt;
    candidates = line_circle(p, d, ci.c, R);
  } else {
    double R1 = offset_radius(a, side_a, ra), R2 = offset_radius(b, side_b, rb);
    if (R1 <= 0 || R2 <= 0) return std::nullopt;
    candidates = circle_circle(a.c, R1, b.c, R2);
  }
  if (candidates.empty()) return std::nullopt;
  return *std::min_element(candidates.begin(), candidates.end(),
                           [&](V2 x, V2 y) { return sqrt_norm_less(x - near, y - near); });
}

RadiusCompensation::Corner RadiusCompensation::corner(const Elem& a, const Elem& b, Joint joint) const {
  const V2 P = a.e;
  const V2 t1 = a.t_end(), t2 = b.t_start();
  // The side and radius of the corner: the offset element's (the first in offset mode).
  const int s = joint == Joint::startup ? b.side : a.side;
  const double r = joint == Joint::startup ? b.r : a.r;
  const V2 v1 = (s * r) * perp(t1), v2 = (s * r) * perp(t2);
  const double cr = cross(t1, t2), dt = dot(t1, t2);
  const bool straight = std::fabs(cr) < 1e-9 && dt > 0;
  const bool inner = !straight && s * cr > 0;
  const bool acute = !straight && !inner && dt < 0;
  Corner k;
  if (joint != Joint::offset) {
    // start-up (no vector at the block's start) and cancel (none at its end): type A, and the inner
    // side of either type, a single vector perpendicular to the block in offset mode; type B the
    // intersection at an obtuse outer corner, and at an acute one the vector perpendicular to the
    // first block, then a straight move to the one perpendicular to the second
    if (!settings_.startup_type_b || straight || inner) {
      k.end_a = k.start_b = joint == Joint::startup ? P + v2 : P + v1;
      return k;
    }
    if (acute) {
      k.end_a = P + v1;
      k.start_b = P + v2;
      k.inserted.push_back(k.start_b);
      return k;
    }
  } else if (straight) {
    k.end_a = k.start_b = P + v1;
    return k;
  }
  if (!acute) {
    // inner corners, and outer corners of 90 degrees and more: the offset paths' intersection
    auto x = intersect(a, s, r, b, s, r, P + 0.5 * (v1 + v2));
    if (x) {
      k.end_a = k.start_b = *x;
      return k;
    }
    if (inner) {
      k.end_a = k.start_b = P + v1;  // flagged by the caller: no intersection
      k.inserted.push_back({std::nan(""), std::nan("")});
      return k;
    }
  }
  // outer acute corner (or an outer corner whose offset paths do not meet): the first path goes on
  // by r along its tangent, the second starts r before its start along its own
  V2 ext1 = P + v1 + r * t1;
  V2 ext2 = P + v2 - r * t2;
  k.end_a = a.arc ? P + v1 : ext1;
  if (a.arc) k.inserted.push_back(ext1);
  if (b.arc) {
    k.inserted.push_back(ext2);
    k.start_b = P + v2;
  } else {
    k.start_b = ext2;
  }
  k.inserted.push_back(k.start_b);
  return k;
}

void RadiusCompensation::check_interference(const Elem& e, V2 from, V2 to) {
  if (e.arc && e.side != 0 && (sqrt_norm_below(from - e.c, 1e-6) || sqrt_norm_below(to - e.c, 1e-6)))
    fail(e.move, "PS0038",
         fmt::format("interference in circular block: the compensated arc would {} on its centre (arc radius "
                     "{:.4f} mm, offset {:g} mm on its inner side)",
                     sqrt_norm(from - e.c) < 1e-6 ? "start" : "end", e.R, e.r));
  if (!settings_.interference_check || e.side == 0) return;
  if (!e.arc) {
    V2 prog = e.e - e.s, comp = to - from;
    if (dot(prog, comp) < 0 && sqrt_norm(prog) > kEps && sqrt_norm(comp) > kEps)
      fail(e.move, "PS0041",
             fmt::format("interference in cutter compensation: the compensated path of this block runs against "
                         "the programmed one ({:.4f} mm back); the cutter (radius {:g} mm) would gouge",
                         sqrt_norm(comp), e.r));
    return;
  }
  double R_off = e.R - e.side * e.dir * e.r;
  if (R_off <= kEps)
    fail(e.move, "PS0041",
           fmt::format("interference in cutter compensation: the arc's radius {:.4f} mm is not larger than the "
                       "offset {:g} mm on its inner side",
                       e.R, e.r));
  // the compensated arc must sweep the same way as the programmed one
  double prog = e.move.sweep;
  if (std::fabs(prog) >= kPi) return;
  double turn = cross(from - e.c, to - e.c);  // the short way from `from` to `to`: its sign
  if (std::fabs(turn) > 1e-9 * e.R * e.R && (turn > 0) != (prog > 0))
    fail(e.move, "PS0041",
         fmt::format("interference in cutter compensation: the compensated arc of this block turns against the "
                     "programmed one; the cutter (radius {:g} mm) would gouge",
                     e.r));
}

void RadiusCompensation::emit_element(const Elem& e, V2 from, V2 to, bool plain_end) {
  Move m = e.move;
  m.start = tool_full_;
  m.start[pa_.p] = from.x + tip_.x;
  m.start[pa_.q] = from.y + tip_.y;
  m.programmed_end = e.move.end;
  m.end[pa_.p] = to.x + tip_.x;
  m.end[pa_.q] = to.y + tip_.y;
  if (m.kind == MoveKind::arc) {
    m.center[pa_.p] = e.c.x + tip_.x;
    m.center[pa_.q] = e.c.y + tip_.y;
  }
  m.compensated = !plain_end || e.side != 0;
  if (m.kind == MoveKind::arc) {
    double sweep = std::atan2(cross(from - e.c, to - e.c), dot(from - e.c, to - e.c));
    const double full = std::fabs(e.move.sweep) > 2 * kPi - 1e-9;
    if (e.dir > 0) {
      while (sweep <= 1e-12) sweep += 2 * kPi;
      if (!full && sweep > 2 * kPi - 1e-9) sweep -= 2 * kPi;
    } else {
      while (sweep >= -1e-12) sweep -= 2 * kPi;
      if (!full && sweep < -2 * kPi + 1e-9) sweep += 2 * kPi;
    }
    if (full) sweep = e.dir > 0 ? 2 * kPi : -2 * kPi;
    m.sweep = sweep;
    double rs = sqrt_norm(from - e.c), re = sqrt_norm(to - e.c);
    double planar = std::fabs(sweep) * (rs + re) / 2;
    double dn = m.end[pa_.n] - m.start[pa_.n];
    double length = dn == 0 ? std::fabs(planar) : std::hypot(planar, dn);  // hypot(x, 0) is |x|, exactly
    if (e.move.length > 0) m.seconds = e.move.seconds * length / e.move.length;
    m.length = length;
  } else {
    double length = line_length(m.start.data(), m.end.data());
    if (e.move.length > 0) m.seconds = e.move.seconds * length / e.move.length;
    m.length = length;
  }
  tool_full_ = m.end;
  tool_plane_ = to;
  deliver_(m);
}

void RadiusCompensation::emit_line(const Elem& attributed_to, V2 from, V2 to, bool corner) {
  if (sqrt_norm(to - from) < kEps) return;
  Move m = attributed_to.move;
  m.kind = attributed_to.move.kind == MoveKind::rapid ? MoveKind::rapid : MoveKind::line;
  m.start = tool_full_;
  m.end = tool_full_;
  m.start[pa_.p] = from.x + tip_.x;
  m.start[pa_.q] = from.y + tip_.y;
  m.end[pa_.p] = to.x + tip_.x;
  m.end[pa_.q] = to.y + tip_.y;
  m.programmed_end = attributed_to.move.end;
  m.compensated = true;
  m.corner = corner;
  m.sweep = 0;
  m.center = {};
  double length = line_length(m.start.data(), m.end.data());
  m.seconds = attributed_to.move.length > 0 ? attributed_to.move.seconds * length / attributed_to.move.length : 0;
  m.length = length;
  m.macro_statements = 0;
  m.nc_blocks = 0;
  tool_full_ = m.end;
  tool_plane_ = to;
  deliver_(m);
}

// A move off the plane (a Z move) or an event happens where the tool is, `at` (put-out coordinates).
void RadiusCompensation::deliver_at(Move m, const AxisVector& at) {
  m.start = at;
  if (m.is_motion()) {
    m.programmed_end = m.end;
    m.end[pa_.p] = at[pa_.p];
    m.end[pa_.q] = at[pa_.q];
    m.length = line_length(m.start.data(), m.end.data());
    m.compensated = true;
  } else {
    m.end = m.start;
  }
  if (tool_) tool_ = m.end;
  else tool_full_ = m.end;
  deliver_(m);
}

void RadiusCompensation::emit_after() {
  while (!after_.empty()) {
    Move m = after_.front();
    after_.pop_front();
    deliver_at(m, tool_full_);
  }
  blocks_after_ = 0;
}

void RadiusCompensation::element(const Move& programmed, int side, double radius, std::optional<V2> cancel_direction) {
  if (!has_pending() && !offset_mode_) {
    if (side == 0) {  // no offset: the move goes from where the tool is
      Move m = programmed;
      if (tool_) {
        m.start = *tool_;
        if (m.kind != MoveKind::arc) m.length = line_length(m.start.data(), m.end.data());
        tool_.reset();
      }
      deliver_(m);
      return;
    }
    pa_ = plane_axes(programmed.plane);
    Elem& e = make_into(spare(), programmed, side, radius);
    if (e.arc)
      fail(programmed, "PS0034",
             "cutter compensation cannot start in a G02/G03 block: start it with G00 or G01 (start-up block)");
    tool_full_ = tool_ ? *tool_ : programmed.start;
    tool_.reset();
    tool_plane_ = plane_point(tool_full_, pa_) - tip_;
    set_pending(e);
    pending_start_ = tool_plane_;
    offset_mode_ = true;
    startup_pending_ = true;
    return;
  }
  Elem& b = make_into(spare(), programmed, side, radius);  // built beside the pending element, not copied
  b.cancel_direction = cancel_direction;
  if (side == 0 && b.arc)
    fail(programmed, "PS0034",
           "cutter compensation cannot be cancelled in a G02/G03 block: cancel it with G00 or G01");
  if (!has_pending() && shift_) {  // type C: the start-up block shifts the tool, then b runs in offset mode
    const Elem by = make(*shift_, side, radius);
    shift_.reset();
    if (side != 0) {
      const V2 start = b.s + (b.side * b.r) * perp(b.t_start());
      emit_line(by, tool_plane_, start, false);
      emit_after();
      set_pending(b);
      pending_start_ = start;
      return;
    }
    emit_after();
  }
  if (!has_pending()) {  // offset mode with the last element already ended (read-ahead lost)
    if (lost_) warn_lost(b);
    set_pending(b);
    pending_start_ = tool_plane_;
    if (side == 0) {
      emit_element(b, tool_plane_, b.e - tip_, true);
      pending_ = -1;
      offset_mode_ = false;
    }
    return;
  }
  Elem& a = pending();
  Joint joint = startup_pending_ ? Joint::startup : side == 0 ? Joint::cancel : Joint::offset;
  const bool cancel_ij = side == 0 && cancel_direction;
  const bool side_change = !cancel_ij && joint == Joint::offset && a.side != 0 && side != a.side;
  Corner k = cancel_ij || side_change ? Corner{} : corner(a, b, joint);  // built in place: not copied
  if (cancel_ij) {
    // G40 with I J: the vector at the end of the last block points as if the next block ran along (I, J)
    Elem ghost = a;
    ghost.arc = false;
    ghost.s = a.e;
    ghost.e = a.e + *cancel_direction;
    ghost.set_tangents();
    k = corner(a, ghost, Joint::offset);
    k.inserted.clear();
    k.start_b = k.end_a;
  } else if (side_change) {
    // G41 <-> G42: the vector at the end of the first block on its side meets the second block's
    // offset path on the new side where they intersect, else both end perpendicular
    auto x = intersect(a, a.side, a.r, b, b.side, b.r, a.e);
    V2 v1 = (a.side * a.r) * perp(a.t_end()), v2 = (b.side * b.r) * perp(b.t_start());
    if (x && sqrt_norm(*x - a.e) <= 2 * std::max(a.r, b.r) + kEps) {
      k.end_a = k.start_b = *x;
    } else {
      k.end_a = a.e + v1;
      k.start_b = a.e + v2;
      k.inserted.push_back(k.start_b);
    }
  }
  if (!k.inserted.empty() && std::isnan(k.inserted.front().x))
    fail(a.move, "PS0033",
           fmt::format("no intersection for cutter compensation: the offset paths of this block and the one before "
                       "(radius {:g} mm) do not meet at their inner corner",
                       a.r));
  // the start-up block runs from no vector to its end vector: the check is for offset mode
  if (joint != Joint::startup) check_interference(a, pending_start_, k.end_a);
  if (joint == Joint::startup) startup_pending_ = false;
  emit_element(a, pending_start_, k.end_a);
  emit_after();
  for (V2 p : k.inserted) emit_line(a, tool_plane_, p);
  if (side == 0) {
    // the cancel block goes to its programmed end without a vector
    emit_element(b, tool_plane_, b.e - tip_, true);
    pending_ = -1;
    offset_mode_ = false;
    return;
  }
  set_pending(b);
  pending_start_ = k.start_b;
}

void RadiusCompensation::fail(const Move& at, const std::string& code, const std::string& message) {
  // the tool stops at the end of the block before: what is still buffered is not executed
  pending_ = -1;
  shift_.reset();
  after_.clear();
  offset_mode_ = false;
  alarm_(at, code, message);
  throw std::logic_error("the alarm callback returned");
}

void RadiusCompensation::other(const Move& m) {
  if (has_pending() || shift_) after_.push_back(m);
  else if (offset_mode_ || tool_) deliver_at(m, tool_ ? *tool_ : tool_full_);
  else {
    Move x = m;
    deliver_(x);
  }
}

void RadiusCompensation::block_without_motion(const Move& at) {
  if (!has_pending()) return;
  if (++blocks_after_ <= settings_.blocks_without_motion) return;
  // the read-ahead cannot see past these blocks: the last element ends with its perpendicular vector
  Elem& a = pending();
  V2 end = a.e + (a.side * a.r) * perp(a.t_end());
  check_interference(a, pending_start_, end);
  emit_element(a, pending_start_, end);
  lost_ = Lost{a, at, blocks_after_};
  pending_ = -1;
  emit_after();
}

// The read-ahead was lost before `next`: the tool starts it from the perpendicular vector at the end of
// the block before, where it should start on next's offset path. How far off, across next's path:
// less than the radius is an overcut, more an undercut.
void RadiusCompensation::warn_lost(const Elem& next) {
  const Lost l = *lost_;
  lost_.reset();
  double across = next.arc ? std::fabs(sqrt_norm(tool_plane_ - next.c) - next.R)
                           : std::fabs(cross(tool_plane_ - next.s, next.t_start()));
  double error = across - next.r;
  std::string effect = std::fabs(error) < 1e-6 ? "no overcut or undercut"
                       : error < 0          ? fmt::format("an overcut of {:.4f} mm", -error)
                                            : fmt::format("an undercut of {:.4f} mm", error);
  warn_(l.at, "NC2101",
        fmt::format("cutter compensation: {} blocks without motion in the offset plane after line {} are more than "
                    "the control reads ahead past ({}); the vector at the end of line {} is left perpendicular and "
                    "line {} starts from there: {} at its start",
                    l.blocks, l.element.move.line, settings_.blocks_without_motion, l.element.move.line,
                    next.move.line, effect));
}

// The pending element ends with its vector perpendicular at its end; what was read after it goes out.
void RadiusCompensation::end_perpendicular() {
  if (has_pending()) {
    Elem& a = pending();
    V2 end = a.e + (a.side * a.r) * perp(a.t_end());
    check_interference(a, pending_start_, end);
    emit_element(a, pending_start_, end);
    pending_ = -1;
  }
  emit_after();
}

void RadiusCompensation::startup_without_motion(const Move& at) {
  if (!settings_.startup_type_c || offset_mode() || shift_) return;
  pa_ = plane_axes(at.plane);
  tool_full_ = tool_ ? *tool_ : at.start;
  tool_.reset();
  tool_plane_ = plane_point(tool_full_, pa_) - tip_;
  shift_ = at;
  offset_mode_ = true;
  lost_.reset();
}

void RadiusCompensation::cancel_without_motion(const Move& at) {
  if (!has_pending() && !offset_mode_) return;
  const bool tool_moved = !shift_;
  shift_.reset();
  end_perpendicular();
  offset_mode_ = false;
  startup_pending_ = false;
  lost_.reset();
  if (!tool_moved) return;  // type C before its shift: the tool never left the programmed point
  if (settings_.startup_type_c) {
    Elem by = make(at, 0, 0);
    emit_line(by, tool_plane_, plane_point(at.end, pa_) - tip_, false);
  } else {
    tool_ = tool_full_;
  }
}

void RadiusCompensation::move_frame(const AxisVector& delta) {
  auto moved = [&](AxisVector v) {
    for (int a = 0; a < kAxes; ++a) v[a] += delta[a];
    return v;
  };
  if (shift_) {  // type C waiting for its next move: nothing has moved yet
    emit_after();
    shift_->start = moved(shift_->start);
    shift_->end = moved(shift_->end);
    tool_full_ = moved(tool_full_);
    tool_plane_ = plane_point(tool_full_, pa_) - tip_;
    return;
  }
  if (offset_mode_ || has_pending()) {
    end_perpendicular();
    offset_mode_ = false;
    startup_pending_ = false;
    lost_.reset();
    tool_ = tool_full_;
  }
  if (tool_) tool_ = moved(*tool_);
}

void RadiusCompensation::cancel_at_end() {
  if (!has_pending() && !offset_mode_) return;
  shift_.reset();
  if (has_pending()) {
    Elem a = pending();
    pending_ = -1;
    if (!startup_pending_) check_interference(a, pending_start_, a.e - tip_);
    emit_element(a, pending_start_, a.e - tip_, true);
  }
  emit_after();
  lost_.reset();
  offset_mode_ = false;
  startup_pending_ = false;
  tool_ = tool_full_;  // where the tool is (the programmed point, or a vector left by a lost read-ahead)
}

void RadiusCompensation::finish() {
  shift_.reset();
  if (has_pending()) {
    Elem a = pending();
    pending_ = -1;
    V2 end = a.e + (a.side * a.r) * perp(a.t_end());
    emit_element(a, pending_start_, end);
  }
  emit_after();
}

}  // namespace ncurve::machine
