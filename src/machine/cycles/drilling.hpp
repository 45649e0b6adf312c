// One hole of a drilling canned cycle, as canned_cycles.cpp works it out for the cycle's motions.
#pragma once
#include "machine/executor.hpp"

namespace ncurve::machine {

struct Executor::Hole {
  AxisVector at{};  // the hole position (its coordinate along the drilling axis is not used)
  int axis = 2;     // the drilling axis: 2 Z, 1 Y, 0 X
  double initial = 0, r = 0, z = 0;  // levels along the drilling axis
  double back = 0;  // where the hole ends: the initial level (G98) or point R (G99)
  bool rigid = false;
  double into() const { return z < r ? -1.0 : 1.0; }  // from R towards Z
};

}  // namespace ncurve::machine
