// The Executor's side of the cycles' expanders (CycleOutput): their moves are the block's own, made
// with linear(), thread_cut() and emit().
#pragma once
#include "machine/cycles/cycle_output.hpp"
#include "machine/executor.hpp"

namespace ncurve::machine {

struct Executor::CycleMoves : CycleOutput {
  explicit CycleMoves(Executor& x) : x(x) {}
  Executor& x;

  AxisVector position() const override { return x.coords_.pos; }
  void rapid(const AxisVector& to) override { x.linear(MoveKind::rapid, to); }
  void feed(const AxisVector& to) override { x.linear(MoveKind::line, to); }
  void thread(const AxisVector& to, double lead, double start_angle) override { x.thread_cut(to, lead, start_angle); }
  void dwell(double seconds) override {
    Move m;
    m.kind = MoveKind::dwell;
    m.start = m.end = x.coords_.pos;
    m.seconds = seconds;
    x.emit(m);
  }
  void spindle(int m) override { x.emit_event(MoveKind::spindle, m); }
  void m_code(int m) override { x.emit_event(MoveKind::m_code, m); }
  void program_stop() override { x.emit_event(MoveKind::program_stop, 0); }
  void manual_return(const AxisVector& to) override {
    if (to != x.coords_.pos) x.linear(MoveKind::rapid, to);
  }
  void returning() override { x.modal_.comp_side = 0; }  // the return to A ends a single cycle's own offset
};

}  // namespace ncurve::machine
