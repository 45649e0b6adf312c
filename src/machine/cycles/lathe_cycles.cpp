// Lathe single cutting cycles of group 01: G90 outer/inner diameter cutting, G94 end face cutting and
// G92 threading (G77, G79, G78 on G-code systems B and C), as the FANUC 0i-TF / 30i-B lathe operator's
// manuals describe them: four moves from the start point A and back to it (turning.cpp), X(U) Z(W) R
// modal.
#include <fmt/format.h>

#include <cmath>

#include "base/restore.hpp"
#include "machine/cycles/cycle_moves.hpp"
#include "machine/cycles/turning.hpp"

namespace ncurve::machine {

namespace {
// The code's meaning as system A writes it (32, 90, 92, 94, 76), or 0. g is x10, as handle_g_codes has it.
int system_a_code(int g, bool system_a) {
  if (system_a) {
    switch (g) {
      case 320: return 32;
      case 900: return 90;
      case 920: return 92;
      case 940: return 94;
      case 760: return 76;
      default: return 0;
    }
  }
  switch (g) {
    case 330: return 32;
    case 770: return 90;
    case 780: return 92;
    case 790: return 94;
    case 760: return 76;
    default: return 0;
  }
}

bool single_cycle_code(int code) { return code == 90 || code == 92 || code == 94; }

const char* cycle_name(int code) {
  switch (code) {
    case 90: return "outer/inner diameter cutting cycle";
    case 92: return "threading cycle";
    case 94: return "end face cutting cycle";
    default: return "threading";
  }
}
}  // namespace

bool Executor::select_lathe_motion(int g, std::vector<int>& one_shot) {
  const bool system_a = profile_.gcode_system == 'A';
  const int code = system_a_code(g, system_a);
  if (code == 0) return false;
  if (code == 76) {  // group 00: runs in place of the block's motion
    one_shot.push_back(760);
    return true;
  }
  // X, Z, R stay while G90/G92/G94 follow one another; any other group 01 code clears them
  if (!single_cycle_code(code) || !single_cycle_code(system_a_code(modal_.motion * 10, system_a))) end_lathe_cycle_data();
  modal_.motion = g / 10;
  return true;
}

void Executor::lathe_motion(const AxisVector& target) {
  const int code = system_a_code(modal_.motion * 10, profile_.gcode_system == 'A');
  if (code == 32) thread_block(target);
  else if (single_cycle_code(code)) single_cycle(target);
}

// One cycle from A (the current position) to the cutting end point E (turning.hpp).
void Executor::single_cycle(const AxisVector& target) {
  const bool system_a = profile_.gcode_system == 'A';
  const int code = system_a_code(modal_.motion * 10, system_a);
  const int written = modal_.motion;
  if (modal_.plane != 18)
    alarm("NC9001", fmt::format("G{} ({}) in the G{} plane is not supported yet (G18 only)", written,
                                cycle_name(code), modal_.plane));
  for (int a = 0; a < kAxes; ++a)
    if (a != 0 && a != 2 && target[a] != coords_.pos[a])
      alarm("NC9001", fmt::format("G{} ({}) with a move of an axis other than X and Z is not supported yet", written,
                                  cycle_name(code)));
  turn::SingleCycle c;
  c.code = code;
  c.end = target;
  if (has('X') || (system_a && has('U'))) lathe_cycle_.x = c.end[0];
  else if (lathe_cycle_.x) c.end[0] = *lathe_cycle_.x;
  if (has('Z') || (system_a && has('W'))) lathe_cycle_.z = c.end[2];
  else if (lathe_cycle_.z) c.end[2] = *lathe_cycle_.z;
  if (has('R')) lathe_cycle_.r = dimension(word('R'));
  c.r = lathe_cycle_.r;
  c.start_angle = code == 92 ? thread_start_angle() : 0;
  c.thread = {feed_, thread_chamfer_, profile_.thread_chamfer_angle};

  // Tool-nose radius compensation: the vector is cancelled at A, the cycle starts up its own offset
  // on the side the cutting pattern gives (whatever G41/G42 says) and cancels it on the return to A
  // (CycleMoves::returning). G92 is threaded without compensation.
  const int programmed_side = modal_.comp_side;
  const base::RestoreOnExit restore_side(modal_.comp_side);
  if (compensating()) {
    comp_->cancel_at_end();
    int side = 0;
    if (programmed_side != 0 && code != 92) {
      side = turn::start_side(c, coords_.pos);
      if (side == 0) side = programmed_side;
    }
    modal_.comp_side = side;
  }
  CycleMoves out(*this);
  turn::single_cycle(c, out);
}

}  // namespace ncurve::machine
