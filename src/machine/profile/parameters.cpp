// The control's parameters a profile or --param sets (No.1320, 6050, 1008#0.A, ...): each checked
// against the range the parameter manual gives and stored in the profile's fields.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <stdexcept>

#include "machine/profile.hpp"

namespace ncurve::machine {

bool is_axis_parameter(const std::string& key) {
  return key == "1006#0" || key == "1008#0" || key == "1008#1" || key == "1008#2" || key == "1260" ||
         key == "1320" || key == "1321" || key == "1322" || key == "1323" || key == "5440" ||
         key == "1022";
}

namespace {

// No.1320..1323 (stored stroke limits 1 and 2) and No.5440 (G60 overrun) of one axis, in increments.
void set_axis_length(MachineProfile& p, const std::string& key, int a, double value) {
  if (value != std::floor(value))
    throw std::runtime_error(fmt::format("parameter {} is a whole number of increments, got {}", key, value));
  const double mm = value * p.increment / (a == 0 && p.lathe() && p.diameter_x ? 2 : 1);  // a diameter on X
  if (key == "1320") p.stroke1_plus[a] = mm;
  else if (key == "1321") p.stroke1_minus[a] = mm;
  else if (key == "1322") p.stroke2_plus[a] = mm;
  else if (key == "1323") p.stroke2_minus[a] = mm;
  else p.g60_overrun[a] = value * p.increment;
}

// No.1006#0, No.1008#0..#2, No.1260 of one axis ("1008#0.A").
void set_axis_parameter(MachineProfile& p, const std::string& key, const std::string& axis, double value) {
  const int a = axis.size() == 1 ? axis_index(axis[0]) : -1;
  if (a < 0 || p.axes.find(axis[0]) == std::string::npos)
    throw std::runtime_error(fmt::format("parameter {}.{}: this machine has no {} axis (axes {})", key, axis, axis, p.axes));
  if (key == "1320" || key == "1321" || key == "1322" || key == "1323" || key == "5440")
    return set_axis_length(p, key, a, value);
  RotaryAxis& r = p.rotary[a];
  if (key == "1260") {  // 0 (a linear axis's entry in an array) leaves 360 deg
    if (value < 0 || value != std::floor(value))
      throw std::runtime_error(fmt::format("parameter 1260.{} is the travel of one turn in increments (0: 360 deg)", axis));
    r.per_turn = value > 0 ? value * p.increment : 360;
    return;
  }
  if (key == "1022") {  // 1, 2, 3: a basic axis; 5, 6, 7: parallel to X, Y, Z
    if (value != std::floor(value) || value < 0 || value > 7 || value == 4)
      throw std::runtime_error(fmt::format("parameter 1022.{} is 0..3 or 5..7 (5, 6, 7: parallel to X, Y, Z)", axis));
    r.parallel = static_cast<int>(value);
    return;
  }
  if (value != 0 && value != 1) throw std::runtime_error(fmt::format("parameter {}.{} is a bit: 0 or 1", key, axis));
  const bool on = value != 0;
  if (key == "1006#0") {
    if (on && a < 3)
      throw std::runtime_error(fmt::format("parameter 1006#0.{}: ncurve takes X, Y and Z as linear axes; A, B or C "
                                           "may be rotary", axis));
    r.rotary = on;
  } else if (key == "1008#0") r.roll_over = on;
  else if (key == "1008#1") r.by_sign = on;
  else r.relative_roll_over = on;
}

// The lathe threading parameters, each checked against the range the parameter manual gives.
void set_threading_parameter(MachineProfile& p, const std::string& key, double value) {
  auto whole = [&](double lo, double hi, const char* what) {
    if (value != std::floor(value) || value < lo || value > hi)
      throw std::runtime_error(fmt::format("parameter {} ({}) is a whole number from {} to {}", key, what, lo, hi));
    return static_cast<int>(value);
  };
  if (key == "5130") p.thread_chamfer = whole(0, 127, "thread chamfer in 0.1 leads");
  else if (key == "5131") p.thread_chamfer_angle = whole(0, 89, "thread chamfer angle, 0 = 45 degrees");
  else if (key == "5140") p.g76_min_depth = whole(0, 999999999, "G76 minimum depth of cut, increments") * p.increment;
  else if (key == "5141") p.g76_allowance = whole(0, 999999999, "G76 finishing allowance, increments") * p.increment;
  else if (key == "5142") p.g76_finish_count = whole(1, 99, "G76 finishing passes");
  else {
    const int a = whole(0, 80, "G76 tool nose angle");
    if (a != 0 && a != 29 && a != 30 && a != 55 && a != 60 && a != 80)
      throw std::runtime_error(fmt::format("parameter 5143 (G76 tool nose angle) is 0, 29, 30, 55, 60 or 80, got {}", a));
    p.g76_tool_angle = a;
  }
}

}  // namespace

// The parameters set_parameter takes, for the message that names them (one a line, kept in order).
constexpr const char* kSupportedParameters[] = {
    "0001#1",
    "0100#2",
    "0100#3",
    "1300#0",
    "1401#1",
    "3401#0",
    "3402#0",
    "3402#3",
    "3402#7",
    "3403#5",
    "3403#6",
    "3404#7",
    "3405#4",
    "3410",
    "3741..3744",
    "3772",
    "5001#5",
    "5003#0",
    "5003#1",
    "5008#1",
    "5008#3",
    "5101#0",
    "5101#2",
    "5101#4",
    "5101#5",
    "5101#6",
    "5102#6",
    "5102#7",
    "5105#1",
    "5105#2",
    "5110",
    "5111",
    "5114",
    "5115",
    "5130",
    "5131",
    "5132",
    "5133",
    "5135..5137",
    "5139",
    "5140..5143",
    "5200#0",
    "5200#5",
    "5213",
    "5400#0",
    "5400#6",
    "5400#7",
    "5410",
    "5411",
    "5421",
    "5431#0",
    "5460",
    "5461",
    "6001#1",
    "6001#5",
    "6004#0",
    "19625",
    "6050..6059",
    "6071..6079",
    "6080..6089",
};

// The per-axis parameters it takes.
constexpr const char* kSupportedAxisParameters[] = {
    "1006#0",
    "1008#0",
    "1008#1",
    "1008#2",
    "1022",
    "1260",
    "1320..1323",
    "5440",
};

double MachineProfile::spindle_limit(int* parameter) const {
  double limit = 0;
  int number = 0;
  for (int g = 0; g < 4; ++g)
    if (gear_max_speed[g] > limit) limit = gear_max_speed[g], number = 3741 + g;
  if (spindle_upper_limit > 0 && (limit == 0 || spindle_upper_limit <= limit))
    limit = spindle_upper_limit, number = 3772;
  if (parameter) *parameter = number;
  return limit;
}

void set_parameter(MachineProfile& p, const std::string& key, double value) {
  auto bit = [&] {
    if (value != 0 && value != 1) throw std::runtime_error(fmt::format("parameter {} is a bit: 0 or 1", key));
    return value != 0;
  };
  if (!std::isfinite(value) || std::fabs(value) > 1e9)
    throw std::runtime_error(fmt::format("parameter {}: {} is not a value a parameter can hold", key, value));
  if (const auto dot = key.find('.'); dot != std::string::npos && is_axis_parameter(key.substr(0, dot)))
    return set_axis_parameter(p, key.substr(0, dot), key.substr(dot + 1), value);
  if (is_axis_parameter(key))
    throw std::runtime_error(fmt::format("parameter {} is set per axis: write {}.A (for the A axis), or in a "
                                         "profile an array with one value per axis",
                                         key, key));
  if (key == "5101#0") p.drilling.axis_by_plane = bit();
  else if (key == "5101#4" || key == "5101#5") {
    const int mask = key == "5101#4" ? 1 : 2;
    p.drilling.shift_direction = bit() ? (p.drilling.shift_direction | mask) : (p.drilling.shift_direction & ~mask);
  }
  else if (key == "5101#6") p.drilling.tap_without_m05 = bit();
  else if (key == "5101#2") p.drilling.lathe_peck_to_r = bit();
  else if (key == "5102#6") p.drilling.lathe_r_by_axis = bit();
  else if (key == "5102#7") p.drilling.lathe_r_absolute = bit();
  else if (key == "5110" || key == "5111") {
    if (value < 0 || value != std::floor(value) || value > 99999999)
      throw std::runtime_error(fmt::format("parameter {} is a whole number, 0 or more", key));
    if (key == "5110") p.drilling.c_clamp_m = static_cast<int>(value);
    else p.drilling.c_unclamp_dwell = value / 1000.0;  // ms
  }
  else if (key == "5200#0") p.drilling.g84_rigid = bit();
  else if (key == "5200#5") p.drilling.peck_to_r = bit();
  else if (key == "5213") {
    if (value < 0 || value != std::floor(value))
      throw std::runtime_error("parameter 5213 is a whole number of increments, 0 or more");
    p.drilling.rigid_return = value * p.increment;
  }
  else if (key == "5431#0") p.g60_modal = bit();
  else if (key == "1300#0") p.stroke2_outside = bit();
  else if (key == "1401#1") p.linear_rapid = bit();
  else if (key == "3402#7") p.stroke2_off_at_power_on = bit();
  else if (key == "3401#0") p.decimal_calculator = bit();
  else if (key == "3403#5") p.arc_without_centre_alarm = bit();
  else if (key == "3403#6") p.address_duplicate_alarm = bit();
  else if (key == "3404#7") p.multiple_m_codes = bit();
  else if (key == "5003#0") p.compensation.startup_type_b = bit();
  else if (key == "5003#1") p.compensation.startup_type_c = bit();
  else if (key == "5008#1" || key == "5008#3") p.compensation.interference_check = !bit();
  else if (key == "19625") {
    if (p.control != Control::fanuc_30i)
      throw std::runtime_error("parameter 19625: the 0i reads a fixed 3 blocks ahead in cutter compensation; No.19625 "
                               "is a 30i parameter (control = \"30i\")");
    if (value != std::floor(value) || value < 3 || value > 8)
      throw std::runtime_error(fmt::format("parameter 19625 is 3 .. 8 blocks, got {}", value));
    p.compensation.blocks_read = static_cast<int>(value);
  }
  else if (key == "6004#0") p.atan_signed = bit();
  else if (key == "0001#1" || key == "1#1") p.series10_format = bit();
  else if (key == "5105#1") p.mrc_no_finish_type1 = bit();
  else if (key == "5105#2") p.mrc_no_finish_type2 = bit();
  else if (key == "5132" || key == "5133" || key == "5135" || key == "5136" || key == "5139") {
    if (value < 0) throw std::runtime_error(fmt::format("parameter {} is a length in mm, 0 or more", key));
    double& field = key == "5132" ? p.mrc_depth : key == "5133" ? p.mrc_escape : key == "5135" ? p.mrc_relief_x
                  : key == "5136" ? p.mrc_relief_z : p.mrc_return;
    field = value;
  }
  else if (key == "5137") {
    if (value < 0 || value != std::floor(value))
      throw std::runtime_error("parameter 5137 is a whole number of divisions, 0 or more");
    p.mrc_divisions = value;
  }
  else if (key == "3402#0") p.power_on_g01 = bit();
  else if (key == "3402#3") p.power_on_g91 = bit();
  else if (key == "6001#5") p.t_code_calls_o9000 = bit();
  else if (key == "6001#1") p.dprnt_no_spaces = bit();
  else if (key == "0100#2" || key == "100#2") p.eob_cr_lf = bit();
  else if (key == "0100#3" || key == "100#3") p.eob_lf_only = bit();
  else if (key == "3405#4") p.chamfer_address_c = bit();
  else if (key == "5001#5") p.position_offset_by_h = bit();
  else if (key == "3410") p.arc_radius_tolerance = value * p.increment;
  else if (key == "3741" || key == "3742" || key == "3743" || key == "3744" || key == "3772") {
    if (value < 0 || value != std::floor(value))
      throw std::runtime_error(fmt::format("parameter {} is a spindle speed, a whole number of rev/min, 0 or more", key));
    (key == "3772" ? p.spindle_upper_limit : p.gear_max_speed[key[3] - '1']) = value;
  }
  else if (key == "5114" || key == "5115") {
    if (value < 0 || value != std::floor(value))
      throw std::runtime_error(fmt::format("parameter {} is a whole number of increments, 0 or more", key));
    (key == "5114" ? p.peck_retract : p.peck_clearance) = value * p.increment;
  }
  else if (key == "5460" || key == "5461") {
    if (value != std::floor(value) || value < 0 || value > 8)
      throw std::runtime_error(fmt::format("parameter {} is an axis number, 0..8 (1: the profile's first axis)", key));
    (key == "5460" ? p.polar_linear_axis : p.polar_rotary_axis) = static_cast<int>(value);
  }
  else if (key == "5400#0") p.rotation_angle_by_g90_g91 = bit();
  else if (key == "5400#6") p.scaling_per_axis = bit();
  else if (key == "5400#7") p.scaling_unit_coarse = bit();
  else if (key == "5410") {
    if (value != std::floor(value) || std::fabs(value) > 360000)
      throw std::runtime_error(fmt::format("parameter 5410 is -360000 .. 360000 (0.001 degree), got {}", value));
    p.rotation_default_deg = value * 0.001;
  } else if (key == "5411" || key == "5421") {
    if (value != std::floor(value) || std::fabs(value) > 999999)
      throw std::runtime_error(
          fmt::format("parameter {} is a magnification of -999999 .. 999999 units, got {}", key, value));
    (key == "5411" ? p.scaling_default : p.scaling_axis_default) = static_cast<int>(value);
  } else if (key == "5130" || key == "5131" || key == "5140" || key == "5141" || key == "5142" || key == "5143") {
    set_threading_parameter(p, key, value);
  }
  else {
    int n = 0;
    try {
      std::size_t used = 0;
      n = std::stoi(key, &used);
      if (used != key.size()) n = 0;
    } catch (...) {
      n = 0;
    }
    const bool known = (n >= 6050 && n <= 6059) || (n >= 6080 && n <= 6089) || (n >= 6071 && n <= 6079);
    if (known && value != std::floor(value))
      throw std::runtime_error(fmt::format("parameter {} takes a whole number, got {}", key, value));
    const int code = static_cast<int>(value);
    if (n >= 6050 && n <= 6059 && code < 0)
      throw std::runtime_error(fmt::format("parameter {} = {}: a negative G code (a modal call on the controls that "
                                           "take one) is not simulated by ncurve: {} makes G{} a simple call, as G65", key, code, -code, -code));
    if (n >= 6050 && n <= 6059) p.g_code_macros[n - 6050] = code;
    else if (n >= 6080 && n <= 6089) p.m_code_macros[n - 6080] = code;
    else if (n >= 6071 && n <= 6079) p.m_code_subprograms[n - 6071] = code;
    else
      throw UnknownParameter(fmt::format("parameter '{}' is not one ncurve uses (supported: {}; per axis {})", key,
                                         fmt::join(kSupportedParameters, ", "), fmt::join(kSupportedAxisParameters, ", ")));
  }
}

}  // namespace ncurve::machine
