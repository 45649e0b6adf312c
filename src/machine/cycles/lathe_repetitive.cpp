// Multiple repetitive cycles of a FANUC lathe: G70 finishing, G71/G72 stock removal, G73 pattern
// repeating, G74 end face peck drilling, G75 outer/inner diameter grooving (G72..G77 in G code
// system C). The finishing shape, blocks N(ns)..N(nf), is read by running its blocks with emit()
// keeping the motions; stock_removal.cpp turns it into passes. docs/lathe-cycles-mrc.md.
#include <fmt/format.h>

#include <cmath>

#include "base/restore.hpp"
#include "machine/executor.hpp"
#include "machine/cycles/stock_removal.hpp"

namespace ncurve::machine {

namespace {
const char* cycle_name(int g) {
  switch (g) {
    case 700: return "finishing cycle";
    case 710: return "stock removal in turning";
    case 720: return "stock removal in facing";
    case 730: return "pattern repeating";
    case 740: return "end face peck drilling";
    case 750: return "outer/inner diameter grooving";
    default: return "multiple repetitive cycle";
  }
}

// G code of cycle g (system A number, x10) as the program writes it.
std::string written(int g, char system) { return fmt::format("G{}", g / 10 + (system == 'C' ? 2 : 0)); }

mrc::P2 p2(const AxisVector& v) { return {v[0], v[2]}; }

// The shape's motions as elements.
mrc::Shape shape_of(const std::vector<Move>& moves, std::size_t from) {
  mrc::Shape s;
  for (std::size_t i = from; i < moves.size(); ++i) {
    const Move& m = moves[i];
    mrc::Element e;
    e.start = p2(m.start), e.end = p2(m.end);
    e.rapid = m.kind == MoveKind::rapid;
    if (m.kind == MoveKind::arc) {
      e.arc = true;
      e.centre = {m.center[0], m.center[2]};
      e.sweep = m.sweep;
    }
    s.push_back(e);
  }
  return s;
}

[[noreturn]] void alarm_at(const Move& at, const std::string& code, const std::string& message) {
  throw nc::Alarm(nc::Diagnostic{nc::Severity::error, code, message, nc::Span{at.file, at.line, 1, 1}});
}
}  // namespace

int Executor::repetitive_code(int g) const {
  if (profile_.gcode_system == 'C') return g >= 720 && g <= 780 && g % 10 == 0 ? g - 20 : 0;
  return g >= 700 && g <= 760 && g % 10 == 0 ? g : 0;
}

double Executor::increments(const Cmd& c) const {
  const double v = integer(c, "P/Q of G74/G75 (least input increments)") / (modal_.inch ? per_unit_inch_ : per_unit_mm_);
  return std::fabs(modal_.inch ? v * 25.4 : v);
}

bool Executor::repetitive_cycle(int g) {
  try {
    return repetitive_cycle_path(g);
  } catch (const mrc::PathTooLong&) {
    alarm("NC9000", fmt::format("{} would make more than {} moves (its depth of cut, peck or travel between cuts is "
                                "a few increments over a long way): ncurve stops it rather than fill the memory",
                                written(g, profile_.gcode_system), mrc::kMaxCyclePath));
  }
}

bool Executor::repetitive_cycle_path(int g) {
  std::uint16_t column = 0;
  for (const Cmd& c : cmds_)
    if (c.letter == 'G' && repetitive_code(static_cast<int>(std::lround(c.value * 10))) == g) column = c.column;
  const std::string code = written(g, profile_.gcode_system);
  if (shape_moves_) alarm("PS0325", fmt::format("{} cannot be commanded inside a finishing shape", code), column);
  if (g == 740 || g == 750) return peck_cycle(g);
  const bool p = has('P'), q = has('Q');
  if (!p && !q && g != 700 && !profile_.series10_format) {  // the first block of the two-block format
    if (g == 730) {
      if (has('U')) mrc_relief_x_ = dimension(word('U'));
      if (has('W')) mrc_relief_z_ = dimension(word('W'));
      if (has('R')) mrc_divisions_ = word('R').value;
    } else {
      const char depth = g == 710 ? 'U' : 'W';
      if (has(depth)) mrc_depth_ = dimension(word(depth));
      if (has('R')) mrc_escape_ = dimension(word('R'));
    }
    return false;
  }
  if (!p || !q)
    alarm("PS0061", fmt::format("{} ({}) needs both P (first block of the shape, N ns) and Q (last, N nf)", code,
                                cycle_name(g)),
          column);
  if (g == 700) {
    finishing_cycle(shape_range(g));
    return true;
  }
  // Under tool-nose radius compensation the vector is cancelled at the start point, the roughing
  // follows the compensated shape and its moves are made as computed; the next move starts up again.
  const base::RestoreOnExit restore_side(modal_.comp_side);
  return g == 730 ? pattern_repeating_cycle() : stock_removal_cycle(g);
}

// The blocks N(ns)..N(nf) of the program holding the cycle block.
Executor::ShapeRange Executor::shape_range(int g) {
  ShapeRange r;
  r.ns = integer(word('P'), "P (sequence number ns)");
  r.nf = integer(word('Q'), "Q (sequence number nf)");
  const std::string code = written(g, profile_.gcode_system);
  r.first = prog_->find_sequence(r.ns);
  if (r.first < 0)
    alarm("PS0063", fmt::format("{} P{}: no block N{} in this program (the shape must be in the program of the "
                                "cycle)", code, r.ns, r.ns),
          word('P').column);
  r.last = -1;
  for (std::int32_t i = r.first; r.last < 0;) {
    const nc::Program::Piece piece = prog_->piece_of(i);
    if (!piece.piece) break;
    for (; i < piece.end && r.last < 0; ++i)
      if (piece.piece->blocks[i - piece.first].sequence == r.nf) r.last = i;
  }
  if (r.last < 0)
    alarm("PS0063", fmt::format("{} Q{}: no block N{} at or after N{} in this program", code, r.nf, r.nf, r.ns),
          word('Q').column);
  return r;
}

// What the manual allows in a shape: motion G00..G03 with their words, dwell, absolute/incremental
// and feed modes, F S T and M codes other than calls and ends.
void Executor::check_shape_block(const nc::Block& b, bool first, int g) {
  if (b.kind != nc::Statement::nc || (b.block_skip && profile_.block_skip)) return;
  const std::string code = written(g, profile_.gcode_system);
  bool move_code = false, arc_code = false;
  for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
    const nc::Word& word = unit_->words[w];
    if (word.letter != 'G' || !word.literal) continue;
    const int v = static_cast<int>(std::lround(word.value * 10));
    const bool mode = profile_.gcode_system == 'A' ? (v == 980 || v == 990) : (v == 900 || v == 910 || v == 940 || v == 950);
    if (v == 0 || v == 10) move_code = true;
    else if (v == 20 || v == 30) arc_code = true;
    else if (v == 400 || v == 410 || v == 420)
      alarm("NC9001", fmt::format("G{} inside the finishing shape of {} is not supported yet: give G41/G42 before "
                                  "the cycle", v / 10, code),
            word.column);
    else if (!(v == 40 || v == 960 || v == 970 || mode))
      alarm("PS0325", fmt::format("G{}{} cannot be commanded in the finishing shape of {}: only G00..G03, G04 and "
                                  "the modes of feed and dimension", v / 10, v % 10 ? fmt::format(".{}", v % 10) : "",
                                  code),
            word.column);
  }
  const bool arc_block = arc_code || (!move_code && (modal_.motion == 2 || modal_.motion == 3));
  for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
    const nc::Word& word = unit_->words[w];
    const int m = static_cast<int>(std::lround(word.value));
    if (word.letter == 'M' && word.literal && (m == 98 || m == 99 || m == 2 || m == 30))
      alarm("PS0325", fmt::format("M{} (a call, return or end) cannot be commanded in the finishing shape of {}", m,
                                  code),
            word.column);
    if ((word.letter == 'C' && !has_axis_[5]) || (word.letter == 'R' && !arc_block))
      alarm("NC9001", fmt::format("chamfering and corner rounding ({} in a G01 block) in the finishing shape of {} "
                                  "are not supported yet", word.letter, code),
            word.column);
  }
  if (first && !move_code)
    alarm("PS0065", fmt::format("the first block of the finishing shape (N{}) must command G00 or G01", b.sequence),
          b.column);
}

