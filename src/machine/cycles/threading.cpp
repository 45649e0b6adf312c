// Lathe threading: G32 (G33 on G-code systems B and C) thread cuts and the data of the G76 multiple
// threading cycle (its passes: turning.cpp), as the FANUC 0i-TF / 30i-B lathe operator's manuals
// describe them. A thread cut is fed per revolution at the lead F, the feed held
// at 100 %; each is marked (Move::threading) with the spindle angle it starts at.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/restore.hpp"
#include "machine/cycles/cycle_moves.hpp"
#include "machine/cycles/turning.hpp"

namespace ncurve::machine {

namespace {
bool valid_tool_angle(int a) { return a == 0 || a == 29 || a == 30 || a == 55 || a == 60 || a == 80; }
}  // namespace

double Executor::increments(const Cmd& c, const char* what) const {
  const double per_unit = modal_.inch ? per_unit_inch_ : per_unit_mm_;
  return integer(c, what) / per_unit * (modal_.inch ? 25.4 : 1.0);
}

double Executor::thread_start_angle() {
  if (!has('Q')) return 0;
  const Cmd& q = word('Q');
  const int v = integer(q, "Q (threading start angle, 0.001 degree)");
  if (v < 0) alarm("PS0006", fmt::format("Q{} (threading start angle) takes no minus sign", v), q.column);
  if (v > 360000)
    alarm("PS0003",
          fmt::format("Q{} (threading start angle) is outside 0..360000 (0.001 degree; the manual names no alarm "
                      "for it, ncurve stops here)",
                      v),
          q.column);
  return v / 1000.0;
}

// One thread cut from the current position: a line fed at the lead per spindle revolution. The lead
// is along the longer axis (Z for a taper of 45 degrees or less), which sets the time.
void Executor::thread_cut(const AxisVector& to, double lead, double angle) {
  if (lead <= 0) alarm("PS0011", "thread lead is zero: give F (the lead, mm per revolution) in the threading block");
  Move m;
  m.kind = MoveKind::line;
  m.start = coords_.pos;
  m.end = to;
  m.plane = static_cast<std::uint8_t>(modal_.plane);
  m.length = line_length(coords_.pos.data(), to.data());
  m.feed = lead;
  m.threading = true;
  m.thread_start = angle < 0 ? -1 : static_cast<std::int32_t>(std::lround(angle * 1000));
  double along = 0;
  for (int a = 0; a < 3; ++a) along = std::max(along, std::fabs(to[a] - coords_.pos[a]));
  m.seconds = along / lead * 60.0 * minutes_per_rev(coords_.pos[0], to[0]);
  coords_.pos = to;
  emit(m);
}

// G32 X(U) Z(W) F Q: one cut; a G32 block right after another continues its thread (no wait for the
// spindle's one-rotation signal, Q not read).
void Executor::thread_block(const AxisVector& target) {
  if (compensating())
    alarm("NC9001", fmt::format("threading (G{}) under {} radius compensation is not supported yet: cancel "
                                "it with G40 before the thread",
                                modal_.motion, profile_.lathe() ? "tool-nose" : "cutter"));
  const bool continues = thread_block_ != 0 && thread_block_ + 1 == result_.stats.blocks;
  double angle = thread_start_angle();
  if (continues) angle = -1;
  thread_cut(target, feed_, angle);
  thread_block_ = result_.stats.blocks;
}

// G76. FANUC 0i format (No.0001#1 FCV = 0): G76 P(m)(r)(a) Q(dmin) R(d); then
// G76 X(U) Z(W) R(i) P(k) Q(dd) F(L). Series 10/11 format (FCV = 1): G76 X(U) Z(W) I(i) K(k) D(dd)
// F(L) A(a) P(1) Q(start angle), m, r, dmin and d from the parameters.
void Executor::multiple_threading_cycle() {
  const bool system_a = profile_.gcode_system == 'A';
  const bool axes = has('X') || has('Z') || (system_a && (has('U') || has('W')));
  const bool fcv = profile_.series10_format;
  if (!fcv && !axes) {  // the first block: modal data that rewrite No.5142, 5130, 5143, 5140, 5141
    if (has('P')) {
      const Cmd& p = word('P');
      const int v = integer(p, "P of G76 (m r a: finishing passes, chamfer, tool angle, two digits each)");
      if (v < 0) alarm("PS0006", fmt::format("P{} of G76: m r a takes no minus sign", v), p.column);
      if (v > 999999)
        alarm("PS0003", fmt::format("P{} of G76 has more than six digits m r a (finishing passes, chamfer in 0.1 "
                                    "leads, tool angle, two digits each)", v), p.column);
      if (!valid_tool_angle(v % 100))
        alarm("PS0315", fmt::format("tool nose angle a = {} in G76 P{:06}: it must be 80, 60, 55, 30, 29 or 0",
                                    v % 100, v), p.column);
      g76_finish_count_ = v / 10000;
      thread_chamfer_ = v / 100 % 100;
      g76_tool_angle_ = v % 100;
    }
    if (has('Q')) g76_min_depth_ = std::fabs(increments(word('Q'), "Q of G76 (minimum depth of cut, increments)"));
    if (has('R')) g76_allowance_ = std::fabs(dimension(word('R')));
    return;
  }
  if (!axes) return;  // Series 10/11 format without an end point: nothing to cut
  AxisVector end = coords_.pos;
  g76_reads_a_ = fcv;  // A is the tool angle there, not an axis
  axis_target(end);
  g76_reads_a_ = false;
  double taper = 0, height = 0, first = 0, angle = 0;
  if (!fcv) {
    if (has('R')) taper = dimension(word('R'));
    if (has('P')) height = increments(word('P'), "P of G76 (thread height k, increments)");
    if (has('Q')) first = increments(word('Q'), "Q of G76 (depth of the first cut, increments)");
  } else {
    if (has('I')) taper = dimension(word('I'));
    if (has('K')) height = dimension(word('K'));
    if (has('D')) first = dimension(word('D'));
    if (has('A')) {
      const int a = integer(word('A'), "A of G76 (tool nose angle)");
      if (!valid_tool_angle(a))
        alarm("PS0315", fmt::format("tool nose angle A{} in G76: it must be 80, 60, 55, 30, 29 or 0", a),
              word('A').column);
      g76_tool_angle_ = a;
    }
    if (has('P') && integer(word('P'), "P of G76 (cutting method)") != 1)
      alarm("NC9001", fmt::format("G76 P{} (cutting method) is not supported yet: P1, single edge at a constant "
                                  "cutting amount, is", word('P').value), word('P').column);
    angle = thread_start_angle();
  }
  const char* k_word = fcv ? "K" : "P";
  const char* d_word = fcv ? "D" : "Q";
  if (height <= 0 || first <= 0)
    alarm("PS0317", fmt::format("G76 needs a thread height {}(k) and a depth of the first cut {}(dd) above zero "
                                "(k = {:g} mm, dd = {:g} mm)", k_word, d_word, height, first));
  if (g76_min_depth_ > height)
    alarm("PS0316", fmt::format("the minimum depth of cut of G76 ({:g} mm: Q of the first block or No.5140) is "
                                "greater than the thread height {}(k) ({:g} mm)", g76_min_depth_, k_word, height));
  turn::MultipleThreading c;
  c.end = end;
  c.taper = taper;
  c.height = height;
  c.first = first;
  c.min_depth = g76_min_depth_;
  c.allowance = g76_allowance_;
  c.finish_count = g76_finish_count_;
  c.tool_angle = g76_tool_angle_;
  c.thread = {feed_, thread_chamfer_, profile_.thread_chamfer_angle};
  c.start_angle = angle;
  std::vector<double> depths;
  try {
    depths = turn::thread_depths(c);
  } catch (const turn::TooManyPasses&) {
    alarm("NC9000", fmt::format("G76 would make more than 100000 passes (first depth {:g} mm, thread height {:g} "
                                "mm): give a larger first depth of cut or a minimum depth of cut (Q of the first "
                                "block, No.5140)", first, height));
  }
  const base::RestoreOnExit restore_side(modal_.comp_side);
  if (compensating()) {  // threading is not compensated: the vector is cancelled at A
    comp_->cancel_at_end();
    modal_.comp_side = 0;
  }
  CycleMoves out(*this);
  turn::multiple_threading(c, depths, out);
}

}  // namespace ncurve::machine
