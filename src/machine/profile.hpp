// What differs between machines: FANUC parameters, axes, units, limits, offsets.
#pragma once
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "nc/program.hpp"

namespace ncurve::machine {

enum class MachineType { mill, lathe };
enum class Control { fanuc_0i, fanuc_30i };

constexpr int kAxes = 6;  // X Y Z A B C
using AxisVector = std::array<double, kAxes>;
int axis_index(char letter);  // X0 Y1 Z2 A3 B4 C5, -1 otherwise

// One lathe offset set (FANUC T series with geometry and wear memory). X values are diameters
// when X is programmed as a diameter (No.5004#1 = 0). tip is the imaginary tool nose number 0..9.
struct LatheOffset {
  double x_wear = 0, z_wear = 0, r_wear = 0, tip = 0, x = 0, z = 0, r = 0;
};

// Where the imaginary tool tip of tip number 0..9 is from the nose centre, in nose radii along X
// and Z. The numbers follow the axes' directions: with +X up and +Z right they sit 2 6 1 / 7 0 5 /
// 3 8 4 about the centre (an outside turning tool is 3 on either side of the spindle); 0 and 9
// are the centre itself.
struct TipDirection {
  int x = 0, z = 0;
};
TipDirection tip_direction(int tip);  // (path/compensation.cpp)

// One mill offset number. Memory A holds one value, used by H and D; memory B a geometry and a
// wear, both used by H and D; memory C separate geometry and wear for H (length) and D (radius).
enum class OffsetMemory { A, B, C };
struct MillOffset {
  double geometry = 0, wear = 0;      // H, and D on memory A and B
  double d_geometry = 0, d_wear = 0;  // D on memory C
};

// Cutter / tool-nose radius compensation settings of the control.
struct CompensationProfile {
  bool startup_type_b = false;     // No.5003#0 SUP: start-up and cancel of type B (else type A)
  bool startup_type_c = false;     // No.5003#1 SUV: type C for G41/G42 and G40 in blocks without motion
  int blocks_read = 3;             // blocks read ahead in offset mode (No.19625 on 30i; 3 on 0i)
  bool interference_check = true;  // No.5008#1 CNC = 0: the interference check is performed
};

enum class AccDec { before, after };  // acc/dec before interpolation (look-ahead) or after it (filter)
enum class Filter { linear, exponential };

// How the control turns blocks into motion, for the time planner ([motion] in a profile).
struct MotionSettings {
  AxisVector acceleration{1000, 1000, 1000, 3600, 3600, 3600};  // mm/s^2 (deg/s^2) per axis
  double jerk = 0;                 // mm/s^3 along the path; 0 = no limit (trapezoidal feed)
  AccDec acc_dec = AccDec::before;
  Filter filter = Filter::linear;  // acc/dec after interpolation
  AxisVector time_constant{};      // s, acc/dec after interpolation per axis (No.1622)
  int look_ahead = 1;              // blocks read and planned ahead of the moving one (buffer)
  double block_time = 0.001;       // s: processing time of an NC block, the shortest time a block may take
  double macro_time = 0.0005;      // s per macro statement
  AxisVector corner_speed{};       // mm/min allowed change of axis speed at a corner (No.1783); 0 = stop
  double in_position = 0.02;       // mm, in-position width for exact stop (No.1826)
  bool look_ahead_at_power_on = true;  // the look-ahead mode (G05.1 Q1) is on at power-on and reset
  bool g61_1 = false;              // G61.1 (high-accuracy mode of other makers) taken as look-ahead on
};

// The position loop of each axis ([servo] in a profile).
struct ServoSettings {
  AxisVector kv{30, 30, 30, 30, 30, 30};  // position loop gain, 1/s (No.1825 / 100)
  double feed_forward = 0;                // velocity feed-forward coefficient 0..1
  double period = 0.001;                  // s, servo/interpolation period
};

// A rotary axis (No.1006#0 ROTx = 1): degrees, no inch/metric conversion, and its roll-over (No.1008).
struct RotaryAxis {
  bool rotary = false;
  bool roll_over = false;           // No.1008#0 ROAx: absolute positions kept within one turn
  bool by_sign = false;             // No.1008#1 RABx: absolute commands turn the way of their sign (else the shorter way)
  bool relative_roll_over = false;  // No.1008#2 RRLx: relative coordinates within one turn (display only)
  double per_turn = 360;            // No.1260, degrees per turn
  int parallel = 0;                 // No.1022: 5, 6, 7 = parallel to X, Y, Z (the axis G07.1 stands it for)
};

// Drilling canned cycle parameters of a mill (No.5101, No.5200, No.5213).
struct DrillingSettings {
  bool axis_by_plane = false;    // No.5101#0 FXY: 0 = the drilling axis is always Z, 1 = the plane's normal
  int shift_direction = 0;       // No.5101#4 RD1 + 2 * #5 RD2: G76/G87 shift (G17: +X, -X, +Y, -Y)
  bool tap_without_m05 = false;  // No.5101#6 M5T: 0 = M05 before the spindle reverses in G84/G74
  bool g84_rigid = false;        // No.5200#0 G84: G84/G74 are rigid tapping without M29
  bool peck_to_r = false;        // No.5200#5 PCP: 1 = peck rigid tapping returns to R (else high-speed, back by d)
  double rigid_return = 0;       // No.5213, mm: d of peck rigid tapping
  char repeat_address = 'K';     // repeats of a hole: K (0i, 16i, 30i) or L (controls whose format uses L)
  // a lathe's drilling cycles G83..G89 (docs/lathe-cycles.md)
  bool lathe_peck_to_r = false;  // No.5101#2 RTR: 0 = G83/G87 with Q are high-speed peck, 1 = peck (out to R)
  bool lathe_r_by_axis = false;  // No.5102#6 RDI: 0 = R is a radius, 1 = R of X follows X's diameter programming
  bool lathe_r_absolute = false; // No.5102#7 RAB: system A's R is 0 = from the initial level, 1 = absolute
  int c_clamp_m = 0;             // No.5110: the M code that clamps the C axis in a drilling block (0: none)
  double c_unclamp_dwell = 0;    // No.5111, s: dwell after the unclamp M code (clamp + 1)
};

struct MachineProfile {
  std::string name = "FANUC 0i-MF 3-axis mill, factory parameters";
  MachineType type = MachineType::mill;
  Control control = Control::fanuc_0i;
  std::string axes = "XYZ";         // axis letters in FANUC axis order (#5001 is the first)
  double increment = 0.001;         // least input increment in mm: IS-B 0.001, IS-C 0.0001
  char gcode_system = 'A';          // lathe G-code system A, B or C
  bool diameter_x = true;           // lathe: X programmed as a diameter (No.1006#3)
  bool decimal_calculator = false;  // No.3401#0 DPI: X10 means 10 mm, not 10 increments
  bool atan_signed = false;         // No.6004#0 NAT: ATAN -180..180, ASIN -90..90
  bool power_on_g01 = false;        // No.3402#0: G01 rather than G00 at power-on
  bool power_on_g91 = false;        // No.3402#3: G91 at power-on
  bool power_on_feed_per_rev = false;  // lathes start in feed per revolution
  int power_on_plane = 17;
  bool t_code_calls_o9000 = false;  // No.6001#5 TCS
  bool chamfer_address_c = false;   // No.3405#4 CCR: lathe chamfering by C (and R), not I/K (and R)
  bool block_skip = false;          // block skip switch on: blocks starting with '/' are skipped
  int macro_nesting = 4;            // G65/G66/custom calls: 4 on 0i/16i, 5 on 30i
  int subprogram_nesting = 10;      // M98 calls: 10 on 0i, 15 on 30i
  bool arc_without_centre_alarm = false;  // No.3403#5 CIR: G02/G03 without R or I J K is PS0022 (else a line)
  bool address_duplicate_alarm = false;  // No.3403#6 AD2: an address twice in a block is PS5074 (else the last counts)
  bool multiple_m_codes = false;         // No.3404#7 M3B: up to three M codes in a block (else one)
  int number_digits = 8;            // digits in one number (word or constant), leading zeros counted
  double arc_radius_tolerance = 0.020;  // No.3410, mm: start/end radius difference allowed
  bool position_offset_by_h = false;    // No.5001#5 TPH: G45..G48 take the offset number from H (else D)
  double peck_retract = 0;    // No.5114, mm: G73's retraction d after each peck
  double peck_clearance = 0;  // No.5115, mm: G83's clearance d above the previous peck's depth
  DrillingSettings drilling;
  std::array<RotaryAxis, kAxes> rotary{};  // by axis_index; only A, B, C may be rotary
  // lathe multiple repetitive cycles (G70..G75), docs/lathe-cycles-mrc.md
  double mrc_depth = 0;         // No.5132, mm: Δd of G71/G72
  double mrc_escape = 0;        // No.5133, mm: e of G71/G72
  double mrc_relief_x = 0;      // No.5135, mm (radius): Δi of G73
  double mrc_relief_z = 0;      // No.5136, mm: Δk of G73
  double mrc_divisions = 0;     // No.5137: d of G73
  double mrc_return = 0;        // No.5139, mm: e of G74/G75
  bool mrc_no_finish_type1 = false;  // No.5105#1 RF1: G71/G72 type I make no last pass along the shape
  bool mrc_no_finish_type2 = false;  // No.5105#2 RF2: likewise type II
  // lathe threading (docs/lathe-cycles.md); a G76 first block rewrites the G76 values
  int thread_chamfer = 0;        // No.5130: chamfer (pull-out) of G92/G76 in 0.1 leads, 0..127
  int thread_chamfer_angle = 0;  // No.5131: its angle to the thread axis, 1..89 degrees; 0 = 45
  double g76_min_depth = 0;      // No.5140, mm: G76 minimum depth of cut (dmin)
  double g76_allowance = 0;      // No.5141, mm: G76 finishing allowance (d)
  int g76_finish_count = 1;      // No.5142: G76 finishing passes (m), 1..99
  int g76_tool_angle = 0;        // No.5143: G76 tool nose angle (a): 0, 29, 30, 55, 60 or 80 degrees
  bool series10_format = false;  // No.0001#1 FCV: Series 10/11 program format (one-block G71..G76)
  // external output of DPRNT/BPRNT (docs/macro-output.md)
  bool dprnt_no_spaces = false;  // No.6001#1 PRT: leading zeros and the + sign send nothing (0: a space each)
  bool eob_cr_lf = false;        // No.0100#2 CRF: the end of block is CR LF (0: as NCR says)
  bool eob_lf_only = false;      // No.0100#3 NCR: the end of block is LF (0: LF CR CR)
  bool output_parity = false;    // characters keep ISO code's even parity bit (8th bit) as a receiver stores them
  int polar_linear_axis = 0;        // No.5460: G12.1's linear axis, by its number in `axes` (0: not set)
  int polar_rotary_axis = 0;        // No.5461: G12.1's rotary axis, by its number
  bool arcs_with_r = false;         // programs written for this machine give arcs by R, not I J K
  // coordinate transforms of a mill (G68, G51): parameters No.5400, 5410, 5411, 5421
  bool rotation_angle_by_g90_g91 = false;  // No.5400#0 RIN: G68 R follows G90/G91 (0: always absolute)
  bool scaling_per_axis = false;           // No.5400#6 XSC: G51 takes I J K per axis (0: P for all axes)
  bool scaling_unit_coarse = false;        // No.5400#7 SCR: P I J K count 0.001 (0: 0.00001)
  double rotation_default_deg = 0;         // No.5410 (0.001 deg): the angle of a G68 without R
  int scaling_default = 0;                 // No.5411: the magnification of a G51 without P
  int scaling_axis_default = 0;            // No.5421: the magnification of an axis without I, J or K
  std::array<int, 10> g_code_macros{};  // No.6050..6059: G code that calls O9010..O9019
  std::array<int, 10> m_code_macros{};  // No.6080..6089: M code that calls O9020..O9029
  std::array<int, 9> m_code_subprograms{};  // No.6071..6079: M code that calls O9001..O9009
  AxisVector rapid_rate{15000, 15000, 15000, 3600, 3600, 3600};  // mm/min (deg/min) per axis
  bool linear_rapid = false;  // No.1401#1 LRP: G00 on a straight line (else each axis at its own rate)
  double max_cutting_feed = 10000;  // mm/min
  double spindle_speed_for_time = 1000;  // rev/min assumed for feed per revolution when no S is active
  std::array<double, 4> gear_max_speed{};  // No.3741..3744, rev/min: each gear's maximum speed (0: not set)
  double spindle_upper_limit = 0;          // No.3772, rev/min: the spindle speed clamp (0: none)
  std::array<AxisVector, 7> work_offsets{};  // [0] external (#5201..), [1..6] G54..G59
  std::array<AxisVector, 4> reference_points{};  // machine coordinates of reference points 1..4
  std::optional<AxisVector> floating_reference;  // G30.1: set by the operator on the control (No.1244)
  // single direction positioning and stored stroke checks (docs/reference-moves.md)
  AxisVector g60_overrun{};   // No.5440 per axis, mm: the sign gives the final direction; 0 = none
  bool g60_modal = false;     // No.5431#0 MDL: G60 is modal in group 01 (0: one-shot, group 00)
  AxisVector stroke1_plus;    // No.1320 per axis, machine mm; +inf: no limit (factory)
  AxisVector stroke1_minus;   // No.1321 per axis
  AxisVector stroke2_plus{}, stroke2_minus{};  // No.1322 / No.1323: the area of stored stroke check 2
  bool stroke2_outside = false;    // No.1300#0 OUT: 0 = the inside of the area is forbidden, 1 = the outside
  bool stroke2_off_at_power_on = false;  // No.3402#7 G23: G23 (check 2 off) at power-on, else G22
  OffsetMemory offset_memory = OffsetMemory::A;  // mill tool compensation memory
  std::map<int, MillOffset> tool_offsets;  // mill: offset number 1..999
  std::map<int, LatheOffset> lathe_offsets;  // lathe: offset number 1..64 -> geometry and wear
  CompensationProfile compensation;
  MotionSettings motion;
  ServoSettings servo;