// Runs blocks N(ns)..N(nf): kept as a shape (keep) or made as moves (G70). The block, its words and,
// for a kept shape, the modal state are as before; the program goes on after the cycle block.
std::vector<Move> Executor::walk_shape(const ShapeRange& r, int g, bool keep) {
  const std::vector<Cmd> cmds = cmds_;
  const auto have = have_;
  const auto slot = slot_;
  const std::vector<int> g_codes = g_codes_, m_codes = m_codes_;
  const std::int32_t block = block_index_;
  const nc::Program* prog = prog_;
  const AxisVector pos = coords_.pos, tool_shift = coords_.tool_shift;
  const int motion = modal_.motion, tool = tool_, lathe_offset = lathe_offset_, last_m = last_m_;
  const bool incremental = modal_.incremental, feed_per_rev = modal_.feed_per_rev, css = modal_.css;
  const double feed = feed_, speed = speed_;
  const std::size_t depth = frames_.size();
  std::int32_t resume = frames_.back().pc;
  if (resume >= r.first && resume <= r.last) resume = r.last + 1;  // the shape right after the cycle block

  std::vector<Move> moves;
  if (keep) shape_moves_ = &moves;
  struct Stop {  // shape_moves_ must not outlive `moves`, even on an alarm
    std::vector<Move>*& p;
    bool& read;
    ~Stop() { p = nullptr, read = false; }
  } stop{shape_moves_, shape_read_};
  shape_read_ = keep;  // (an observer sees the cycle block make the roughing, not the shape's blocks)
  frames_.back().pc = r.first;
  for (bool first = true;;) {
    const std::int32_t at = frames_.back().pc;
    if (result_.stats.blocks >= options_.max_steps)
      alarm("NC9000", fmt::format("program stopped after {} blocks (--max-steps) in the finishing shape", options_.max_steps));
    if (select_block(prog_, at)) {  // an alarm names this block
      check_shape_block(*block_, first, g);
      if (block_->kind == nc::Statement::nc) first = false;
    }
    step();
    if (frames_.size() != depth)
      alarm("PS0325", fmt::format("a macro or subprogram call cannot be commanded in the finishing shape of {}",
                                  written(g, profile_.gcode_system)));
    if (finished_) alarm("PS0325", "the program ended inside the finishing shape");
    if (at == r.last) break;
    const std::int32_t next = frames_.back().pc;
    if (next < r.first || next > r.last)
      alarm("PS0325", fmt::format("a jump out of the finishing shape N{}..N{}", r.ns, r.nf));
  }
  if (keep) {
    coords_.pos = pos, coords_.tool_shift = tool_shift;
    modal_.motion = motion, tool_ = tool, lathe_offset_ = lathe_offset, last_m_ = last_m;
    modal_.incremental = incremental, modal_.feed_per_rev = feed_per_rev, modal_.css = css;
    feed_ = feed, speed_ = speed;
  }
  cmds_ = cmds, have_ = have, slot_ = slot, g_codes_ = g_codes, m_codes_ = m_codes;
  select_block(prog, block);
  frames_.back().pc = resume;
  return moves;
}

