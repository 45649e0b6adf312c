// The Executor's side of the drilling cycles' expanders (hole_cycles.hpp).
#pragma once
#include <fmt/format.h>

#include "machine/cycles/cycle_moves.hpp"
#include "machine/cycles/hole_cycles.hpp"

namespace ncurve::machine {

// G88's return by hand is a warning and a rapid; a mill's block M codes act at the positioning.
struct Executor::HoleOutput final : CycleMoves {
  HoleOutput(Executor& x, const drill::Hole& h) : CycleMoves(x), hole(h) {}
  const drill::Hole& hole;

  void manual_return(const AxisVector& to) override {
    x.warn("NC2005", fmt::format("G88 stops at the bottom of the hole ({} {:.3f}) for the operator to bring the tool "
                                 "back to point R by hand (JOG or handle) and press cycle start; ncurve takes that "
                                 "as a straight rapid to R",
                                 "XYZ"[hole.axis], hole.z));
    CycleMoves::manual_return(to);
  }
  void positioned() override {
    if (!x.m_codes_.empty()) [[unlikely]] x.cycle_m_codes();
  }
};

inline drill::Parameters drill_parameters(const MachineProfile& p) {
  return {p.peck_retract, p.peck_clearance, p.drilling};
}

}  // namespace ncurve::machine
