// Where the tool is and the coordinate systems it is measured in: the work offsets G54..G59 and
// G54.1 P1..P300, the external offset, the local system G52, the G92 (G50) shift and the tool
// shift of length and lathe offsets. machine = work + origin + tool_shift, each in mm (lathe X a radius).
#pragma once
#include <array>
#include <map>

#include "machine/move.hpp"

namespace ncurve::machine {

struct Coordinates {
  AxisVector pos{};         // the tool, work coordinates
  AxisVector origin{};      // the work zero in machine coordinates, tool shift aside
  AxisVector local{};       // G52
  AxisVector shift{};       // G92 (G50 on a system A lathe)
  AxisVector tool_shift{};  // G43/G44 on Z; a lathe's T offset on X and Z
  std::array<AxisVector, 7> work_offsets{};  // [0] the external offset, [1..6] G54..G59
  std::map<int, AxisVector> extended;        // G54.1 P1..P300

  // The work zero of work_index (1..6 G54..G59, 7 and up G54.1 P(n - 6)) put in force, the tool
  // staying where it is on the machine; returns how far the work coordinates moved (old - new origin).
  AxisVector select(int work_index);
  // G92: the tool's position becomes `given`; the G52 offsets of the named axes (a bit per axis) fold
  // into the shift, the others stay. Returns how far the work coordinates moved (given - old pos).
  AxisVector set_current(const AxisVector& given, unsigned named_axes);
};

}  // namespace ncurve::machine
