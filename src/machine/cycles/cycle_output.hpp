// Where a cycle's expander writes the elementary moves of its block: the interpreter implements it
// with its own move paths, a test records the moves. Positions are work coordinates, mm.
#pragma once
#include "machine/profile.hpp"

namespace ncurve::machine {

struct CycleOutput {
  virtual ~CycleOutput() = default;
  // Where the tool is. A move ends at its target, but a rotary axis (A, B, C) with roll-over may be
  // given back within one turn: read it again after a move that turns one.
  virtual AxisVector position() const = 0;
  virtual void rapid(const AxisVector& to) = 0;
  virtual void feed(const AxisVector& to) = 0;  // at the feed in force
  // A thread cut at `lead` mm per spindle revolution, starting at the spindle angle `start_angle`
  // (degrees; -1: it continues the cut before it).
  virtual void thread(const AxisVector& to, double lead, double start_angle) = 0;
  virtual void dwell(double seconds) = 0;
  virtual void spindle(int m) = 0;  // M03, M04, M05, M19 (oriented stop)
  virtual void m_code(int m) = 0;   // another M code the cycle gives out (a lathe's C-axis clamp)
  virtual void program_stop() = 0;  // the cycle stops for the operator
  // The operator brings the tool to `to` by hand (G88); it may already be there.
  virtual void manual_return(const AxisVector& to) = 0;
  // A hole is positioned, before the rapid to point R: the block's M codes act here (no move).
  virtual void positioned() {}
  // The cutting moves are over: the return to the start point follows (a lathe's G90, G94).
  virtual void returning() {}
};

}  // namespace ncurve::machine