// G70 P(ns) Q(nf): the shape as programmed, its F S T in effect, then back to the start by rapid.
void Executor::finishing_cycle(const ShapeRange& r) {
  const AxisVector start = coords_.pos;
  walk_shape(r, 700, false);
  linear(MoveKind::rapid, start);
}

// G71 / G72: roughing in passes of Δd parallel to Z (G71) or X (G72), then along the shape moved by
// the finishing allowance; back to the start point.
bool Executor::stock_removal_cycle(int g) {
  const bool facing = g == 720;
  const std::string code = written(g, profile_.gcode_system);
  const double diameter = profile_.diameter_x ? 2.0 : 1.0;
  const double du = has('U') ? dimension(word('U')) / diameter : 0.0, dw = has('W') ? dimension(word('W')) : 0.0;
  if (profile_.series10_format && has('D')) mrc_depth_ = std::fabs(as_written(word('D').value, true, false)) * (modal_.inch ? 25.4 : 1);
  if (!(mrc_depth_ > 0))
    alarm("PS0062", fmt::format("{}: the depth of cut Δd is {} (give it by {} in the first block, or No.5132)", code,
                                mrc_depth_, profile_.series10_format ? 'D' : facing ? 'W' : 'U'));
  if (mrc_escape_ < 0) alarm("PS0062", fmt::format("{}: the escaping amount e is negative", code));
  const ShapeRange range = shape_range(g);
  const std::uint16_t pcol = word('P').column;
  // the first block names the type: the infeed axis alone is type I, both axes type II
  bool infeed_axis = false, other_axis = false;
  const nc::Program::Piece first = prog_->piece_of(range.first);
  const nc::Block& nb = first.piece->blocks[range.first - first.first];
  for (std::uint32_t w = nb.words_begin; nb.kind == nc::Statement::nc && w < nb.words_end; ++w) {
    const char l = first.piece->words[w].letter;
    const bool x = l == 'X' || (l == 'U' && profile_.gcode_system == 'A');
    const bool z = l == 'Z' || (l == 'W' && profile_.gcode_system == 'A');
    if (x || z) (x != facing ? infeed_axis : other_axis) = true;
  }
  const AxisVector start = coords_.pos;
  const std::vector<Move> moves = walk_shape(range, g, true);
  if (!infeed_axis || moves.empty())
    alarm("PS0065", fmt::format("{}: the first block of the shape (N{}) must move {} (and {} too for type II)", code,
                                range.ns, facing ? 'Z' : 'X', facing ? 'X' : 'Z'),
          pcol);
  const bool pockets = other_axis;
  mrc::Shape shape = shape_of(moves, 1);
  if (shape.empty()) alarm("PS0065", fmt::format("{}: the shape N{}..N{} has no block after the first", code, range.ns, range.nf), pcol);
  mrc::Shape cut = facing ? mrc::transposed(shape) : shape;
  // the alarm list names the plane's axes: PS0064 the first (Z of G18's ZpXp plane), PS0329 the
  // second (X), whichever of them the cycle cuts along
  const char* cut_alarm = facing ? "PS0329" : "PS0064";
  const char* depth_alarm = facing ? "PS0064" : "PS0329";
  if (const int i = mrc::first_reversal(cut, 1); i >= 0)
    alarm_at(moves[i + 1], cut_alarm,
             fmt::format("{}: the finishing shape is not monotone along {} (this block turns back); both types need it",
                         code, facing ? 'X' : 'Z'));
  if (!pockets)
    if (const int i = mrc::first_reversal(cut, 0); i >= 0)
      alarm_at(moves[i + 1], depth_alarm,
               fmt::format("{}: the finishing shape is not monotone along {} (this block turns back): type I needs "
                           "it; give both {} and {} in the first block (N{}) for type II",
                           code, facing ? 'Z' : 'X', facing ? 'Z' : 'X', facing ? 'X' : 'Z', range.ns));
  if (modal_.comp_side != 0 || comp_->offset_mode()) shape = shape_of(nose_compensated(moves), 1);
  mrc::Roughing r;
  r.start = p2(start);
  r.shape = mrc::translated(shape, {du, dw});
  if (facing) r.start = mrc::transposed(r.start), r.shape = mrc::transposed(r.shape);
  r.depth = mrc_depth_;
  r.escape = mrc_escape_;
  r.rapid_infeed = moves.front().kind == MoveKind::rapid;
  r.pockets = pockets;
  r.finish_pass = pockets ? !profile_.mrc_no_finish_type2 : !profile_.mrc_no_finish_type1;
  emit_cycle_path(mrc::stock_removal(r), facing);
  return true;
}

