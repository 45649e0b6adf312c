// Where a rapid (G00) really goes: with non-linear positioning (No.1401#1 LRP = 0, the factory
// setting) each axis moves at its own rapid rate from the start and stops when it arrives, so the
// path is a dog-leg of up to one corner an axis; with linear positioning it is the straight line.
#pragma once
#include <vector>

#include "machine/move.hpp"

namespace ncurve::machine {

// The points the tool passes through, start first and end last (two for a straight path), at the
// axes' rapid rates (mm/min or deg/min) or on a line (linear positioning).
std::vector<AxisVector> rapid_path(const AxisVector& start, const AxisVector& end, const AxisVector& rates, bool linear);
inline std::vector<AxisVector> rapid_path(const AxisVector& start, const AxisVector& end, const MachineProfile& profile) {
  return rapid_path(start, end, profile.rapid_rate, profile.linear_rapid);
}

}  // namespace ncurve::machine
