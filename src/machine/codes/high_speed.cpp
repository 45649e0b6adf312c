// High-speed and look-ahead modes: G05.1 Q1/Q0 (AI contour control), G08 P1/P0 (its advanced
// preview control command), G05 P10000/P0 (its high-precision contour control command) and, on a
// profile that takes it, G61.1. They change how the control accelerates, not the path: each move
// records whether look-ahead is on, for `ncurve analyze`.
#include <fmt/format.h>

#include "machine/executor.hpp"

namespace ncurve::machine {

void Executor::high_speed_mode(int g, std::uint16_t column) {
  switch (g) {
    case 51: {  // G05.1: group 00, but the mode it sets lasts until Q0 or a reset
      if (!has('Q'))
        alarm("NC9002", "G05.1 needs Q1 (AI contour control on) or Q0 (off); the manual names no alarm for a "
                        "missing Q", column);
      const int q = integer(word('Q'), "Q of G05.1");
      if (q == 0 || q == 1) {
        modal_.look_ahead = q == 1;  // R (machining condition level) tunes the acceleration only
        return;
      }
      if (q == 2) alarm("NC9001", "smooth interpolation (G05.1 Q2) is not supported yet", column);
      if (q == 3) alarm("NC9001", "nano smoothing (G05.1 Q3) is not supported yet", column);
      alarm("NC9001", fmt::format("G05.1 Q{} is not supported yet (Q1 and Q0 switch AI contour control)", q), column);
    }
    case 80: {  // G08 P1/P0
      const int p = has('P') ? integer(word('P'), "P of G08") : -1;
      if (p != 0 && p != 1)
        alarm("PS0109", "format error in G08: G08 takes P1 (look-ahead control on) or P0 (off)", column);
      modal_.look_ahead = p == 1;
      return;
    }
    case 50: {  // G05 P10000/P0; other forms of G05 are high-speed cycle machining
      if (!has('P')) alarm("NC9001", "high-speed cycle machining (G05 without P) is not supported yet", column);
      const int p = integer(word('P'), "P of G05");
      if (p != 0 && p != 10000)
        alarm("NC9001", fmt::format("G05 P{} is not supported yet (P10000 and P0 switch AI contour control)", p),
              column);
      modal_.look_ahead = p == 10000;
      return;
    }
    case 611:  // G61.1: group 15 with G61..G64, which end it
      if (!profile_.motion.g61_1)
        alarm("PS0010", "G61.1 is not a G code of this control: it is the high-accuracy mode of other makers' "
                        "controls (FANUC's is G05.1 Q1); a profile with [motion] g61_1 = true takes it as look-ahead on",
              column);
      modal_.exact_stop = false;
      modal_.exact_stop_code = 611;
      return;
    default: return;
  }
}

}  // namespace ncurve::machine
