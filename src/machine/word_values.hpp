// Values of a block's words as the control reads them, shared by the run loop, calls and dispatch.
#pragma once
#include <cmath>

namespace ncurve::machine {

// Half away from zero, saturated to the int range.
inline int round_int(double v) {
  double r = v < 0 ? -std::floor(-v + 0.5) : std::floor(v + 0.5);
  if (!(r > -2147483647.0)) return -2147483647;
  if (!(r < 2147483647.0)) return 2147483647;
  return static_cast<int>(r);
}

// Argument specification I: address -> local variable number.
inline int argument_variable(char letter) {
  switch (letter) {
    case 'A': return 1;  case 'B': return 2;  case 'C': return 3;  case 'I': return 4;
    case 'J': return 5;  case 'K': return 6;  case 'D': return 7;  case 'E': return 8;
    case 'F': return 9;  case 'H': return 11; case 'M': return 13; case 'Q': return 17;
    case 'R': return 18; case 'S': return 19; case 'T': return 20; case 'U': return 21;
    case 'V': return 22; case 'W': return 23; case 'X': return 24; case 'Y': return 25;
    case 'Z': return 26; default: return 0;
  }
}

// Dimension words, read in least input increments without a decimal point.
inline bool scaled_address(char c) {
  switch (c) {
    case 'X': case 'Y': case 'Z': case 'U': case 'V': case 'W': case 'A': case 'B': case 'C':
    case 'I': case 'J': case 'K': case 'R': case 'Q': return true;
    default: return false;
  }
}

}  // namespace ncurve::machine
