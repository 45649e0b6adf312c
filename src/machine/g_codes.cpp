// The rows of the G-code table (g_codes.hpp), from the G code lists of the FANUC 0i-F / 30i-B
// operator's manuals: the machining center's, and the lathe's with its systems A, B and C.
#include "machine/g_codes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <iterator>

namespace ncurve::machine {

// The actions of the codes that have one (g_actions.cpp unless a code has a file of its own in codes/).
namespace actions {
bool dwell(Executor&, int);
bool data_setting(Executor&, int);
bool reference_check(Executor&, int);
bool reference_return(Executor&, int);
bool from_reference(Executor&, int);
bool skip(Executor&, int);
bool coordinate_setting(Executor&, int);
bool workpiece_preset(Executor&, int);
bool machine_coordinates(Executor&, int);
bool single_direction(Executor&, int);
bool stroke_area(Executor&, int);
bool repetitive_cycle(Executor&, int);
bool multiple_threading(Executor&, int);
bool tool_retract(Executor&, int);  // codes/tool_retract.cpp
}  // namespace actions

namespace {
using namespace actions;
constexpr std::uint8_t M = kMill, LA = kLatheA, LB = kLatheB, LC = kLatheC, L = LA | LB | LC, BC = LB | LC,
                       ALL = M | L;
constexpr GStatus sim = GStatus::simulated, ns = GStatus::not_simulated, absent = GStatus::absent;
using K = GKind;

// One row per code and machine; a code whose meaning differs between machines has a row for each.
constexpr GCode kTable[] = {
    // group 01: interpolation
    {0, ALL, 1, sim, K::positioning, false, "positioning (G00)"},
    {10, ALL, 1, sim, K::none, false, "linear interpolation (G01)"},
    {20, ALL, 1, sim, K::none, false, "circular interpolation CW (G02)"},
    {30, ALL, 1, sim, K::none, false, "circular interpolation CCW (G03)"},
    {22, M, 1, ns, K::none, false, "involute interpolation (G02.2)"},
    {32, M, 1, ns, K::none, false, "involute interpolation (G03.2)"},
    {23, M, 1, ns, K::none, false, "exponential interpolation (G02.3)"},
    {33, M, 1, ns, K::none, false, "exponential interpolation (G03.3)"},
    {24, M, 1, ns, K::none, false, "3-dimensional circular interpolation (G02.4)"},
    {34, M, 1, ns, K::none, false, "3-dimensional circular interpolation (G03.4)"},
    {62, M, 1, ns, K::none, false, "NURBS interpolation (G06.2)"},
    {320, LA, 1, sim, K::threading, false, "threading (G32)"},
    {320, M | BC, 0, ns, K::threading, false, "threading (G32/G33)"},
    {330, M, 1, sim, K::threading, false, "thread cutting (G33)"},
    {330, BC, 1, sim, K::threading, false, "threading (G33)"},
    {330, LA, 0, ns, K::threading, false, "threading (G32/G33)"},
    {340, L, 1, ns, K::threading, false, "variable lead threading (G34)"},
    {340, M, 0, absent, K::threading, false, nullptr},
    {750, M, 0, absent, K::drilling_cycle, false, nullptr},  // the drilling-cycle check takes G73..G76 whole
    {350, L, 1, ns, K::none, false, "circular threading (G35)"},
    {900, LA, 1, sim, K::single_cycle, false, "outer/inner diameter cutting cycle (G90)"},
    {920, LA, 1, sim, K::single_cycle, false, "threading cycle (G92)"},
    {940, LA, 1, sim, K::single_cycle, false, "end face cutting cycle (G94)"},
    {770, BC, 1, sim, K::single_cycle, false, "outer/inner diameter cutting cycle (G77)"},
    {780, BC, 1, sim, K::single_cycle, false, "threading cycle (G78)"},
    {790, BC, 1, sim, K::single_cycle, false, "end face cutting cycle (G79)"},
    // group 00: one-shot
    {40, ALL, 0, sim, K::none, false, "dwell (G04)", dwell},
    {50, ALL, 0, sim, K::none, false, "high-precision contour control (G05)"},
    {51, ALL, 0, sim, K::none, false, "AI contour control (G05.1)"},
    {70, ALL, 0, ns, K::none, false, "cylindrical interpolation (G07.1)"},
    {71, ALL, 0, sim, K::none, false, "cylindrical interpolation (G07.1)"},
    {1070, ALL, 0, sim, K::none, false, "cylindrical interpolation (G107)"},
    {80, ALL, 0, sim, K::none, false, "advanced preview control (G08)"},
    {90, ALL, 0, sim, K::none, false, "exact stop (G09)"},
    {100, ALL, 0, sim, K::none, false, "programmable data input (G10)", data_setting},
    {106, ALL, 0, sim, K::none, false, "tool retract and recover (G10.6)", tool_retract},
    {109, L, 0, ns, K::none, false, "programmable switching of diameter and radius programming (G10.9)"},
    {110, ALL, 0, ns, K::none, false, "programmable parameter input (G10 L50 .. G11)"},
    {120, ALL, 0, ns, K::none, false, "circle cutting (G12/G13)"},
    {130, ALL, 0, ns, K::none, false, "circle cutting (G12/G13)"},
    {270, ALL, 0, sim, K::reference, false, "reference position return check (G27)", reference_check},
    {280, ALL, 0, sim, K::reference, false, "automatic reference position return (G28)", reference_return},
    {281, ALL, 0, ns, K::none, false, "in-position check disable reference position return (G28.2)"},
    {290, ALL, 0, sim, K::reference, false, "movement from reference position (G29)", from_reference},
    {300, ALL, 0, sim, K::reference, false, "2nd, 3rd, 4th reference position return (G30)", reference_return},
    {301, ALL, 0, sim, K::reference, false, "floating reference position return (G30.1)", reference_return},
    {302, ALL, 0, ns, K::none, false, "in-position check disable 2nd reference position return (G30.2)"},
    {310, ALL, 0, sim, K::skip, false, "skip function (G31)", skip},
    {311, ALL, 0, sim, K::skip, false, "multi-step skip (G31.1)", skip},
    {312, ALL, 0, sim, K::skip, false, "multi-step skip (G31.2)", skip},
    {313, ALL, 0, sim, K::skip, false, "multi-step skip (G31.3)", skip},
    {314, ALL, 0, sim, K::skip, false, "multi-step skip (G31.4)", skip},
    {318, ALL, 0, ns, K::none, false, "EGB skip (G31.8)"},
    {319, ALL, 0, ns, K::none, false, "continuous high-speed skip (G31.9)"},
    {360, L, 0, ns, K::none, false, "automatic tool compensation (G36): ncurve does not simulate the measuring "
                                "position reached signal (without it the control stops with PS0080)"},
    {370, L, 0, ns, K::tool_measurement, false, "automatic tool compensation (G37): ncurve does not simulate the measuring "
                                "position reached signal (without it the control stops with PS0080)"},
    {370, M, 0, ns, K::tool_measurement, false, "automatic tool length measurement (G37): ncurve does not simulate the "
     "measuring position reached signal (without it the control stops with PS0080)"},
    {380, ALL, 0, ns, K::none, false, "cutter compensation vector retention (G38)"},
    {390, ALL, 0, ns, K::none, false, "corner circular interpolation (G39)"},
    {450, M, 0, sim, K::none, false, "tool offset increase (G45)"},
    {460, M, 0, sim, K::none, false, "tool offset decrease (G46)"},
    {470, M, 0, sim, K::none, false, "tool offset double increase (G47)"},
    {480, M, 0, sim, K::none, false, "tool offset double decrease (G48)"},
    {500, LA, 0, sim, K::coordinate_setting_with_axes, false, "coordinate system setting, maximum spindle speed (G50)", coordinate_setting},
    {500, BC, 0, sim, K::none, false, "(G50)"},
    {503, LA, 0, sim, K::none, false, "workpiece coordinate system preset (G50.3)", workpiece_preset},
    {504, ALL, 0, ns, K::none, false, "synchronous control (G50.4)"},
    {514, ALL, 0, ns, K::none, false, "synchronous control (G51.4)"},
    {505, ALL, 0, ns, K::none, false, "composite control (G50.5)"},
    {515, ALL, 0, ns, K::none, false, "composite control (G51.5)"},
    {506, ALL, 0, ns, K::none, false, "superimposed control (G50.6)"},
    {516, ALL, 0, ns, K::none, false, "superimposed control (G51.6)"},
    {520, ALL, 0, sim, K::coordinate_change, false, "local coordinate system setting (G52)", coordinate_setting},
    {530, ALL, 0, sim, K::coordinate_change, false, "machine coordinate system selection (G53)", machine_coordinates},
    {531, M, 0, ns, K::none, false, "tool axis direction control (G53.1)"},
    {542, M, 0, ns, K::none, false, "rotary table dynamic fixture offset (G54.2)"},
    {544, M, 0, ns, K::none, false, "workpiece setting error compensation (G54.4)"},
    {600, M, 0, sim, K::none, false, "single direction positioning (G60)", single_direction},
    {650, ALL, 0, sim, K::none, false, "macro call (G65)"},
    {920, M | BC, 0, sim, K::coordinate_setting, false, "coordinate system setting (G92)", coordinate_setting},
    {921, M | BC, 0, sim, K::none, false, "workpiece coordinate system preset (G92.1)", workpiece_preset},
    {911, ALL, 0, ns, K::none, false, "maximum incremental value check (G91.1)"},
    {961, ALL, 0, ns, K::none, false, "spindle indexing (G96.1)"},
    {962, ALL, 0, ns, K::none, false, "spindle indexing (G96.2)"},
    {963, ALL, 0, ns, K::none, false, "spindle indexing (G96.3)"},
    {964, ALL, 0, ns, K::none, false, "spindle indexing (G96.4)"},
    {804, ALL, 0, ns, K::none, false, "electronic gear box (G80.4)"},
    {814, ALL, 0, ns, K::none, false, "electronic gear box (G81.4)"},
    {811, M, 0, ns, K::none, false, "chopping (G81.1)"},
    {721, M, 0, ns, K::none, false, "figure copying, rotation (G72.1)"},
    {722, M, 0, ns, K::none, false, "figure copying, parallel (G72.2)"},
    // lathe multiple repetitive cycles: G70..G76 on systems A and B, G72..G78 on C
    {700, LA | LB, 0, sim, K::repetitive_cycle, false, "finishing cycle (G70)", repetitive_cycle},
    {710, LA | LB, 0, sim, K::repetitive_cycle, false, "stock removal in turning (G71)", repetitive_cycle},
    {720, L, 0, sim, K::repetitive_cycle, false, "stock removal in facing (G72)", repetitive_cycle},
    {730, L, 0, sim, K::repetitive_cycle, false, "pattern repeating (G73)", repetitive_cycle},
    {740, L, 0, sim, K::repetitive_cycle, false, "end face peck drilling (G74)", repetitive_cycle},
    {750, L, 0, sim, K::repetitive_cycle, false, "outer/inner diameter drilling (G75)", repetitive_cycle},
    {760, L, 0, sim, K::repetitive_cycle, false, "multiple threading cycle (G76)", multiple_threading},
    // group 02 (mill) / 16 (lathe): plane selection
    {170, M, 2, sim, K::plane, false, "XpYp plane selection (G17)"},
    {180, M, 2, sim, K::plane, false, "ZpXp plane selection (G18)"},
    {190, M, 2, sim, K::plane, false, "YpZp plane selection (G19)"},
    {170, L, 16, sim, K::plane, false, "XpYp plane selection (G17)"},
    {180, L, 16, sim, K::plane, false, "ZpXp plane selection (G18)"},
    {190, L, 16, sim, K::plane, false, "YpZp plane selection (G19)"},
    // group 03: absolute and incremental programming (mill, lathe B and C)
    {900, M | BC, 3, sim, K::none, false, "absolute programming (G90)"},
    {910, M | BC, 3, sim, K::none, false, "incremental programming (G91)"},
    // group 04 (mill) / 09 (lathe): stored stroke check
    {220, M, 4, sim, K::none, false, "stored stroke check function on (G22)", stroke_area},
    {230, M, 4, sim, K::none, false, "stored stroke check function off (G23)"},
    {220, L, 9, sim, K::none, false, "stored stroke check function on (G22)", stroke_area},
    {230, L, 9, sim, K::none, false, "stored stroke check function off (G23)"},
    // lathe group 04: mirror image for double turrets
    {680, L, 4, ns, K::coordinate_transform, false, "mirror image for double turrets / balance cut (G68)"},
    {690, L, 4, sim, K::none, true, "mirror image for double turrets off / balance cut cancel (G69)"},
    // group 05: feed per minute / per revolution (lathe system A: G98/G99)
    {940, M | BC, 5, sim, K::none, false, "feed per minute (G94)"},
    {950, M | BC, 5, sim, K::none, false, "feed per revolution (G95)"},
    {980, LA, 5, sim, K::none, false, "feed per minute (G98)"},
    {990, LA, 5, sim, K::none, false, "feed per revolution (G99)"},
    {930, M, 5, ns, K::none, false, "inverse time feed (G93)"},
    // group 06: inch/metric (lathe system C: G70/G71)
    {200, ALL, 6, sim, K::none, false, "input in inch (G20)"},
    {210, ALL, 6, sim, K::none, false, "input in mm (G21)"},
    {700, LC, 6, sim, K::repetitive_cycle, false, "input in inch (G70)"},
    {710, LC, 6, sim, K::repetitive_cycle, false, "input in mm (G71)"},
    // group 07: cutter / tool-nose radius compensation
    {400, ALL, 7, sim, K::none, false, "cutter compensation cancel (G40)"},
    {410, ALL, 7, sim, K::none, false, "cutter compensation left (G41)"},
    {420, ALL, 7, sim, K::none, false, "cutter compensation right (G42)"},
    {412, M, 7, ns, K::none, false, "3-dimensional cutter compensation (G41.2)"},
    {422, M, 7, ns, K::none, false, "3-dimensional cutter compensation (G42.2)"},
    // group 08: tool length compensation (mill) / spindle speed fluctuation detection (lathe)
    {430, M, 8, sim, K::length_compensation, false, "tool length compensation + (G43)"},
    {440, M, 8, sim, K::length_compensation, false, "tool length compensation - (G44)"},
    {490, M, 8, sim, K::length_compensation, false, "tool length compensation cancel (G49)"},
    {430, L, 0, absent, K::length_compensation, false, nullptr},
    {440, L, 0, absent, K::length_compensation, false, nullptr},
    {490, L, 0, absent, K::length_compensation, false, nullptr},
    {431, M, 8, ns, K::none, false, "tool length compensation in tool axis direction (G43.1)"},
    {434, M, 8, ns, K::none, false, "tool center point control (G43.4)"},
    {435, M, 8, ns, K::none, false, "tool center point control (G43.5)"},
    {250, L, 8, sim, K::none, true, "spindle speed fluctuation detection off (G25)"},
    {260, L, 8, sim, K::none, false, "spindle speed fluctuation detection on (G26)"},
    {250, M, 24, sim, K::none, false, "spindle speed fluctuation detection off (G25)"},
    {260, M, 24, sim, K::none, false, "spindle speed fluctuation detection on (G26)"},
    // group 09 (mill) / 10 (lathe): canned cycles for drilling
    {800, M, 9, sim, K::none, false, "canned cycle cancel (G80)"},
    {730, M, 9, sim, K::drilling_cycle, false, "peck drilling cycle (G73)"},
    {740, M, 9, sim, K::drilling_cycle, false, "left-handed tapping cycle (G74)"},
    {760, M, 9, sim, K::drilling_cycle, false, "fine boring cycle (G76)"},
    {810, M, 9, sim, K::drilling_cycle, false, "drilling cycle, spot drilling (G81)"},
    {820, M, 9, sim, K::drilling_cycle, false, "drilling cycle, counter boring (G82)"},
    {830, M, 9, sim, K::drilling_cycle, false, "peck drilling cycle (G83)"},
    {840, M, 9, sim, K::drilling_cycle, false, "tapping cycle (G84)"},
    {850, M, 9, sim, K::drilling_cycle, false, "boring cycle (G85)"},
    {860, M, 9, sim, K::drilling_cycle, false, "boring cycle (G86)"},
    {870, M, 9, sim, K::drilling_cycle, false, "back boring cycle (G87)"},
    {880, M, 9, sim, K::drilling_cycle, false, "boring cycle (G88)"},
    {890, M, 9, sim, K::drilling_cycle, false, "boring cycle (G89)"},
    {800, L, 10, sim, K::none, false, "canned cycle for drilling cancel (G80)"},
    {830, L, 10, sim, K::drilling_cycle, false, "face drilling cycle (G83)"},
    {840, L, 10, sim, K::drilling_cycle, false, "face tapping cycle (G84)"},
    {850, L, 10, sim, K::drilling_cycle, false, "face boring cycle (G85)"},
    {870, L, 10, sim, K::drilling_cycle, false, "side drilling cycle (G87)"},
    {880, L, 10, sim, K::drilling_cycle, false, "side tapping cycle (G88)"},
    {890, L, 10, sim, K::drilling_cycle, false, "side boring cycle (G89)"},
    // group 10 (mill) / 11 (lathe systems B and C): canned cycle return level
    {980, M, 10, sim, K::none, false, "canned cycle: return to initial level (G98)"},
    {990, M, 10, sim, K::none, false, "canned cycle: return to R point level (G99)"},
    {980, BC, 11, sim, K::none, false, "canned cycle: return to initial level (G98)"},
    {990, BC, 11, sim, K::none, false, "canned cycle: return to R point level (G99)"},
    // group 11 (mill): scaling
    {500, M, 11, sim, K::none, true, "scaling cancel (G50)"},
    {510, M, 11, sim, K::coordinate_transform, false, "scaling (G51)"},
    {510, L, 0, ns, K::coordinate_transform, false, "scaling (G51)"},
    // group 12: macro modal call
    {660, ALL, 12, sim, K::none, false, "macro modal call (G66)"},
    {661, ALL, 12, ns, K::none, false, "macro modal call on every block (G66.1)"},
    {670, ALL, 12, sim, K::none, false, "macro modal call cancel (G67)"},
    // group 13 (mill) / 02 (lathe): constant surface speed
    {960, M, 13, sim, K::none, false, "constant surface speed control (G96)"},
    {970, M, 13, sim, K::none, false, "constant surface speed control cancel (G97)"},
    {960, L, 2, sim, K::none, false, "constant surface speed control (G96)"},
    {970, L, 2, sim, K::none, false, "constant surface speed control cancel (G97)"},
    // group 14: workpiece coordinate systems
    {540, ALL, 14, sim, K::coordinate_change, false, "workpiece coordinate system 1 selection (G54)"},
    {541, ALL, 14, sim, K::coordinate_change, false, "additional workpiece coordinate system selection (G54.1)"},
    {550, ALL, 14, sim, K::coordinate_change, false, "workpiece coordinate system 2 selection (G55)"},
    {560, ALL, 14, sim, K::coordinate_change, false, "workpiece coordinate system 3 selection (G56)"},
    {570, ALL, 14, sim, K::coordinate_change, false, "workpiece coordinate system 4 selection (G57)"},
    {580, ALL, 14, sim, K::coordinate_change, false, "workpiece coordinate system 5 selection (G58)"},
    {590, ALL, 14, sim, K::coordinate_change, false, "workpiece coordinate system 6 selection (G59)"},
    // group 15: exact stop, tapping, cutting modes
    {610, ALL, 15, sim, K::none, false, "exact stop mode (G61)"},
    {611, ALL, 15, sim, K::none, false, "high-precision control mode (G61.1)"},
    {620, ALL, 15, sim, K::none, false, "automatic corner override (G62)"},
    {630, ALL, 15, sim, K::none, false, "tapping mode (G63)"},
    {640, ALL, 15, sim, K::none, false, "cutting mode (G64)"},
    // group 16 (mill): coordinate system rotation
    {680, M, 16, sim, K::coordinate_transform, false, "coordinate system rotation (G68)"},
    {690, M, 16, sim, K::none, true, "coordinate system rotation cancel (G69)"},
    {681, L, 16, ns, K::none, false, "coordinate system rotation (G68.1)"},
    {691, ALL, 16, ns, K::none, false, "coordinate system rotation cancel (G69.1)"},
    {682, M, 0, ns, K::none, false, "tilted working plane command (G68.2)"},
    {683, M, 0, ns, K::none, false, "tilted working plane command by tool axis direction (G68.3)"},
    {684, M, 0, ns, K::none, false, "tilted working plane command, incremental multi-command (G68.4)"},
    // group 17 (mill): polar coordinate command
    {150, M, 17, sim, K::none, true, "polar coordinates command cancel (G15)"},
    {160, M, 17, sim, K::coordinate_transform, false, "polar coordinates command (G16)"},
    {150, L, 0, ns, K::none, false, "polar coordinates (G15/G16)"},
    {160, L, 0, ns, K::coordinate_transform, false, "polar coordinates (G15/G16)"},
    // group 18 (mill): normal direction control
    {401, M, 18, ns, K::none, false, "normal direction control (G40.1)"},
    {411, M, 18, ns, K::none, false, "normal direction control (G41.1)"},
    {421, M, 18, ns, K::none, false, "normal direction control (G42.1)"},
    // lathe group 20: polygon turning
    {502, L, 20, ns, K::none, false, "polygon turning (G50.2)"},
    {512, L, 20, ns, K::none, false, "polygon turning (G51.2)"},
    {2500, BC, 20, ns, K::none, false, "polygon turning (G250)"},
    {2510, BC, 20, ns, K::none, false, "polygon turning (G251)"},
    // group 21: polar coordinate interpolation
    {121, ALL, 21, sim, K::none, false, "polar coordinate interpolation (G12.1)"},
    {131, ALL, 21, sim, K::none, true, "polar coordinate interpolation cancel (G13.1)"},
    {1120, L, 21, sim, K::none, false, "polar coordinate interpolation (G112)"},
    {1130, L, 21, sim, K::none, false, "polar coordinate interpolation cancel (G113)"},
    // group 22 (mill): programmable mirror image
    {501, M, 22, sim, K::none, false, "programmable mirror image cancel (G50.1)"},
    {511, M, 22, sim, K::coordinate_transform, false, "programmable mirror image (G51.1)"},
    {511, L, 0, ns, K::coordinate_transform, false, "programmable mirror image (G51.1)"},
};

constexpr int kCodes = 2600;  // x10: up to G259.9

struct Index {
  std::array<std::array<std::int16_t, kCodes>, 4> row;  // -1: none
  Index() {
    for (auto& r : row) r.fill(-1);
    for (int i = 0; i < static_cast<int>(std::size(kTable)); ++i)
      for (int m = 0; m < 4; ++m)
        if ((kTable[i].machines & (1 << m)) && row[m][kTable[i].code] < 0) row[m][kTable[i].code] = static_cast<std::int16_t>(i);
  }
};
const Index& index() {
  static const Index kIndex;
  return kIndex;
}
int slot(GMachine m) { return m == kMill ? 0 : m == kLatheA ? 1 : m == kLatheB ? 2 : 3; }
}  // namespace

GMachine g_machine(const MachineProfile& p) {
  if (!p.lathe()) return kMill;
  return p.gcode_system == 'A' ? kLatheA : p.gcode_system == 'B' ? kLatheB : kLatheC;
}

const GCode* g_code(int g, GMachine m) {
  if (g < 0 || g >= kCodes) return nullptr;
  const int i = index().row[slot(m)][g];
  return i < 0 ? nullptr : &kTable[i];
}

GAction g_action(int g, GMachine m) {
  const GCode* r = g_code(g, m);
  if ((!r || !r->action) && m != kMill) r = g_code(g, kLatheA);
  return r ? r->action : nullptr;
}

int g_group(int g, GMachine m) {
  const GCode* r = g_code(g, m);
  return r && r->status != GStatus::absent ? r->group : 0;
}

std::vector<int> g_groups(GMachine m) {
  std::vector<int> groups;
  for (const GCode& r : kTable)
    if (r.group > 0 && (r.machines & m) && r.status != GStatus::absent) groups.push_back(r.group);
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  return groups;
}

std::vector<int> modal_groups(const MachineProfile& p) { return g_groups(g_machine(p)); }

int g_initial(int group, GMachine m) {
  for (const GCode& r : kTable)
    if (r.initial && r.group == group && (r.machines & m)) return r.code;
  return 0;
}

std::string g_name(int g) { return fmt::format("G{:02}{}", g / 10, g % 10 ? fmt::format(".{}", g % 10) : ""); }

const char* to_string(GKind k) {
  switch (k) {
    case GKind::none: return nullptr;
    case GKind::positioning: return "positioning";
    case GKind::plane: return "plane selection";
    case GKind::reference: return "reference position return";
    case GKind::skip: return "skip function";
    case GKind::tool_measurement: return "automatic tool length measurement";
    case GKind::coordinate_change: return "coordinate system change";
    case GKind::coordinate_setting: case GKind::coordinate_setting_with_axes: return "coordinate system setting";
    case GKind::coordinate_transform: return "coordinate transform";
    case GKind::length_compensation: return "tool length compensation";
    case GKind::threading: return "threading";
    case GKind::single_cycle: return "single cutting cycle";
    case GKind::repetitive_cycle: return "multiple repetitive cycle";
    case GKind::drilling_cycle: return "drilling canned cycle";
  }
  return nullptr;
}

}  // namespace ncurve::machine
