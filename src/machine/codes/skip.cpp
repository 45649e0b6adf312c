// G31 skip function. ncurve has no skip signal: the block runs as it does when the signal never
// comes, a linear move to its end point, and #5061.. hold that point (docs/reference-moves.md).
#include <fmt/format.h>

#include "machine/executor.hpp"

namespace ncurve::machine {

bool Executor::skip_move(int g) {
  const std::string code = g == 310 ? std::string("G31") : fmt::format("G31.{}", g % 10);
  if (compensating())
    alarm("PS0035", fmt::format("{} cannot be given in cutter compensation mode (G41/G42): cancel it with G40 first",
                                code));
  std::string signal = "the skip signal";
  if (g == 310 && has('P')) {  // multi-step skip: P1..P4 choose the signals (No.6202..)
    const int p = integer(word('P'), "P of G31");
    if (p < 1 || p > 4)
      alarm("NC9002", fmt::format("G31 P{}: the multi-step skip takes P1 to P4 (the manual names no alarm)", p),
            word('P').column);
    signal = fmt::format("the skip signals of P{}", p);
  } else if (g != 310) {
    signal = fmt::format("the skip signals of {}", code);
  }
  AxisVector target = coords_.pos;
  if (!axis_target(target)) return false;
  if (rolls_) roll_over(target);
  linear(MoveKind::line, target);
  skip_position_ = coords_.pos;
  warn("NC2040", fmt::format("{}: ncurve does not simulate {}; the tool moves to the end point, as when the signal "
                             "never comes, and #5061.. hold it",
                             code, signal));
  return true;
}

}  // namespace ncurve::machine
