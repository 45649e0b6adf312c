// The programmed contour under cutter / tool-nose radius compensation, beside the path the moves
// make (their ends the tool centre's, a lathe's imaginary tip's): each compensated move's start and
// end as programmed, and the move cancelling the offset; each such arc's programmed centre and
// sweep. The corners compensation inserts have no programmed move of their own. What /api/run's
// "programmed" columns and run --html's data carry for the backplot (web/backplot-programmed.js).
#pragma once
#include <array>
#include <optional>

#include "machine/move.hpp"

namespace ncurve::report {

class ProgrammedContour {
public:
  struct Piece {
    machine::AxisVector start{}, end{};  // as programmed: work coordinates, lathe X a radius
    bool arc = false;
    std::array<double, 3> centre{};  // an arc's
    double sweep = 0;                // an arc's, radians, counter-clockwise positive about its plane's normal
  };
  // Each motion in order. tip: the imaginary tip's offset from the nose centre (Z, X radius) for
  // this move (machine::Interpreter::nose_tip_now) on a lathe whose moves are the tip's; none on a
  // mill or when the moves are the nose centre's. The programmed piece the motion makes, if it is
  // off the path.
  std::optional<Piece> on_motion(const machine::Move& m, std::array<double, 2> tip = {});

private:
  machine::AxisVector programmed_{};  // where the program has the tool: the next programmed move's start
  machine::AxisVector last_end_{};
  bool started_ = false;
};

}  // namespace ncurve::report
