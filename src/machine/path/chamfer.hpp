// Chamfering and corner R: the request of a block and its move, held until the next move.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "machine/path/corner_geometry.hpp"
#include "machine/move.hpp"
#include "nc/program.hpp"

namespace ncurve::machine {

// What the block's words ask for, read before its move.
struct CornerRequest {
  corner::Kind kind = corner::Kind::chamfer;
  double amount = 0;          // mm: ,C distance from the virtual corner, or ,R radius
  bool square = false;        // the lathe's 90-degree form (C/I/K, R): the next move is fixed
  int next_axis = 0;          // square: the axis the next block moves along
  int next_sign = 0;          // square: and its direction, from the amount's sign
  std::uint16_t column = 0;   // the word, for alarms
};

// A move held until the next move shows where the corner is cut.
struct HeldCorner {
  CornerRequest request;
  Move move;
  std::optional<nc::Span> block;  // the block with the request (its first column), for alarms there
  std::uint64_t step = 0;     // the run's block count when it was held
  int side = 0;               // G41 +1, G42 -1, 0: compensation of the held move
  int d = 0;                  // its D number and lathe offset, should the next block change them
  int lathe_offset = 0;
  std::vector<Move> events;   // events after it (M codes of its block, T of the next): after the corner
};

}  // namespace ncurve::machine
