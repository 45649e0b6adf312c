// The one G-code table: every G code of the FANUC 0i-F / 30i-B machining center and lathe (systems
// A, B, C) tables that ncurve knows, with its group, name, whether ncurve simulates it and the kind
// the interpolation and transform modes forbid. Group lookup, #4001..#4022, names and the
// not-simulated message are read from it (g_codes.cpp holds the rows).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "machine/profile.hpp"

namespace ncurve::machine {

// The control a row belongs to: the machining center or a lathe's G code system.
enum GMachine : std::uint8_t { kMill = 1, kLatheA = 2, kLatheB = 4, kLatheC = 8 };
GMachine g_machine(const MachineProfile& p);

enum class GStatus : std::uint8_t {
  simulated,
  not_simulated,  // the control has it, ncurve does not: NC9001 with the row's name
  absent,         // not a code of this control; the row only names the kind a mode check forbids
};

// What a code does, as the polar/cylindrical interpolation and transform modes forbid it.
enum class GKind : std::uint8_t {
  none, positioning, plane, reference, skip, tool_measurement, coordinate_change, coordinate_setting,
  coordinate_setting_with_axes,  // lathe system A G50: with X/Z/U/W (G50 S alone clamps the spindle)
  coordinate_transform, length_compensation, threading, single_cycle, repetitive_cycle, drilling_cycle,
};
const char* to_string(GKind k);  // "reference position return", or nullptr for none

class Executor;
// What a code does in its block, after the block's other words are read (one-shot codes, and G22
// with its area); returns whether the tool moved. The actions live beside the state they change.
using GAction = bool (*)(Executor& x, int g);

struct GCode {
  std::int16_t code;      // x10: 121 for G12.1
  std::uint8_t machines;  // GMachine bits
  std::uint8_t group;     // 0: one-shot (group 00)
  GStatus status;
  GKind kind;
  bool initial;           // in force at power-on in its group (the groups ncurve does not change)
  const char* name;
  GAction action = nullptr;
  bool one_shot() const { return group == 0; }
};

// The row of code g (x10) on machine m, or nullptr if the control has no such code.
const GCode* g_code(int g, GMachine m);
// The action of one-shot code g (x10) as the dispatch keeps it (a lathe's cycles as system A writes
// them), or nullptr.
GAction g_action(int g, GMachine m);
// Whether g (x10) selects a drilling canned cycle: G73/G74/G76/G81..G89 on a mill, G83..G85 and
// G87..G89 on a lathe.
inline bool drilling_cycle_code(int g, bool lathe) {
  if (lathe) return g == 830 || g == 840 || g == 850 || g == 870 || g == 880 || g == 890;
  return g % 10 == 0 && ((g >= 730 && g <= 760 && g != 750) || (g >= 810 && g <= 890));
}
// Whether the profile makes g (x10) a custom macro call (No.6050..6059), as the file's checks read it.
inline bool macro_g_code(const MachineProfile& p, int g) {
  for (int code : p.g_code_macros)
    if (code != 0 && g == (code < 0 ? -code : code) * 10) return true;
  return false;
}
// The group of g on m; 0 for a one-shot code or none.
int g_group(int g, GMachine m);
// The modal groups (1..) m's G-code table has, in order: those the control shows among its modal codes.
std::vector<int> g_groups(GMachine m);
// The code in force at power-on in group `group` of m that ncurve keeps no state for, or 0.
int g_initial(int group, GMachine m);
// "G02.2", as the manuals write it.
std::string g_name(int g);

}  // namespace ncurve::machine
