// Tool offsets and work offsets set by the program: the lathe's offset selection by T, and G10's
// data setting (L2/L20 work offsets, L1/L10..L13 tool offsets, a lathe's P, L52 parameters).
#include <fmt/format.h>

#include "machine/executor.hpp"

namespace ncurve::machine {

// Lathe offsets shift the tool tip: the path in work coordinates stays as programmed, the machine
// position (#5021.., G28, G53) carries the offset (geometry + wear).
void Executor::select_lathe_offset(int number, std::uint16_t column) {
  if (number < 0 || number > 64) alarm("PS0030", fmt::format("offset number {} out of range (0..64)", number), column);
  lathe_offset_ = number;
  if (number == 0) {
    coords_.tool_shift[0] = coords_.tool_shift[2] = 0;
    return;
  }
  const LatheOffset& o = lathe_offsets_[number];
  coords_.tool_shift[0] = (o.x + o.x_wear) / (profile_.diameter_x ? 2.0 : 1.0);
  coords_.tool_shift[2] = o.z + o.z_wear;
}

// G10 P_ X_ Z_ R_ Q_ on a lathe: P 1..64 wear, P 10001..10064 geometry; U, W, C add to X, Z, R.
void Executor::lathe_offset_setting() {
  if (!has('P')) alarm("PS0031", "G10 on a lathe needs P (offset number: 1..64 wear, 10001..10064 geometry)");
  int p = integer(word('P'), "P of G10");
  bool geometry = p > 10000;
  int n = geometry ? p - 10000 : p;
  if (n < 1 || n > 64) alarm("PS0031", fmt::format("G10 P{}: offset number out of range", p), word('P').column);
  LatheOffset& o = lathe_offsets_[n];
  auto set = [&](char absolute, char increment, double& geo, double& wear) {
    double& field = geometry ? geo : wear;
    if (has(absolute)) field = dimension(word(absolute));
    if (has(increment)) field += dimension(word(increment));
  };
  set('X', 'U', o.x, o.x_wear);
  set('Z', 'W', o.z, o.z_wear);
  set('R', 'C', o.r, o.r_wear);
  if (has('Q')) o.tip = word('Q').value;  // takes effect at the next T code, as on FANUC
}

void Executor::data_setting() {
  int l = has('L') ? integer(word('L'), "L of G10") : 0;
  if (profile_.lathe() && l == 0) return lathe_offset_setting();
  if (l == 2 || l == 20) {
    int p = has('P') ? integer(word('P'), "P of G10") : 0;
    AxisVector* set = nullptr;
    if (l == 2) {
      if (p < 0 || p > 6) alarm("PS0031", "G10 L2 P must be 0 (external) or 1..6 (G54..G59)", word('P').column);
      set = &coords_.work_offsets[p];
    } else {
      if (p < 1 || p > 300) alarm("PS0031", "G10 L20 P must be 1..300", word('P').column);
      set = &coords_.extended[p];
    }
    for (const Cmd& c : cmds_) {
      int a = axis_index(c.letter);
      if (a < 0 || !has_axis_[a]) continue;
      double v = dimension(c);
      (*set)[a] = modal_.incremental ? (*set)[a] + v : v;
    }
    set_origin();
    return;
  }
  if (l == 1 || l == 10 || l == 11 || l == 12 || l == 13) {
    if (!has('P') || !has('R')) alarm("PS0031", "G10 L10..L13 needs P (offset number) and R (value)");
    int p = integer(word('P'), "P of G10");
    if (p < 1 || p > 999) alarm("PS0031", fmt::format("G10 P{}: offset number out of range (1..999)", p), word('P').column);
    double v = dimension(word('R'));
    MillOffset& o = tool_offsets_[p];
    const bool wear = l == 11 || l == 13;
    double* field = &o.geometry;
    switch (profile_.offset_memory) {
      case OffsetMemory::A: field = &o.geometry; break;  // one value: every L sets it
      case OffsetMemory::B: field = wear ? &o.wear : &o.geometry; break;
      case OffsetMemory::C:
        field = l == 12 ? &o.d_geometry : l == 13 ? &o.d_wear : wear ? &o.wear : &o.geometry;
        break;
    }
    *field = modal_.incremental ? *field + v : v;
    return;
  }
  if (l == 52) return start_parameter_input();  // parameter_input.cpp
  if (l == 50)
    alarm("NC9001", "G10 L50 is the Series 15 form of programmable parameter input; the 0i, 16i and 30i take "
                    "G10 L52 (N_ R_ blocks, then G11)");
  alarm("NC9001", fmt::format("G10 L{} is not supported yet (L2, L20, L1/L10..L13 and L52 are)", l));
}

}  // namespace ncurve::machine
