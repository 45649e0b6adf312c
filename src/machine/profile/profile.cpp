// Machine profiles read from TOML: each table checked and stored in a MachineProfile; the control
// parameters of [parameters] go through set_parameter (parameters.cpp).
#include "machine/profile.hpp"
#include "io/toml_text.hpp"

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

// The shipped mill stands as a vertical machining centre is set up: reference position 1 (where it
// powers on and G28 goes) at machine zero, the top of Z's travel and a corner of X and Y, and the
// work zeros G54..G59 on the table below it, all at one place (docs/profiles.md). The external
// offset and G54.1's stay 0.
MachineProfile default_mill() {
  MachineProfile p;
  for (int i = 1; i <= 6; ++i) p.work_offsets[i] = {-250, -200, -400, 0, 0, 0};
  return p;
}

std::string offset_field_error(std::string_view field, double value) {
  if (field == "tip")
    return value >= 0 && value <= 9 && value == std::floor(value)
               ? std::string()
               : fmt::format("the imaginary tool nose direction 'tip' is a whole number 0 .. 9, not {}", value);
  const bool wear = field.ends_with("_wear");
  const double most = wear ? 100 : 1000;
  if (std::fabs(value) < most) return {};
  return fmt::format("'{}' = {} mm is beyond the control's range (a {} value: -{} .. {} mm)", field, value,
                     wear ? "wear" : "geometry", most - 0.001, most - 0.001);
}

bool set_lathe_offset_field(LatheOffset& o, std::string_view field, double value) {
  if (field == "x") o.x = value;
  else if (field == "z") o.z = value;
  else if (field == "r") o.r = value;
  else if (field == "tip") o.tip = value;
  else if (field == "x_wear") o.x_wear = value;
  else if (field == "z_wear") o.z_wear = value;
  else if (field == "r_wear") o.r_wear = value;
  else return false;
  return true;
}

MachineProfile default_lathe() {
  MachineProfile p;
  p.name = "FANUC 0i-TF 2-axis lathe, factory parameters";
  p.type = MachineType::lathe;
  p.axes = "XZ";
  p.power_on_feed_per_rev = true;
  p.power_on_plane = 18;
  return p;
}

namespace {

[[noreturn]] void fail(const std::string& origin, const toml::node& node, const std::string& what) {
  const auto& src = node.source();
  throw std::runtime_error(fmt::format("{}:{}:{}: error: {}", origin, src.begin.line, src.begin.column, what));
}

double number(const std::string& origin, const toml::node& node, const std::string& key) {
  if (auto v = node.value<double>()) return *v;
  fail(origin, node, fmt::format("'{}' must be a number", key));
}

// A tool offset value within the control's input range (offset_field_error; a key ending in _wear
// is a wear value).
double offset_value(const std::string& origin, const toml::node& node, const std::string& key) {
  const double v = number(origin, node, key);
  if (const std::string why = offset_field_error(key, v); !why.empty()) fail(origin, node, "tool offset " + why);
  return v;
}

bool flag(const std::string& origin, const toml::node& node, const std::string& key) {
  if (auto v = node.value_exact<bool>()) return *v;
  // (as a double: toml++ converts a float out of int64's range to it undefined)
  if (auto v = node.value<double>(); v && (*v == 0 || *v == 1)) return *v == 1;
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

}  // namespace

MachineProfile parse_profile(const std::string& toml_text, const std::string& origin) {
  const toml::table root = io::parse_toml(toml_text, origin);
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
        else if (f == "linear_rapid") p.linear_rapid = flag(origin, fn, f);
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
            const double v = f == "tip" ? number(origin, fn, f) : offset_value(origin, fn, f);
            if (const std::string why = f == "tip" ? offset_field_error(f, v) : ""; !why.empty()) fail(origin, fn, why);
            if (!set_lathe_offset_field(o, f, v))
              fail(origin, fn, fmt::format("unknown lathe offset field '{}' (x, z, r, tip, x_wear, z_wear, r_wear)", f));
          }
          continue;
        }
        if (n < 1 || n > 999) fail(origin, tn, "tool offset numbers are 1 .. 999");
        MillOffset& o = p.tool_offsets[n];
        if (!set) {  // one value: the geometry of H and D alike
          o.geometry = o.d_geometry = offset_value(origin, tn, s);
          continue;
        }
        if (set->contains("x") || set->contains("z"))
          fail(origin, tn, "a table of x and z is a lathe offset: set type = \"lathe\" first");
        for (const auto& [fk, fn] : *set) {
          std::string f(fk.str());
          double v = offset_value(origin, fn, f);
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
