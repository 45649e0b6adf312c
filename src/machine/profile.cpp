#include "machine/profile.hpp"
#include "machine/toml_nesting.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <toml++/toml.h>

namespace ncurve::machine {

int axis_index(char letter) {
  switch (letter) {
    case 'X': return 0;
    case 'Y': return 1;
    case 'Z': return 2;
    case 'A': return 3;
    case 'B': return 4;
    case 'C': return 5;
    default: return -1;
  }
}

MachineProfile default_mill() { return MachineProfile{}; }

MachineProfile default_lathe() {
  MachineProfile p;
  p.name = "FANUC 0i-TF 2-axis lathe, factory parameters";
  p.type = MachineType::lathe;
  p.axes = "XZ";
  p.power_on_feed_per_rev = true;
  p.power_on_plane = 18;
  return p;
}

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

[[noreturn]] void fail(const std::string& origin, const toml::node& node, const std::string& what) {
  const auto& src = node.source();
  throw std::runtime_error(fmt::format("{}:{}:{}: error: {}", origin, src.begin.line, src.begin.column, what));
}

double number(const std::string& origin, const toml::node& node, const std::string& key) {
  if (auto v = node.value<double>()) return *v;
  fail(origin, node, fmt::format("'{}' must be a number", key));
}

// A tool offset value within FANUC's input range (16i/0i, metric): geometry +-999.999 mm, wear
// +-99.999 mm (+-999.9999 and +-99.9999 on IS-C).
double offset_value(const std::string& origin, const toml::node& node, const std::string& key, bool wear) {
  const double v = number(origin, node, key);
  const double most = wear ? 100 : 1000;
  if (!(std::fabs(v) < most))
    fail(origin, node, fmt::format("tool offset '{}' = {} mm is beyond the control's range (a {} value: -{} .. {} mm)",
                                   key, v, wear ? "wear" : "geometry", most - 0.001, most - 0.001));
  return v;
}

bool flag(const std::string& origin, const toml::node& node, const std::string& key) {
  if (auto v = node.value<bool>()) return *v;
  if (auto v = node.value<int64_t>(); v && (*v == 0 || *v == 1)) return *v == 1;
  fail(origin, node, fmt::format("'{}' must be true/false or 0/1", key));
}

std::string text(const std::string& origin, const toml::node& node, const std::string& key) {
  if (auto v = node.value<std::string>()) return *v;
  fail(origin, node, fmt::format("'{}' must be a string", key));
}

AxisVector axis_vector(const std::string& origin, const toml::node& node, const std::string& key,
                       const std::string& axes) {
  const toml::array* arr = node.as_array();
  if (!arr || arr->size() != axes.size())
    fail(origin, node, fmt::format("'{}' must be an array of {} numbers, one per axis {}", key, axes.size(), axes));
  AxisVector v{};
  for (std::size_t i = 0; i < axes.size(); ++i) v[axis_index(axes[i])] = number(origin, *arr->get(i), key);
  return v;
}

void machine_table(MachineProfile& p, const toml::table& t, const std::string& origin) {
  // type first: its defaults (a lathe's axes X Z) must not replace the file's axes, and a TOML
  // table's keys come in alphabetical order ("axes" before "type"), not in the file's
  if (const toml::node* node = t.get("type")) {
    std::string v = text(origin, *node, "type");
    if (v == "mill") p.type = MachineType::mill;
    else if (v == "lathe") {
      MachineProfile l = default_lathe();
      p.type = l.type;
      p.axes = l.axes;
      p.power_on_feed_per_rev = l.power_on_feed_per_rev;
      p.power_on_plane = l.power_on_plane;
    } else fail(origin, *node, "type must be \"mill\" or \"lathe\"");
  }
  for (const auto& [k, node] : t) {
    std::string key(k.str());
    if (key == "name") p.name = text(origin, node, key);
    else if (key == "type") continue;
    else if (key == "control") {
      std::string v = text(origin, node, key);
      if (v == "0i" || v == "16i" || v == "18i" || v == "21i") p.control = Control::fanuc_0i;
      else if (v == "30i" || v == "31i" || v == "32i") {
        p.control = Control::fanuc_30i;
        p.macro_nesting = 5;
        p.subprogram_nesting = 15;
      } else fail(origin, node, "control must be \"0i\" or \"30i\" (or 16i/18i/21i/31i/32i)");
    } else if (key == "axes") {
      const toml::array* arr = node.as_array();
      if (!arr || arr->empty()) fail(origin, node, "axes must be an array of axis letters");
      std::string axes;
      for (const auto& a : *arr) {
        std::string s = text(origin, a, "axes");
        if (s.size() != 1 || axis_index(s[0]) < 0 || axes.find(s[0]) != std::string::npos)
          fail(origin, a, "each axis is one of X, Y, Z, A, B, C, named once");
        axes += s[0];
      }
      p.axes = axes;
    } else if (key == "increment_system") {
      std::string v = text(origin, node, key);
      if (v == "IS-B") p.increment = 0.001;
      else if (v == "IS-C") p.increment = 0.0001;
      else fail(origin, node, "increment_system must be \"IS-B\" (0.001 mm) or \"IS-C\" (0.0001 mm)");
    } else if (key == "gcode_system") {
      std::string v = text(origin, node, key);
      if (v != "A" && v != "B" && v != "C") fail(origin, node, "gcode_system must be \"A\", \"B\" or \"C\"");
      p.gcode_system = v[0];
    } else if (key == "arc_words") {
      std::string v = text(origin, node, key);
      if (v != "IJK" && v != "R") fail(origin, node, "arc_words must be \"IJK\" (centre offsets) or \"R\" (radius)");
      p.arcs_with_r = v == "R";
    } else if (key == "offset_memory") {
      std::string v = text(origin, node, key);
      if (v != "A" && v != "B" && v != "C")
        fail(origin, node, "offset_memory must be \"A\", \"B\" or \"C\" (tool compensation memory)");
      p.offset_memory = v == "A" ? OffsetMemory::A : v == "B" ? OffsetMemory::B : OffsetMemory::C;
    } else if (key == "cycle_repeat") {
      std::string v = text(origin, node, key);
      if (v != "K" && v != "L") fail(origin, node, "cycle_repeat must be \"K\" or \"L\" (the address of a canned cycle's repeats)");
      p.drilling.repeat_address = v[0];
    } else if (key == "diameter_programming") p.diameter_x = flag(origin, node, key);
    else if (key == "block_skip") p.block_skip = flag(origin, node, key);
    else if (key == "output_parity") p.output_parity = flag(origin, node, key);
    else if (key == "macro_call_nesting") p.macro_nesting = static_cast<int>(number(origin, node, key));
    else if (key == "subprogram_nesting") p.subprogram_nesting = static_cast<int>(number(origin, node, key));
    else if (key == "number_digits") {
      double v = number(origin, node, key);
      if (v != std::floor(v) || v < 8 || v > nc::kMostDigits)
        fail(origin, node, fmt::format("number_digits must be a whole number from 8 to {}", nc::kMostDigits));
      p.number_digits = static_cast<int>(v);
    } else fail(origin, node, fmt::format("unknown key '{}' in [machine]", key));
  }
}

void parameters_table(MachineProfile& p, const toml::table& t, const std::string& origin) {
  for (const auto& [k, node] : t) {
    std::string key(k.str());
    if (const toml::array* arr = node.as_array()) {  // an axis-type parameter: one value per axis
      if (!is_axis_parameter(key))
        fail(origin, node, fmt::format("parameter {} has one value, not one per axis", key));
      if (arr->size() != p.axes.size())
        fail(origin, node, fmt::format("'{}' must be an array of {} values, one per axis {}", key, p.axes.size(), p.axes));
      for (std::size_t i = 0; i < p.axes.size(); ++i) {
        const toml::node& v = *arr->get(i);
        double value = key.find('#') != std::string::npos ? (flag(origin, v, key) ? 1.0 : 0.0) : number(origin, v, key);
        try {
          set_parameter(p, fmt::format("{}.{}", key, p.axes[i]), value);
        } catch (const std::runtime_error& e) {
          fail(origin, v, e.what());
        }
      }
      continue;
    }
    double value = key.find('#') != std::string::npos ? (flag(origin, node, key) ? 1.0 : 0.0)
                                                       : number(origin, node, key);
    try {
      set_parameter(p, key, value);
    } catch (const std::runtime_error& e) {
      fail(origin, node, e.what());
    }
  }
}

double positive(const std::string& origin, const toml::node& node, const std::string& key, bool zero_allowed) {
  double v = number(origin, node, key);
  if (!(zero_allowed ? v >= 0 : v > 0))
    fail(origin, node, fmt::format("'{}' must be {}", key, zero_allowed ? "zero or more" : "more than zero"));
  return v;
}

AxisVector positive_axes(const std::string& origin, const toml::node& node, const std::string& key,
                         const std::string& axes, bool zero_allowed) {
  AxisVector v = axis_vector(origin, node, key, axes);
  for (char a : axes) {
    double x = v[axis_index(a)];
    if (!(zero_allowed ? x >= 0 : x > 0))
      fail(origin, node, fmt::format("'{}' must be {} for every axis", key, zero_allowed ? "zero or more" : "more than zero"));
  }
  return v;
}

void motion_table(MachineProfile& p, const toml::table& t, const std::string& origin) {
  MotionSettings& m = p.motion;
  for (const auto& [k, node] : t) {
    std::string key(k.str());
    if (key == "acceleration") m.acceleration = positive_axes(origin, node, key, p.axes, false);
    else if (key == "jerk") m.jerk = positive(origin, node, key, true);
    else if (key == "acc_dec") {
      std::string v = text(origin, node, key);
      if (v == "before") m.acc_dec = AccDec::before;
      else if (v == "after") m.acc_dec = AccDec::after;
      else fail(origin, node, "acc_dec must be \"before\" (interpolation, with look-ahead) or \"after\"");
    } else if (key == "filter") {
      std::string v = text(origin, node, key);
      if (v == "linear") m.filter = Filter::linear;
      else if (v == "exponential") m.filter = Filter::exponential;
      else fail(origin, node, "filter must be \"linear\" or \"exponential\"");
    } else if (key == "time_constant") m.time_constant = positive_axes(origin, node, key, p.axes, true);
    else if (key == "look_ahead") {
      double v = number(origin, node, key);
      if (v < 0 || v > 1000 || v != static_cast<int>(v))
        fail(origin, node, "look_ahead is a whole number of blocks, 0 (no buffer) .. 1000");
      m.look_ahead = static_cast<int>(v);
    } else if (key == "block_time") m.block_time = positive(origin, node, key, true);
    else if (key == "macro_time") m.macro_time = positive(origin, node, key, true);
    else if (key == "corner_speed") m.corner_speed = positive_axes(origin, node, key, p.axes, true);
    else if (key == "in_position") m.in_position = positive(origin, node, key, false);
    else if (key == "look_ahead_at_power_on") m.look_ahead_at_power_on = flag(origin, node, key);
    else if (key == "g61_1") m.g61_1 = flag(origin, node, key);
    else fail(origin, node, fmt::format("unknown key '{}' in [motion] (acceleration, jerk, acc_dec, filter, "
                                        "time_constant, look_ahead, block_time, macro_time, corner_speed, in_position, "
                                        "look_ahead_at_power_on, g61_1)", key));
  }
}

void servo_table(MachineProfile& p, const toml::table& t, const std::string& origin) {
  ServoSettings& s = p.servo;
  for (const auto& [k, node] : t) {
    std::string key(k.str());
    if (key == "kv") s.kv = positive_axes(origin, node, key, p.axes, false);
    else if (key == "feed_forward") {
      s.feed_forward = number(origin, node, key);
      if (s.feed_forward < 0 || s.feed_forward > 1) fail(origin, node, "feed_forward is a coefficient from 0 to 1");
    } else if (key == "period") {
      s.period = number(origin, node, key);
      if (s.period < 1e-5 || s.period > 0.01) fail(origin, node, "period is in seconds, 0.00001 .. 0.01");
    } else fail(origin, node, fmt::format("unknown key '{}' in [servo] (kv, feed_forward, period)", key));
  }
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
    "3401#0",
    "3402#0",
    "3402#3",
    "3402#7",
    "3403#5",
    "3403#6",
    "3404#7",
    "3405#4",
    "3410",
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
    if (n >= 6050 && n <= 6059) p.g_code_macros[n - 6050] = code;
    else if (n >= 6080 && n <= 6089) p.m_code_macros[n - 6080] = code;
    else if (n >= 6071 && n <= 6079) p.m_code_subprograms[n - 6071] = code;
    else
      throw UnknownParameter(fmt::format("parameter '{}' is not one ncurve uses (supported: {}; per axis {})", key,
                                         fmt::join(kSupportedParameters, ", "), fmt::join(kSupportedAxisParameters, ", ")));
  }
}