// The shape as the imaginary tip follows it under tool-nose radius compensation: the first block
// starts up from the cycle's start point (type A), every corner as in offset mode, the last block
// ends with its vector perpendicular. The compensation in force is cancelled at the start point and
// stays off for the cycle's own moves.
std::vector<Move> Executor::nose_compensated(const std::vector<Move>& shape) {
  int side = modal_.comp_side;
  comp_->cancel_at_end();
  modal_.comp_side = 0;
  double radius = nose_radius();
  if (radius < 0) radius = -radius, side = -side;
  std::vector<Move> out;
  if (side == 0 || radius == 0) return shape;
  RadiusCompensation nose = radius_compensation({}, [&](Move& m) { out.push_back(m); });
  nose.set_tip(nose_tip());
  for (const Move& m : shape)
    if (m.is_motion()) nose.element(m, side, radius);
  nose.finish();
  return out;
}

// G73: the shape repeated d times, moved by the relief falling to the finishing allowance.
bool Executor::pattern_repeating_cycle() {
  const std::string code = written(730, profile_.gcode_system);
  const double diameter = profile_.diameter_x ? 2.0 : 1.0;
  const double du = has('U') ? dimension(word('U')) / diameter : 0.0, dw = has('W') ? dimension(word('W')) : 0.0;
  if (profile_.series10_format) {
    if (has('I')) mrc_relief_x_ = dimension(word('I'));
    if (has('K')) mrc_relief_z_ = dimension(word('K'));
    if (has('D')) mrc_divisions_ = word('D').value;
  }
  if (!(mrc_divisions_ >= 1) || mrc_divisions_ != std::floor(mrc_divisions_) || mrc_divisions_ > 99999)
    alarm("PS0321", fmt::format("{}: the number of divisions d is {} (a whole number from 1; {} in the first block, "
                                "or No.5137)", code, mrc_divisions_, profile_.series10_format ? 'D' : 'R'));
  const ShapeRange range = shape_range(730);
  const AxisVector start = coords_.pos;
  const std::vector<Move> moves = walk_shape(range, 730, true);
  if (moves.empty()) alarm("PS0065", fmt::format("{}: the shape N{}..N{} makes no move", code, range.ns, range.nf));
  mrc::Pattern p;
  p.start = p2(start);
  p.shape = shape_of(modal_.comp_side != 0 || comp_->offset_mode() ? nose_compensated(moves) : moves, 0);
  p.relief = {mrc_relief_x_, mrc_relief_z_};
  p.allowance = {du, dw};
  p.count = static_cast<int>(mrc_divisions_);
  emit_cycle_path(mrc::pattern_repeating(p), false);
  return true;
}

