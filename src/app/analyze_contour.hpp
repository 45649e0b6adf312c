// `ncurve analyze --curve`: the run's moves passed on to the planner and the part's verifier, and
// the contour kept to be measured against the curve (docs/analyze.md).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "base/progress.hpp"
#include "machine/move.hpp"
#include "machine/profile.hpp"

namespace ncurve::app {

// The contour measured against the curve: feed moves (lines and arcs), and for a plane curve on a
// mill only those that stay at one Z (plunges and retracts are not part of the contour).
// With `programmed`, a compensated move is taken as programmed and the compensation's corner
// moves are left out. base::BoundExceeded past max_moves contour moves.
struct ContourTee final : machine::MoveSink {
  machine::MoveSink* planner = nullptr;
  std::vector<machine::Move>* contour = nullptr;  // null: none kept
  const machine::MachineProfile* profile = nullptr;
  std::size_t max_moves = 0;
  bool plane_only = false;
  bool programmed = false;
  bool compensated = false;             // a compensated move was met
  machine::AxisVector at_programmed{};  // where the program put the tool, compensation aside
  bool moved = false;
  std::array<double, 3> tip{};          // lathe: the imaginary tip from the nose centre (X radius, Y, Z)
  std::uint64_t moves = 0;
  base::Progress* progress = nullptr;   // the CLI's, drawn on a terminal
  machine::MoveSink* part = nullptr;    // the verifier cutting the part
  void on_move(const machine::Move& m) override;
  void keep(const machine::Move& m);
};

// A radius-compensated move as programmed: from the programmed end of the move before to its own.
// An arc keeps its centre (concentric with the tool's), less the imaginary tip's shift on a lathe.
machine::Move as_programmed(const machine::Move& m, const machine::AxisVector& from, const std::array<double, 3>& tip);

}  // namespace ncurve::app