MachineProfile parse_profile(const std::string& toml_text, const std::string& origin) {
  check_toml_nesting(toml_text, origin);
  toml::table root;
  try {
    root = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(fmt::format("{}:{}:{}: error: {}", origin, e.source().begin.line,
                                         e.source().begin.column, e.description()));
  }
  MachineProfile p;
  // [machine] first: type and axes decide how the other tables read.
  if (auto* m = root["machine"].as_table()) machine_table(p, *m, origin);
  if (auto* m = root["parameters"].as_table()) parameters_table(p, *m, origin);
  for (const auto& [k, node] : root) {
    std::string key(k.str());
    if (key == "machine" || key == "parameters") {
      if (!node.is_table()) fail(origin, node, fmt::format("[{}] must be a table", key));
      continue;
    }
    const toml::table* t = node.as_table();
    if (!t) fail(origin, node, fmt::format("unknown top-level key '{}'", key));
    if (key == "feeds") {
      for (const auto& [fk, fn] : *t) {
        std::string f(fk.str());
        if (f == "rapid") p.rapid_rate = axis_vector(origin, fn, f, p.axes);
        else if (f == "max_cutting") p.max_cutting_feed = number(origin, fn, f);
        else if (f == "spindle_speed_for_time") p.spindle_speed_for_time = number(origin, fn, f);
        else fail(origin, fn, fmt::format("unknown key '{}' in [feeds]", f));
      }
    } else if (key == "motion") {
      motion_table(p, *t, origin);
    } else if (key == "servo") {
      servo_table(p, *t, origin);
    } else if (key == "work_offsets") {
      static const char* names[] = {"EXT", "G54", "G55", "G56", "G57", "G58", "G59"};
      for (const auto& [wk, wn] : *t) {
        std::string w(wk.str());
        int idx = -1;
        for (int i = 0; i < 7; ++i)
          if (w == names[i]) idx = i;
        if (idx < 0) fail(origin, wn, "work offsets are named EXT, G54 .. G59");
        p.work_offsets[idx] = axis_vector(origin, wn, w, p.axes);
      }
    } else if (key == "reference_points") {
      for (const auto& [rk, rn] : *t) {
        std::string r(rk.str());
        if (r == "floating") {  // G30.1: the floating reference position (No.1244)
          p.floating_reference = axis_vector(origin, rn, r, p.axes);
          continue;
        }
        int idx = r == "1" ? 0 : r == "2" ? 1 : r == "3" ? 2 : r == "4" ? 3 : -1;
        if (idx < 0)
          fail(origin, rn, "reference points are named \"1\" .. \"4\" (G28 uses 1, G30 P2..P4) or \"floating\" (G30.1)");
        p.reference_points[idx] = axis_vector(origin, rn, r, p.axes);
      }
    } else if (key == "tool_offsets") {
      for (const auto& [tk, tn] : *t) {
        std::string s(tk.str());
        int n = 0;
        std::size_t used = 0;
        try {
          n = std::stoi(s, &used);
        } catch (...) {
        }
        if (used != s.size() || s.empty())
          fail(origin, tn, fmt::format("tool offset '{}' is not a whole offset number", s));
        const toml::table* set = tn.as_table();
        if (p.lathe()) {  // { x = .., z = .., r = .., tip = .., x_wear = .. }
          if (!set) fail(origin, tn, "a lathe offset is a table: { x = .., z = .., r = .., tip = .., x_wear = .. }");
          if (n < 1 || n > 64) fail(origin, tn, "lathe offset numbers are 1 .. 64");
          LatheOffset& o = p.lathe_offsets[n];
          for (const auto& [fk, fn] : *set) {
            std::string f(fk.str());
            double v = f == "tip" ? number(origin, fn, f) : offset_value(origin, fn, f, f.ends_with("_wear"));
            if (f == "tip" && !(v >= 0 && v <= 9 && v == std::floor(v)))
              fail(origin, fn, fmt::format("the imaginary tool nose direction 'tip' is a whole number 0 .. 9, not {}", v));
            if (f == "x") o.x = v;
            else if (f == "z") o.z = v;
            else if (f == "r") o.r = v;
            else if (f == "tip") o.tip = v;
            else if (f == "x_wear") o.x_wear = v;
            else if (f == "z_wear") o.z_wear = v;
            else if (f == "r_wear") o.r_wear = v;
            else fail(origin, fn, fmt::format("unknown lathe offset field '{}' (x, z, r, tip, x_wear, z_wear, r_wear)", f));
          }
          continue;
        }
        if (n < 1 || n > 999) fail(origin, tn, "tool offset numbers are 1 .. 999");
        MillOffset& o = p.tool_offsets[n];
        if (!set) {  // one value: the geometry of H and D alike
          o.geometry = o.d_geometry = offset_value(origin, tn, s, false);
          continue;
        }
        if (set->contains("x") || set->contains("z"))
          fail(origin, tn, "a table of x and z is a lathe offset: set type = \"lathe\" first");
        for (const auto& [fk, fn] : *set) {
          std::string f(fk.str());
          double v = offset_value(origin, fn, f, f.ends_with("_wear"));
          if (f == "length") o.geometry = v;
          else if (f == "length_wear") o.wear = v;
          else if (f == "radius") o.d_geometry = v;
          else if (f == "radius_wear") o.d_wear = v;
          else fail(origin, fn, fmt::format("unknown mill offset field '{}' (length, length_wear, radius, radius_wear)", f));
        }
        if (p.offset_memory != OffsetMemory::C && (set->contains("radius") || set->contains("radius_wear")) &&
            (set->contains("length") || set->contains("length_wear")))
          fail(origin, tn, "offset memory A and B hold one value for H and D: give length or radius, not both "
                           "(offset_memory = \"C\" separates them)");
        if (p.offset_memory != OffsetMemory::C) {
          if (set->contains("radius")) o.geometry = o.d_geometry;
          if (set->contains("radius_wear")) o.wear = o.d_wear;
        }
        if (p.offset_memory == OffsetMemory::A && o.wear != 0)
          fail(origin, tn, "offset memory A has no wear values (offset_memory = \"B\" or \"C\")");
      }
    } else {
      fail(origin, node, fmt::format("unknown table [{}]", key));
    }
  }
  return p;
}

MachineProfile load_profile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: error: cannot open the machine profile", path));
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_profile(ss.str(), path);
}

}  // namespace ncurve::machine
