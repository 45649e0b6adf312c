// Chamfering and corner R: ,C and ,R at the end of a G01/G02/G03 block (optional-angle chamfering
// and corner R), and a lathe's 90-degree form (G01 Z_ I(C)±i; G01 X_ K(C)±k; G01 Z_/X_ R±r). The
// block's move is held until the next move is known; then both are cut back and the chamfer line or
// corner arc, which belongs to the first block, goes out between them.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {
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

[[noreturn]] void Executor::corner_alarm(const HeldCorner& h, std::string code, std::string message) const {
  throw nc::Alarm(nc::Diagnostic{nc::Severity::error, std::move(code), std::move(message),
                                 h.prog && h.block ? h.prog->span_of(*h.block, h.request.column) : span()});
}

void Executor::arm_corner(const AxisVector& target) {
  const bool lathe = profile_.lathe();
  const PlaneAxes pa = plane_axes(plane_);
  const Cmd* comma = nullptr;  // ,C or ,R
  for (const Cmd& c : comma_cmds_) {
    if (c.letter == 'a')
      alarm("NC9001", "the angle ,A (direct drawing dimension programming) is not supported yet", c.column);
    if (comma) alarm("PS0053", "too many address commands: one ,C or ,R in a block", c.column);
    comma = &c;
  }
  corner_.words_read = true;
  // a lathe: C (No.3405#4 CCR = 1; not an axis) or I, K (CCR = 0) and R of the 90-degree form
  const bool ccr = lathe && profile_.chamfer_address_c;
  const Cmd* c_word = ccr && has('C') && !has_axis_[5] ? &word('C') : nullptr;
  std::optional<CornerRequest> req;
  const Cmd* given = comma;
  if (lathe && motion_ == 1) {
    if (ccr && (has(pa.ip) || has(pa.iq)))
      alarm("PS0009", fmt::format("address {} in a G01 block: with No.3405#4 CCR = 1 chamfering takes C",
                                  has(pa.ip) ? pa.ip : pa.iq),
            word(has(pa.ip) ? pa.ip : pa.iq).column);
    const Cmd* square = nullptr;
    int count = 0;
    for (const Cmd* w : {c_word, ccr || !has(pa.ip) ? nullptr : &word(pa.ip), ccr || !has(pa.iq) ? nullptr : &word(pa.iq),
                         has('R') ? &word('R') : nullptr})
      if (w) {
        square = w;
        if (++count > 1 || comma)
          alarm("PS0053", "too many address commands: give one of chamfering (I, K or C), corner R (R) or ,C/,R",
                w->column);
      }
    if (square) {
      given = square;
      CornerRequest r;
      r.kind = square->letter == 'R' ? corner::Kind::round : corner::Kind::chamfer;
      r.column = square->column;
      const double v = dimension(*square);
      r.amount = std::fabs(v);
      const double dp = target[pa.p] - pos_[pa.p], dq = target[pa.q] - pos_[pa.q];
      const bool along_p = std::fabs(dp) > kTol, along_q = std::fabs(dq) > kTol;
      if (along_p && along_q && !ccr)
        alarm("PS0054", fmt::format("no taper allowed after CHF/CNR: {} of chamfering or corner R needs a block "
                                    "moving along {} or {} alone; this one is a taper",
                                    square->letter, axis_name(pa.p), axis_name(pa.q)),
              square->column);
      if (!along_p && !along_q)
        alarm("PS0055", fmt::format("missing move value in CHF/CNR: the block makes no move in the plane for {}{}",
                                    square->letter, std::fabs(v)),
              square->column);
      if (!(along_p && along_q)) {  // both: direct drawing dimension programming (CCR = 1), cut as ,C / ,R
        r.square = true;
        const int moving = along_p ? pa.p : pa.q;
        r.next_axis = along_p ? pa.q : pa.p;
        r.next_sign = v < 0 ? -1 : 1;
        const char wants = along_p ? pa.iq : pa.ip;  // I: chamfer toward X after a Z move; K toward Z after X
        if (square->letter != 'R' && square->letter != 'C' && square->letter != wants)
          alarm("PS0306", fmt::format("{} gives a chamfer along {}, the axis this block moves on; after a move along "
                                      "{} the chamfer is {}",
                                      square->letter, axis_name(moving), axis_name(moving), wants),
                square->column);
        if (std::fabs(target[moving] - pos_[moving]) < r.amount - kTol)
          alarm("PS0055", fmt::format("missing move value in CHF/CNR: the block moves {:g} mm along {}, less than "
                                      "the {} {:g} mm",
                                      std::fabs(target[moving] - pos_[moving]), axis_name(moving),
                                      r.kind == corner::Kind::round ? "corner R" : "chamfer", r.amount),
                square->column);
      }
      req = r;
    }
  }
  if (!req && !comma && c_word) given = c_word;  // C of direct drawing dimension programming (CCR = 1)
  if (!req && given) {
    if (motion_ == 0)
      alarm("PS0052", "chamfering and corner R are commanded at the end of a G01, G02 or G03 block; this block is "
                      "G00",
            given->column);
    CornerRequest r;
    r.kind = given->letter == 'r' || given->letter == 'R' ? corner::Kind::round : corner::Kind::chamfer;
    r.amount = std::fabs(dimension(*given));
    r.column = given->column;
    req = r;
  }
  if (!req || req->amount <= 0) return;  // ,C0: nothing to insert
  if (comp_side_ != 0 && !comp_->offset_mode())
    alarm("PS0039", fmt::format("CHF/CNR not allowed in G41, G42: chamfering or corner R in the start-up block of {}",
                                lathe ? "tool-nose radius compensation" : "cutter compensation"),
          req->column);
  if (comp_side_ == 0 && comp_->offset_mode())
    alarm("PS0039", fmt::format("CHF/CNR not allowed in G41, G42: chamfering or corner R in the block that cancels {} "
                                "(G40)",
                                lathe ? "tool-nose radius compensation" : "cutter compensation"),
          req->column);
  corner_.armed = req;
  corner_on_ = true;
}

