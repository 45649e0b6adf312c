// What a verifier found wrong with a move: a warning at the move's block, where and how much.
#pragma once
#include <array>
#include <string>

#include "machine/move.hpp"

namespace ncurve::sim {

struct Finding {
  nc::Diagnostic diagnostic;       // a warning at the move's block
  std::array<double, 3> at{};      // where, work coordinates
  double amount = 0;               // how much (what the message says it is)
};

// The warning `code` with `message` at the block of move m (its line from its first non-blank
// column to its end).
Finding finding_at(const machine::Move& m, const std::string& code, std::string message,
                   const std::array<double, 3>& at, double amount);

}  // namespace ncurve::sim