// G74 (pecks along Z, steps along X) and G75 (pecks along X, steps along Z).
bool Executor::peck_cycle(int g) {
  const std::string code = written(g, profile_.gcode_system);
  const bool one_block = profile_.series10_format;
  const bool target = has('X') || has('Z') || (profile_.gcode_system == 'A' && (has('U') || has('W')));
  if (!target) {  // G74 R(e): the return amount
    if (!one_block && has('R')) mrc_return_ = dimension(word('R'));
    return false;
  }
  const char di = one_block ? 'I' : 'P', dk = one_block ? 'K' : 'Q';
  auto amount = [&](char l) {
    if (!has(l)) return 0.0;
    if (!one_block && word(l).value < 0)
      alarm("PS0320", fmt::format("{}: {}{:g}: Δi (P) and Δk (Q), the travel and the depth of cut, take no minus sign",
                                  code, l, word(l).value),
            word(l).column);
    return one_block ? std::fabs(dimension(word(l))) : increments(word(l));
  };
  const double step_x = amount(di), step_z = amount(dk);  // Δi along X (radius), Δk along Z
  double relief = 0;
  if (one_block ? has('D') : has('R'))
    relief = one_block ? as_written(word('D').value, true, false) * (modal_.inch ? 25.4 : 1) : dimension(word('R'));
  if (mrc_return_ < 0) alarm("PS0062", fmt::format("{}: the return amount e is negative", code));
  AxisVector end = coords_.pos;
  axis_target(end);
  const bool moves_x = std::fabs(end[0] - coords_.pos[0]) > 1e-9, moves_z = std::fabs(end[2] - coords_.pos[2]) > 1e-9;
  if (moves_x && !(step_x > 0))
    alarm("PS0319", fmt::format("{}: X moves but Δi ({}) is 0: give the {} along X", code, di,
                                g == 740 ? "travel between cuts" : "depth of each cut"));
  if (moves_z && !(step_z > 0))
    alarm("PS0319", fmt::format("{}: Z moves but Δk ({}) is 0: give the {} along Z", code, dk,
                                g == 740 ? "depth of each cut" : "travel between cuts"));
  if ((g == 740 ? moves_x : moves_z) && relief < 0)
    alarm("PS0318", fmt::format("{}: the relief Δd at the bottom is negative; its direction follows the travel", code));
  mrc::Pecking k;
  k.start = p2(coords_.pos), k.end = p2(end);
  k.back = mrc_return_;
  k.relief = relief;
  if (g == 740) {
    k.shift = step_x, k.peck = step_z;
  } else {
    k.start = mrc::transposed(k.start), k.end = mrc::transposed(k.end);
    k.shift = step_z, k.peck = step_x;
  }
  // Tool-nose radius compensation is not applied to G74/G75 (as to G76): the vector in force is
  // cancelled at the start point, the pecks are made as programmed, the next move starts up again.
  const base::RestoreOnExit restore_side(modal_.comp_side);
  if (compensating()) {
    comp_->cancel_at_end();
    modal_.comp_side = 0;
  }
  emit_cycle_path(mrc::peck_cycle(k), g == 750);
  return true;
}