  MachineProfile() {
    stroke1_plus.fill(std::numeric_limits<double>::infinity());
    stroke1_minus.fill(-std::numeric_limits<double>::infinity());
  }
  bool lathe() const { return type == MachineType::lathe; }
  // The speed the control clamps the spindle at, rev/min (0: none), and the parameter that sets it:
  // No.3772, or the top gear's maximum (type M gear selection takes the top gear for any S beyond it).
  double spindle_limit(int* parameter = nullptr) const;
  nc::ParseOptions parse_options() const { return nc::ParseOptions{number_digits}; }
};

MachineProfile default_mill();
MachineProfile default_lathe();

// Reads a TOML profile; throws std::runtime_error naming file:line:column on a bad or unknown key.
MachineProfile load_profile(const std::string& path);
// Thrown by set_parameter for a parameter ncurve does not model (others are bad values).
struct UnknownParameter : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// Whether a parameter is set per axis (its key then ends in ".A", the axis letter).
bool is_axis_parameter(const std::string& key);
// Sets a FANUC parameter by its number ("6050", "3401#0"; per axis "1008#0.A"); throws for ones
// ncurve does not use.
void set_parameter(MachineProfile& p, const std::string& key, double value);
MachineProfile parse_profile(const std::string& toml_text, const std::string& origin);

// A tool offset's field (x, r_wear, radius, ... as the profile file and the API name them) against
// the control's input range (16i/0i, metric: geometry ±999.999 mm, wear ±99.999; a lathe's tip a
// whole 0..9): why the value cannot be set, without the field's place, or empty.
std::string offset_field_error(std::string_view field, double value);
// Sets a lathe offset's field by its name; false for a name it has not.
bool set_lathe_offset_field(LatheOffset& o, std::string_view field, double value);

}  // namespace ncurve::machine
