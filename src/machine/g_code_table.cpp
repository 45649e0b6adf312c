// G codes of the FANUC 0i-F / 30i-B G code tables (machining center and lathe systems) that ncurve
// does not simulate: they are NC9001, not PS0010, since the control has them (docs/reference-moves.md).
#include "machine/g_code_table.hpp"

namespace ncurve::machine {

namespace {
enum Where : unsigned char { mill = 1, lathe = 2, both = 3, lathe_bc = 4 };

struct Entry {
  int code;  // x10
  Where where;
  const char* name;
};

constexpr Entry kTable[] = {
    {22, mill, "involute interpolation (G02.2)"},
    {32, mill, "involute interpolation (G03.2)"},
    {23, mill, "exponential interpolation (G02.3)"},
    {33, mill, "exponential interpolation (G03.3)"},
    {24, mill, "3-dimensional circular interpolation (G02.4)"},
    {34, mill, "3-dimensional circular interpolation (G03.4)"},
    {62, mill, "NURBS interpolation (G06.2)"},
    {106, both, "tool retract and recover (G10.6)"},
    {109, lathe, "programmable switching of diameter and radius programming (G10.9)"},
    {110, both, "programmable parameter input (G10 L50 .. G11)"},
    {281, both, "in-position check disable reference position return (G28.2)"},
    {302, both, "in-position check disable 2nd reference position return (G30.2)"},
    {318, both, "EGB skip (G31.8)"},
    {319, both, "continuous high-speed skip (G31.9)"},
    {340, lathe, "variable lead threading (G34)"},
    {350, lathe, "circular threading (G35)"},
    {360, lathe, "automatic tool compensation (G36): ncurve does not simulate the measuring position reached "
                 "signal (without it the control stops with PS0080)"},
    {370, lathe, "automatic tool compensation (G37): ncurve does not simulate the measuring position reached "
                 "signal (without it the control stops with PS0080)"},
    {370, mill, "automatic tool length measurement (G37): ncurve does not simulate the measuring position reached "
                "signal (without it the control stops with PS0080)"},
    {380, both, "cutter compensation vector retention (G38)"},
    {390, both, "corner circular interpolation (G39)"},
    {401, mill, "normal direction control (G40.1)"},
    {411, mill, "normal direction control (G41.1)"},
    {421, mill, "normal direction control (G42.1)"},
    {412, mill, "3-dimensional cutter compensation (G41.2)"},
    {422, mill, "3-dimensional cutter compensation (G42.2)"},
    {431, mill, "tool length compensation in tool axis direction (G43.1)"},
    {434, mill, "tool center point control (G43.4)"},
    {435, mill, "tool center point control (G43.5)"},
    {502, lathe, "polygon turning (G50.2)"},
    {512, lathe, "polygon turning (G51.2)"},
    {2500, lathe_bc, "polygon turning (G250)"},
    {2510, lathe_bc, "polygon turning (G251)"},
    {504, both, "synchronous control (G50.4)"},
    {514, both, "synchronous control (G51.4)"},
    {505, both, "composite control (G50.5)"},
    {515, both, "composite control (G51.5)"},
    {506, both, "superimposed control (G50.6)"},
    {516, both, "superimposed control (G51.6)"},
    {531, mill, "tool axis direction control (G53.1)"},
    {542, mill, "rotary table dynamic fixture offset (G54.2)"},
    {544, mill, "workpiece setting error compensation (G54.4)"},
    {661, both, "macro modal call on every block (G66.1)"},
    {680, lathe, "mirror image for double turrets / balance cut (G68)"},
    {681, lathe, "coordinate system rotation (G68.1)"},
    {691, both, "coordinate system rotation cancel (G69.1)"},
    {682, mill, "tilted working plane command (G68.2)"},
    {683, mill, "tilted working plane command by tool axis direction (G68.3)"},
    {684, mill, "tilted working plane command, incremental multi-command (G68.4)"},
    {721, mill, "figure copying, rotation (G72.1)"},
    {722, mill, "figure copying, parallel (G72.2)"},
    {804, both, "electronic gear box (G80.4)"},
    {814, both, "electronic gear box (G81.4)"},
    {811, mill, "chopping (G81.1)"},
    {911, both, "maximum incremental value check (G91.1)"},
    {930, mill, "inverse time feed (G93)"},
    {961, both, "spindle indexing (G96.1)"},
    {962, both, "spindle indexing (G96.2)"},
    {963, both, "spindle indexing (G96.3)"},
    {964, both, "spindle indexing (G96.4)"},
    {1070, both, "cylindrical interpolation (G107)"},
    {1120, lathe, "polar coordinate interpolation (G112)"},
    {1130, lathe, "polar coordinate interpolation (G113)"},
};
}  // namespace

const char* g_code_not_simulated(int g, const MachineProfile& p) {
  const bool bc = p.lathe() && p.gcode_system != 'A';
  const unsigned here = p.lathe() ? lathe : mill;
  for (const Entry& e : kTable)
    if (e.code == g && ((e.where & here) || (bc && e.where == lathe_bc))) return e.name;
  return nullptr;
}

}  // namespace ncurve::machine