bool Executor::corner_emit(Move& m) {
  if (corner_.held) {
    if (!m.is_motion()) {  // M codes of the held block, T of the next: after the corner
      corner_.held->events.push_back(m);
      return true;
    }
    cut_held_corner(m);
  }
  if (!corner_.armed || !m.is_motion()) return false;
  HeldCorner h;
  h.request = *corner_.armed;
  h.move = m;
  h.prog = prog_;
  h.block = block_;
  h.step = result_.stats.blocks;
  h.side = comp_side_;
  h.d = d_;
  h.lathe_offset = lathe_offset_;
  corner_.armed.reset();
  corner_.held = std::move(h);
  if (compensating()) path_comp_.note_plane_motion();  // the block has its move, put out later
  return true;
}

void Executor::cut_held_corner(Move& next) {
  HeldCorner h = std::move(*corner_.held);
  corner_.held.reset();
  const CornerRequest& rq = h.request;
  const PlaneAxes pa = plane_axes(h.move.plane);
  const std::string after = fmt::format("the block after the chamfering or corner R block of line {}", h.block->line);
  if (next.kind == MoveKind::rapid)
    alarm("PS0052", fmt::format("code is not G01 after CHF/CNR: {} must be a G01{} move; this one moves at rapid "
                                "traverse",
                                after, rq.square ? "" : ", G02 or G03"));
  if (rq.square && next.kind != MoveKind::line)
    alarm("PS0052", fmt::format("code is not G01 after CHF/CNR: {} must be a G01 move along {}; this one is an arc",
                                after, axis_name(rq.next_axis)));
  if (next.plane != h.move.plane)
    alarm("PS0051", fmt::format("missing move after CNR/CHF: {} must move in the same plane (G{}); this one changes "
                                "the plane to G{}",
                                after, h.move.plane, next.plane));
  const double dp = next.end[pa.p] - next.start[pa.p], dq = next.end[pa.q] - next.start[pa.q];
  if (next.kind == MoveKind::line && std::fabs(dp) < kTol && std::fabs(dq) < kTol)
    alarm("PS0051", fmt::format("missing move after CNR/CHF: {} makes no move in the plane", after));
  if (h.side != comp_side_)
    alarm("PS0039", fmt::format("CHF/CNR not allowed in G41, G42: {} {} {}", after,
                                comp_side_ == 0 ? "cancels" : h.side == 0 ? "starts up" : "switches the side of",
                                profile_.lathe() ? "tool-nose radius compensation" : "cutter compensation"));
  if (rq.square) {
    const int across = rq.next_axis == pa.p ? pa.q : pa.p;
    const double along = next.end[rq.next_axis] - next.start[rq.next_axis];
    if (std::fabs(next.end[across] - next.start[across]) > kTol)
      alarm("PS0052", fmt::format("code is not G01 after CHF/CNR: {} must move along {} alone, at right angles to it",
                                  after, axis_name(rq.next_axis)));
    if ((along < 0 ? -1 : 1) != rq.next_sign)
      alarm("PS0051", fmt::format("missing move after CNR/CHF: {} moves toward {}{}, but the sign of the {} says {}{}",
                                  after, along < 0 ? "-" : "+", axis_name(rq.next_axis),
                                  rq.kind == corner::Kind::round ? "corner R" : "chamfer", rq.next_sign < 0 ? "-" : "+",
                                  axis_name(rq.next_axis)));
    if (std::fabs(along) < rq.amount - kTol)
      alarm("PS0051", fmt::format("missing move after CNR/CHF: {} moves {:g} mm, less than the {} {:g} mm", after,
                                  std::fabs(along), rq.kind == corner::Kind::round ? "corner R" : "chamfer", rq.amount));
  }
  const corner::Cut cut = corner::cut_corner(path_of(h.move, pa), path_of(next, pa), rq.kind, rq.amount);
  const char* what = rq.kind == corner::Kind::round ? "corner R" : "chamfer";
  switch (cut.fault) {
    case corner::Fault::none: break;
    case corner::Fault::first_too_short:
      corner_alarm(h, "PS0055", fmt::format("missing move value in CHF/CNR: the {} {:g} mm does not fit on this block",
                                            what, rq.amount));
    case corner::Fault::second_too_short:
      if (rq.square) alarm("PS0051", fmt::format("missing move after CNR/CHF: the {} {:g} mm does not fit on {}", what,
                                                 rq.amount, after));
      corner_alarm(h, "PS0055", fmt::format("missing move value in CHF/CNR: the {} {:g} mm does not fit on the next "
                                            "block (line {})",
                                            what, rq.amount, block_ ? block_->line : 0));
    case corner::Fault::no_solution:
      corner_alarm(h, "PS0055", fmt::format("missing move value in CHF/CNR: no corner R of {:g} mm touches both this "
                                            "block and the next (line {})",
                                            rq.amount, block_ ? block_->line : 0));
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
  const int d_now = d_, offset_now = lathe_offset_;
  d_ = h.d, lathe_offset_ = h.lathe_offset;
  emit_programmed(h.move);
  if (inserted) emit_programmed(*inserted);
  for (Move& e : h.events) emit_programmed(e);
  d_ = d_now, lathe_offset_ = offset_now;
}

void Executor::corner_block_end(bool program_end) {
  const bool words = !comma_cmds_.empty();
  const std::uint16_t column = words ? comma_cmds_.front().column : 0;
  comma_cmds_.clear();
  const bool read = corner_.words_read;
  corner_.words_read = false;
  if (corner_.armed) {
    const std::uint16_t at = corner_.armed->column;
    corner_.armed.reset();
    alarm("PS0055", "missing move value in CHF/CNR: chamfering or corner R is commanded, but the block makes no move",
          at);
  }
  if (words && !read)
    alarm("PS0055", "missing move value in CHF/CNR: ,C and ,R go at the end of a G01, G02 or G03 block with a move",
          column);
  if (corner_.held && (program_end || corner_.held->step != result_.stats.blocks)) {
    const std::uint32_t line = corner_.held->block->line;
    corner_.held.reset();
    alarm("PS0052", fmt::format("code is not G01 after CHF/CNR: the block after the chamfering or corner R block of "
                                "line {} must be a G01, G02 or G03 move in the plane{}",
                                line, program_end ? "; the program ends instead" : ""));
  }
  if (!corner_.held) corner_on_ = false;
}

}  // namespace ncurve::machine
