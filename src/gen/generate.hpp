// Part programs for a curve in the forms a programmer chooses, each run back through the
// interpreter and measured against the exact curve.
#pragma once
#include <string>
#include <optional>
#include <utility>
#include <vector>

#include "geom/approx.hpp"
#include "geom/curve.hpp"
#include "machine/move.hpp"
#include "machine/profile.hpp"

namespace ncurve::gen {

enum class Form { expanded, arcs, macro, adaptive_macro, cycle };
enum class Side { left, right };  // of the curve, looking along it (G41 / G42)
const char* to_string(Form f);
bool parse_form(const std::string& text, Form& out);

struct Options {
  Form form = Form::expanded;
  double tol = 0.005;  // mm
  geom::LineMethod lines = geom::LineMethod::equal_error;
  machine::MachineProfile profile = machine::default_mill();
  double feed = 0;          // mm/min (mill) or mm/rev (lathe); 0: 200 mm/min or 0.1 mm/rev
  double depth = 1;         // mill: cutting depth below Z0 for a plane curve, mm
  double clearance = 5;     // mill: rapid plane above Z0; lathe: retract distance, mm
  double step_down = 0;     // mill, plane curve: depth per pass, mm (0: one pass at full depth)
  int program_number = 1000;
  double tool_radius = 0;   // > 0: the program is the cutter-centre path, offset to `side`
  Side side = Side::left;
  // lathe with a tool radius: the imaginary tool nose direction (FANUC 0..9, the tip from the nose
  // centre: 1 (+X,+Z), 2 (+X,-Z), 3 (-X,-Z), 4 (-X,+Z), 5 +Z, 6 +X, 7 -Z, 8 -X; machine::
  // tip_direction); the program is the path of that imaginary tip. 0 or 9: the nose centre.
  int tip = 0;
  int cycle_program = 0;  // cycle: O9010..O9019 (G102..G111, No.6050..6059); 0: the curve's own
  // The program's set-up, once before the contour, and its end (none by default). tool > 0: the
  // tool called (mill: T M06, then G00 G43 Z at the clearance H tool; lathe: T with the offset of
  // the same number, T0101); spindle: rev/min, M03 (M04 with spindle_ccw), G97 on a lathe; css:
  // lathe, constant surface speed in m/min (G96), clamped by max_rpm (G50 S, G92 S on systems B
  // and C); coolant: M08 after the set-up, M09 at the end. A spindle started is stopped (M05).
  int tool = 0;
  int spindle = 0;
  bool spindle_ccw = false;
  int css = 0;
  int max_rpm = 0;
  bool coolant = false;
  // G20: every coordinate and feed of the program in inches, on the inch increment (IS-B
  // 0.0001 in, IS-C 0.00001 in). The curve, the tolerance and these options stay in mm (css in
  // m/min, written as ft/min); the round trip runs the inch program and measures in mm.
  bool inch = false;
  // Bounds on the work (docs/gen.md): the most contour moves (lines and arcs, all depth passes)
  // the program may make, and the most depth passes; beyond, generate() refuses (std::
  // runtime_error naming --max-moves or --step-down).
  std::size_t max_moves = 200000;
  static constexpr double kMostPasses = 1000;
};

// How the curve sits on the machine.
using AxisMap = geom::Placement;
AxisMap axis_map(const geom::Curve& curve, const Options& o);
geom::Plane plane_of(const machine::MachineProfile& p);

struct Stats {
  std::size_t words = 0, bytes = 0, blocks = 0;
  std::size_t points = 0;    // cutter-location points of the contour as the control runs it
  double path_length = 0;    // contour length, mm
  double max_deviation = 0;  // round trip: largest distance from the curve to the path, mm
  double worst_t = 0;        // where it is
  double start_t = 0;        // the curve parameter nearest the contour's first point
  geom::Vec3 worst_point{};  // machine coordinates of the curve point there
  // for plots: the contour as points (arcs sampled), and each move's largest deviation at the
  // curve parameter where it ends
  std::vector<geom::Vec3> path;
  std::vector<std::size_t> path_block;  // for each point after the first, the move that reaches it
  std::vector<std::pair<double, double>> deviation;  // (t, mm)
  // each move's largest distance from the curve: the curve's farthest point from the move over
  // the move's parameter interval, and the move's ends (the largest of these is max_deviation)
  std::vector<double> move_deviation;
  // round trip: every contour move of every pass, its index among all the moves the program makes
  // (events included, as `ncurve run` lists them) and its move_deviation
  std::vector<std::size_t> run_index;
  std::vector<double> run_deviation;
  std::size_t passes = 1;    // depth passes measured (all within max_deviation; the rest is the last)
  // the moves were the fit's path as the control reads it back, measured while the program was
  // emitted and run (the same figures as measuring them afterwards)
  bool measured_beside = false;
};

struct Result {
  std::string text;
  std::optional<geom::Curve> cutter_centre;  // with a tool radius: the offset curve the path follows
  AxisMap placement;  // where the measured curve (cutter_centre, else the curve) lies, mm, the last pass
  std::vector<std::pair<std::string, double>> parameters;  // to set on the control, e.g. {"6050", 102}
  std::string macro;  // cycle: its macro program alone (also at the end of text)
  Stats stats;
  bool within_tolerance = false;
};

// Throws std::runtime_error for options that are not finite, out of range or do not go together
// (a constant surface speed on a mill, a cycle in inches ...); generate() checks them first.
void check_options(const Options& o);

// Throws std::runtime_error for curves or options that cannot be generated.
Result generate(const geom::Curve& curve, const Options& o);

// Runs the program and measures the contour (blocks in [first_line, last_line] of the main
// program) against the curve; throws with the interpreter's alarm if the program fails.
Stats round_trip(const std::string& text, const geom::Curve& curve, const Options& o, std::uint32_t first_line,
                 std::uint32_t last_line);

// A move of a contour as measure() takes it (work coordinates, lathe X as a radius).
struct ContourMove {
  geom::Vec3 start{}, end{}, centre{};
  double sweep = 0;   // arcs: radians, counter-clockwise positive about the plane normal
  double length = 0;  // mm
  bool arc = false;
  static ContourMove of(const machine::Move& m);
};

// Measures a contour (lines and arcs, in order along the curve) against the curve: the largest
// distance from the curve to the path, by optimisation on each piece. With require_end the
// contour must end at the curve's end (within the tolerance).
Stats measure(const std::vector<ContourMove>& contour, const geom::Curve& curve, const Options& o, bool require_end);
Stats measure(const std::vector<machine::Move>& contour, const geom::Curve& curve, const Options& o, bool require_end);

// An SVG picture: the curve, the path (with its vertices) in the machine plane, and the deviation
// along the curve against the tolerance.
std::string plot_svg(const geom::Curve& curve, const Options& o, const Stats& s);

}  // namespace ncurve::gen
