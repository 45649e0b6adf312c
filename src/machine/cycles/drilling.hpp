// The Executor's side of the drilling cycles' expanders (hole_cycles.hpp): their moves are the
// block's own, made with linear() and emit().
#pragma once
#include <fmt/format.h>

#include "machine/cycles/hole_cycles.hpp"
#include "machine/executor.hpp"

namespace ncurve::machine {

struct Executor::HoleOutput final : CycleOutput {
  HoleOutput(Executor& x, const drill::Hole& h) : x(x), hole(h) {}
  Executor& x;
  const drill::Hole& hole;

  AxisVector position() const override { return x.pos_; }
  void rapid(const AxisVector& to) override { x.linear(MoveKind::rapid, to); }
  void feed(const AxisVector& to) override { x.linear(MoveKind::line, to); }
  void dwell(double seconds) override {
    Move m;
    m.kind = MoveKind::dwell;
    m.start = m.end = x.pos_;
    m.seconds = seconds;
    x.emit(m);
  }
  void spindle(int m) override { x.emit_event(MoveKind::spindle, m); }
  void m_code(int m) override { x.emit_event(MoveKind::m_code, m); }
  void program_stop() override { x.emit_event(MoveKind::program_stop, 0); }
  void manual_return(const AxisVector& to) override {
    x.warn("NC2005", fmt::format("G88 stops at the bottom of the hole ({} {:.3f}) for the operator to bring the tool "
                                 "back to point R by hand (JOG or handle) and press cycle start; ncurve takes that "
                                 "as a straight rapid to R",
                                 "XYZ"[hole.axis], hole.z));
    if (to != x.pos_) x.linear(MoveKind::rapid, to);
  }
  void positioned() override {
    if (!x.m_codes_.empty()) [[unlikely]] x.cycle_m_codes();
  }
};

inline drill::Parameters drill_parameters(const MachineProfile& p) {
  return {p.peck_retract, p.peck_clearance, p.drilling};
}

}  // namespace ncurve::machine