// Each step of a cycle's path as a move of the cycle block, at the F in force.
void Executor::emit_cycle_path(const std::vector<mrc::Step>& path, bool transposed) {
  for (mrc::Step s : path) {
    if (transposed) s.end = mrc::transposed(s.end), s.centre = mrc::transposed(s.centre), s.sweep = -s.sweep;
    AxisVector target = coords_.pos;
    target[0] = s.end.x, target[2] = s.end.y;
    if (!s.arc) {
      linear(s.rapid ? MoveKind::rapid : MoveKind::line, target);
      continue;
    }
    if (feed_ <= 0) alarm("PS0011", "feed rate is zero: give F before or in the cycle block");
    Move m;
    m.kind = MoveKind::arc;
    m.clockwise = s.sweep < 0;
    m.plane = 18;
    m.start = coords_.pos;
    m.end = target;
    m.center = {s.centre.x, coords_.pos[1], s.centre.y};
    m.sweep = s.sweep;
    const double rs = std::hypot(coords_.pos[0] - s.centre.x, coords_.pos[2] - s.centre.y);
    m.length = std::fabs(s.sweep) * rs;
    m.feed = feed_;
    m.seconds = arc_feed_seconds(m, m.length);
    clamp_cutting_feed(m, m.length);
    coords_.pos = target;
    emit(m);
  }
}

}  // namespace ncurve::machine
