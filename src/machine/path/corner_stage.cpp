#include "machine/path/corner_stage.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "machine/interpreter.hpp"

namespace ncurve::machine {

namespace {
using geom::V2;
constexpr double kTol = 1e-6;  // mm

corner::Path path_of(const Move& m, const PlaneAxes& pa) {
  corner::Path p;
  p.arc = m.kind == MoveKind::arc;
  p.s = {m.start[pa.p], m.start[pa.q]};
  p.e = {m.end[pa.p], m.end[pa.q]};
  p.c = {m.center[pa.p], m.center[pa.q]};
  p.sweep = m.sweep;
  return p;
}

AxisVector lerp(const AxisVector& a, const AxisVector& b, double t) {
  AxisVector r{};
  for (int i = 0; i < kAxes; ++i) r[i] = a[i] + t * (b[i] - a[i]);
  return r;
}

void set_length(Move& m, const PlaneAxes& pa) {
  const double old = m.length;
  if (m.kind == MoveKind::arc) {
    const double r = std::hypot(m.start[pa.p] - m.center[pa.p], m.start[pa.q] - m.center[pa.q]);
    m.length = std::hypot(std::fabs(m.sweep) * r, m.end[pa.n] - m.start[pa.n]);
  } else {
    m.length = line_length(m.start.data(), m.end.data());
  }
  if (old > 0) m.seconds *= m.length / old;
}

// The first block ends at `at`, `part` of its way (axes off the plane move in proportion).
void cut_end(Move& m, const PlaneAxes& pa, V2 at, double part) {
  m.end = lerp(m.start, m.end, part);
  m.end[pa.p] = at.x, m.end[pa.q] = at.y;
  if (m.kind == MoveKind::arc) m.sweep *= part;
  set_length(m, pa);
}

// The next block starts at `at`, `part` of its way.
void cut_start(Move& m, const PlaneAxes& pa, V2 at, double part) {
  m.start = lerp(m.start, m.end, part);
  m.start[pa.p] = at.x, m.start[pa.q] = at.y;
  if (m.kind == MoveKind::arc) {
    m.sweep *= 1 - part;
    m.center[pa.n] = m.start[pa.n];
  }
  set_length(m, pa);
}

const char* axis_name(int a) { return a == 0 ? "X" : a == 1 ? "Y" : a == 2 ? "Z" : "?"; }
}  // namespace

nc::Span CornerStage::here() const {
  const CornerContext ctx = control_.corner_context();
  return ctx.prog && ctx.block ? ctx.prog->span_of(*ctx.block) : nc::Span{};
}

void CornerStage::fail(const nc::Span& where, const std::string& code, const std::string& message) const {
  alarm_(where, code, message);
  throw nc::Alarm(nc::Diagnostic{nc::Severity::error, code, message, where});
}

void CornerStage::hold_or_cut(Move m) {
  if (held_) {
    if (!m.is_motion()) {  // M codes of the held block, T of the next: after the corner
      held_->events.push_back(m);
      return;
    }
    cut_held_corner(m);
  }
  if (!armed_ || !m.is_motion()) return next_->on_move(m);
  const CornerContext ctx = control_.corner_context();
  HeldCorner h;
  h.request = *armed_;
  h.move = m;
  if (ctx.prog && ctx.block) h.block = ctx.prog->span_of(*ctx.block);
  h.step = ctx.step;
  h.side = ctx.side;
  h.d = ctx.d;
  h.lathe_offset = ctx.lathe_offset;
  armed_.reset();
  held_ = std::move(h);
  control_.move_held();
}

void CornerStage::cut_held_corner(Move& next) {
  HeldCorner h = std::move(*held_);
  held_.reset();
  const CornerContext ctx = control_.corner_context();
  const CornerRequest& rq = h.request;
  const PlaneAxes pa = plane_axes(h.move.plane);
  const std::string after = fmt::format("the block after the chamfering or corner R block of line {}", h.block->line);
  if (next.kind == MoveKind::rapid)
    fail(here(), "PS0052",
         fmt::format("code is not G01 after CHF/CNR: {} must be a G01{} move; this one moves at rapid "
                     "traverse",
                     after, rq.square ? "" : ", G02 or G03"));
  if (rq.square && next.kind != MoveKind::line)
    fail(here(), "PS0052",
         fmt::format("code is not G01 after CHF/CNR: {} must be a G01 move along {}; this one is an arc", after,
                     axis_name(rq.next_axis)));
  if (next.plane != h.move.plane)
    fail(here(), "PS0051",
         fmt::format("missing move after CNR/CHF: {} must move in the same plane (G{}); this one changes "
                     "the plane to G{}",
                     after, h.move.plane, next.plane));
  const double dp = next.end[pa.p] - next.start[pa.p], dq = next.end[pa.q] - next.start[pa.q];
  if (next.kind == MoveKind::line && std::fabs(dp) < kTol && std::fabs(dq) < kTol)
    fail(here(), "PS0051", fmt::format("missing move after CNR/CHF: {} makes no move in the plane", after));
  if (h.side != ctx.side)
    fail(here(), "PS0039",
         fmt::format("CHF/CNR not allowed in G41, G42: {} {} {}", after,
                     ctx.side == 0 ? "cancels"
                     : h.side == 0 ? "starts up"
                                   : "switches the side of",
                     lathe_ ? "tool-nose radius compensation" : "cutter compensation"));
  if (rq.square) {
    const int across = rq.next_axis == pa.p ? pa.q : pa.p;
    const double along = next.end[rq.next_axis] - next.start[rq.next_axis];
    if (std::fabs(next.end[across] - next.start[across]) > kTol)
      fail(here(), "PS0052",
           fmt::format("code is not G01 after CHF/CNR: {} must move along {} alone, at right angles to it", after,
                       axis_name(rq.next_axis)));
    if ((along < 0 ? -1 : 1) != rq.next_sign)
      fail(here(), "PS0051",
           fmt::format("missing move after CNR/CHF: {} moves toward {}{}, but the sign of the {} says {}{}", after,
                       along < 0 ? "-" : "+", axis_name(rq.next_axis),
                       rq.kind == corner::Kind::round ? "corner R" : "chamfer", rq.next_sign < 0 ? "-" : "+",
                       axis_name(rq.next_axis)));
    if (std::fabs(along) < rq.amount - kTol)
      fail(here(), "PS0051",
           fmt::format("missing move after CNR/CHF: {} moves {:g} mm, less than the {} {:g} mm", after,
                       std::fabs(along), rq.kind == corner::Kind::round ? "corner R" : "chamfer", rq.amount));
  }
  const corner::Cut cut = corner::cut_corner(path_of(h.move, pa), path_of(next, pa), rq.kind, rq.amount);
  const char* what = rq.kind == corner::Kind::round ? "corner R" : "chamfer";
  const nc::Span held_at =
      h.block ? nc::Span{h.block->file, h.block->line, rq.column ? rq.column : h.block->column, 1} : here();
  switch (cut.fault) {
    case corner::Fault::none: break;
    case corner::Fault::first_too_short:
      fail(held_at, "PS0055",
           fmt::format("missing move value in CHF/CNR: the {} {:g} mm does not fit on this block", what, rq.amount));
    case corner::Fault::second_too_short:
      if (rq.square)
        fail(here(), "PS0051",
             fmt::format("missing move after CNR/CHF: the {} {:g} mm does not fit on {}", what, rq.amount, after));
      fail(held_at, "PS0055",
           fmt::format("missing move value in CHF/CNR: the {} {:g} mm does not fit on the next "
                       "block (line {})",
                       what, rq.amount, ctx.block ? ctx.block->line : 0));
    case corner::Fault::no_solution:
      fail(held_at, "PS0055",
           fmt::format("missing move value in CHF/CNR: no corner R of {:g} mm touches both this "
                       "block and the next (line {})",
                       rq.amount, ctx.block ? ctx.block->line : 0));
  }
  std::optional<Move> inserted;
  if (!cut.none) {
    const double rate = h.move.length > 0 ? h.move.seconds / h.move.length : 0;  // s/mm of the block
    cut_end(h.move, pa, cut.a_end, cut.a_part);
    cut_start(next, pa, cut.b_start, cut.b_part);
    Move& m = inserted.emplace(h.move);  // the first block's feed, spindle, line
    m.start = h.move.end;
    m.end = next.start;
    m.macro_statements = m.nc_blocks = 0;
    if (rq.kind == corner::Kind::round) {
      m.kind = MoveKind::arc;
      m.clockwise = !cut.ccw;
      m.center = {m.start[0], m.start[1], m.start[2]};
      m.center[pa.p] = cut.centre.x, m.center[pa.q] = cut.centre.y;
      const V2 u{m.start[pa.p] - cut.centre.x, m.start[pa.q] - cut.centre.y};
      const V2 v{m.end[pa.p] - cut.centre.x, m.end[pa.q] - cut.centre.y};
      double sweep = std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
      if (cut.ccw && sweep < 0) sweep += 2 * std::numbers::pi;
      if (!cut.ccw && sweep > 0) sweep -= 2 * std::numbers::pi;
      m.sweep = sweep;
    } else {
      m.kind = MoveKind::line;
      m.sweep = 0;
    }
    m.length = 0;
    set_length(m, pa);
    m.seconds = rate * m.length;
  }
  // out as the first block's: its D and lathe offset, even if the next block changes them
  control_.set_offset_numbers(h.d, h.lathe_offset);
  next_->on_move(h.move);
  if (inserted) next_->on_move(*inserted);
  for (Move& e : h.events) next_->on_move(e);
  control_.set_offset_numbers(ctx.d, ctx.lathe_offset);
}

}  // namespace ncurve::machine
