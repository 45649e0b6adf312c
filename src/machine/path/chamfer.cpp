// Chamfering and corner R: ,C and ,R at the end of a G01/G02/G03 block (optional-angle chamfering
// and corner R), and a lathe's 90-degree form (G01 Z_ I(C)±i; G01 X_ K(C)±k; G01 Z_/X_ R±r): the
// words, read into the request the corner stage (corner_stage.hpp) cuts at the next move.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {
constexpr double kTol = 1e-6;  // mm

const char* axis_name(int a) { return a == 0 ? "X" : a == 1 ? "Y" : a == 2 ? "Z" : "?"; }
}  // namespace

void Executor::arm_corner(const AxisVector& target) {
  const bool lathe = profile_.lathe();
  const PlaneAxes pa = plane_axes(modal_.plane);
  const Cmd* comma = nullptr;  // ,C or ,R
  for (const Cmd& c : comma_cmds_) {
    if (c.letter == 'a')
      alarm("NC9001", "the angle ,A (direct drawing dimension programming) is not supported yet", c.column);
    if (comma) alarm("PS0053", "too many address commands: one ,C or ,R in a block", c.column);
    comma = &c;
  }
  corner_words_read_ = true;
  // a lathe: C (No.3405#4 CCR = 1; not an axis) or I, K (CCR = 0) and R of the 90-degree form
  const bool ccr = lathe && profile_.chamfer_address_c;
  const Cmd* c_word = ccr && has('C') && !has_axis_[5] ? &word('C') : nullptr;
  std::optional<CornerRequest> req;
  const Cmd* given = comma;
  if (lathe && modal_.motion == 1) {
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
      const double dp = target[pa.p] - coords_.pos[pa.p], dq = target[pa.q] - coords_.pos[pa.q];
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
        if (std::fabs(target[moving] - coords_.pos[moving]) < r.amount - kTol)
          alarm("PS0055", fmt::format("missing move value in CHF/CNR: the block moves {:g} mm along {}, less than "
                                      "the {} {:g} mm",
                                      std::fabs(target[moving] - coords_.pos[moving]), axis_name(moving),
                                      r.kind == corner::Kind::round ? "corner R" : "chamfer", r.amount),
                square->column);
      }
      req = r;
    }
  }
  if (!req && !comma && c_word) given = c_word;  // C of direct drawing dimension programming (CCR = 1)
  if (!req && given) {
    if (modal_.motion == 0)
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
  if (modal_.comp_side != 0 && !comp_->offset_mode())
    alarm("PS0039", fmt::format("CHF/CNR not allowed in G41, G42: chamfering or corner R in the start-up block of {}",
                                lathe ? "tool-nose radius compensation" : "cutter compensation"),
          req->column);
  if (modal_.comp_side == 0 && comp_->offset_mode())
    alarm("PS0039", fmt::format("CHF/CNR not allowed in G41, G42: chamfering or corner R in the block that cancels {} "
                                "(G40)",
                                lathe ? "tool-nose radius compensation" : "cutter compensation"),
          req->column);
  path_corner_.arm(*req);
  corner_on_ = true;
}

void Executor::corner_block_end(bool program_end) {
  const bool words = !comma_cmds_.empty();
  const std::uint16_t column = words ? comma_cmds_.front().column : 0;
  comma_cmds_.clear();
  const bool read = corner_words_read_;
  corner_words_read_ = false;
  if (const auto at = path_corner_.take_armed())
    alarm("PS0055", "missing move value in CHF/CNR: chamfering or corner R is commanded, but the block makes no move",
          *at);
  if (words && !read)
    alarm("PS0055", "missing move value in CHF/CNR: ,C and ,R go at the end of a G01, G02 or G03 block with a move",
          column);
  if (const HeldCorner* h = path_corner_.held(); h && (program_end || h->step != result_.stats.blocks)) {
    const std::uint32_t line = h->block->line;
    path_corner_.drop_held();
    alarm("PS0052", fmt::format("code is not G01 after CHF/CNR: the block after the chamfering or corner R block of "
                                "line {} must be a G01, G02 or G03 move in the plane{}",
                                line, program_end ? "; the program ends instead" : ""));
  }
  if (!path_corner_.held()) corner_on_ = false;
}

}  // namespace ncurve::machine
