// The G-code table's actions (g_codes.cpp) for the codes whose work is an Executor function of
// their feature's file: each one runs its code's block and says whether the tool moved.
#include "machine/executor.hpp"

namespace ncurve::machine::actions {

bool dwell(Executor& x, int) { return x.dwell(), false; }
bool data_setting(Executor& x, int) { return x.data_setting(), false; }
bool reference_check(Executor& x, int) { return x.reference_check(), true; }        // reference_moves.cpp
bool reference_return(Executor& x, int g) { return x.reference_return(g), true; }   // G28, G30, G30.1
bool from_reference(Executor& x, int) { return x.return_from_reference(), true; }   // G29
bool skip(Executor& x, int g) { return x.skip_move(g); }                              // skip.cpp
bool coordinate_setting(Executor& x, int g) { return x.set_coordinate_system(g), false; }  // G52, G92, G50
bool workpiece_preset(Executor& x, int) { return x.workpiece_preset(), false; }     // G92.1, G50.3
bool machine_coordinates(Executor& x, int) { return x.machine_coordinate_move(), true; }  // G53
bool single_direction(Executor& x, int) { return x.single_direction_block(); }       // single_direction.cpp
bool stroke_area(Executor& x, int) { return x.stroke_area_command(), false; }        // stroke_check.cpp
bool repetitive_cycle(Executor& x, int g) { return x.repetitive_cycle(g); }          // G70..G75 as system A writes them
bool multiple_threading(Executor& x, int) { return x.multiple_threading_cycle(), true; }  // G76 (threading.cpp)

}  // namespace ncurve::machine::actions
