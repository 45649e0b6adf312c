// Macro variables: locals, commons and the system variables a FANUC control exposes.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ctime>

#include "machine/g_codes.hpp"
#include "machine/executor.hpp"

namespace ncurve::machine {

using nc::Value;


// The code (x10) in force in modal group `group`, as #4001..#4022 read it: from the state ncurve
// keeps, each code's group taken from the G-code table (the lathe's groups differ from the mill's);
// the table's power-on code for a group ncurve does not change; 0 for a group the control lacks.
int Executor::modal_code(int group) const {
  const GMachine m = g_machine(profile_);
  if (group == 1) return motion_ * 10;  // G60 too, modal with No.5431#0 MDL = 1
  if (group == 3 && m == kLatheA) return incremental_ ? 910 : 900;
  const int work = work_index_ > 6 ? 541 : 530 + 10 * work_index_;
  const int state[] = {
      plane_ * 10,
      incremental_ ? 910 : 900,
      m == kLatheA ? (feed_per_rev_ ? 990 : 980) : (feed_per_rev_ ? 950 : 940),  // before the return level
      m == kLatheC ? (inch_ ? 700 : 710) : (inch_ ? 200 : 210),
      comp_side_ > 0 ? 410 : comp_side_ < 0 ? 420 : 400,
      length_comp_ * 10,
      stroke_.area_on ? 220 : 230,
      cycle_ == 0 ? 800 : cycle_ * 10,
      cycle_return_initial_ ? 980 : 990,
      css_ ? 960 : 970,
      speed_fluctuation_check_ ? 260 : 250,
      modal_call_ ? 660 : 670,
      work,
      exact_stop_code_ == 611 ? 611 : exact_stop_code_ * 10,
      developed_ && dev_->polar ? 121 : 131,
      xf_.scaling ? 510 : 500,
      xf_.rotating ? 680 : 690,
      polar_ ? 160 : 150,
      xf_.mirroring() ? 511 : 501,
  };
  for (const int g : state)
    if (g_group(g, m) == group) return g;
  return g_initial(group, m);
}

double Executor::program_units(int axis, double mm) const {
  double v = mm;
  if (axis == 0 && profile_.lathe() && profile_.diameter_x) v *= 2;
  if (inch_ && axis < 3) v /= 25.4;
  return v;
}

// An offset (tool, work) in mm as the program reads or writes it: a length in inches under G20; not
// a length (a rotary axis's degrees, a tool nose tip number) as it is.
double Executor::offset_units(double mm, bool length) const { return length && inch_ ? mm / 25.4 : mm; }
double Executor::offset_mm(double value, bool length) const { return length && inch_ ? value * 25.4 : value; }
bool Executor::is_tip_variable(int n) { return n >= 2301 && n <= 2364; }

// (a look from outside the run: not a read of the program's, so not told to the observer)
nc::Value Executor::variable(int number) { return number >= 1000 ? read_system(number, 0) : read_var(number, 0); }

Value Executor::read_var(int n, std::uint16_t column) {
  if (n >= 1 && n <= 33) return locals_[frames_.empty() ? 0 : frames_.back().level][n - 1];
  if ((n >= 100 && n <= common_high_) || (n >= 500 && n <= 999)) return common_[n];
  if (n == 0) return Value{};
  if (observer_) [[unlikely]] return observed_read(n, column);
  return read_system(n, column);
}

void Executor::write_var(int n, Value v, std::uint16_t column) {
  if (!v.vacant && (!std::isfinite(v.v) || std::fabs(v.v) > 1e47))
    alarm("PS0111", "value out of the range of a macro variable (about 1e47)", column);
  if (observer_) [[unlikely]] return observed_write(n, v, column);
  if (n >= 1 && n <= 33) {
    locals_[frames_.empty() ? 0 : frames_.back().level][n - 1] = v;
    return;
  }
  if ((n >= 100 && n <= common_high_) || (n >= 500 && n <= 999)) {
    common_[n] = v;
    return;
  }
  if (n == 0) alarm("PS0116", "#0 is always vacant and cannot be assigned", column);
  write_system(n, v, column);
}

// Mill offsets by memory type. A: #2001..#2200 and #10001..#10999, one value a number. B: wear
// there, geometry at #2201..#2400 and #11001..#11999. C: those for H, and D wear at #12001..
// #12999, D geometry at #13001..#13999.
double* Executor::mill_offset_field(int n) {
  int k = 0, kind = 0;  // kind: 0 H/shared wear (geometry on A), 1 geometry, 2 D wear, 3 D geometry
  if (n >= 2001 && n <= 2200) k = n - 2000;
  else if (n >= 10001 && n <= 10999) k = n - 10000;
  else if (n >= 2201 && n <= 2400) k = n - 2200, kind = 1;
  else if (n >= 11001 && n <= 11999) k = n - 11000, kind = 1;
  else if (n >= 12001 && n <= 12999) k = n - 12000, kind = 2;
  else if (n >= 13001 && n <= 13999) k = n - 13000, kind = 3;
  else return nullptr;
  const OffsetMemory mem = profile_.offset_memory;
  if (mem == OffsetMemory::A && kind != 0) return nullptr;
  if (mem == OffsetMemory::B && kind >= 2) return nullptr;
  MillOffset& o = tool_offsets_[k];
  switch (kind) {
    case 0: return mem == OffsetMemory::A ? &o.geometry : &o.wear;
    case 1: return &o.geometry;
    case 2: return &o.d_wear;
    default: return &o.d_geometry;
  }
}

double Executor::length_offset(int n) const {
  auto it = tool_offsets_.find(n);
  return it == tool_offsets_.end() ? 0.0 : it->second.geometry + it->second.wear;
}

double Executor::radius_offset(int n) const {
  auto it = tool_offsets_.find(n);
  if (it == tool_offsets_.end()) return 0.0;
  const MillOffset& o = it->second;
  return profile_.offset_memory == OffsetMemory::C ? o.d_geometry + o.d_wear : o.geometry + o.wear;
}

// FANUC T series, 64 offset sets: #2001 X wear, #2101 Z wear, #2201 R wear, #2301 tip,
// #2701 X geometry, #2801 Z geometry, #2901 R geometry (+ offset number - 1).
double* Executor::lathe_offset_field(int n) {
  if (n < 2001 || n > 2964 || (n - 2000) % 100 == 0 || (n - 2000) % 100 > 64) return nullptr;
  LatheOffset& o = lathe_offsets_[(n - 2000) % 100];
  switch ((n - 2001) / 100) {
    case 0: return &o.x_wear;
    case 1: return &o.z_wear;
    case 2: return &o.r_wear;
    case 3: return &o.tip;
    case 7: return &o.x;
    case 8: return &o.z;
    case 9: return &o.r;
    default: return nullptr;
  }
}

Value Executor::read_system(int n, std::uint16_t column) {
  auto axis_order = [&](int k) -> int {  // k-th axis of the profile (0-based) -> internal index
    if (k < 0 || k >= static_cast<int>(profile_.axes.size())) return -1;
    return axis_index(profile_.axes[k]);
  };
  if ((n >= 1000 && n <= 1035) || (n >= 1100 && n <= 1135)) {  // interface signals: no PMC attached
    auto it = system_store_.find(n);
    return it == system_store_.end() ? Value::of(0) : it->second;
  }
  // Offsets are kept in mm and read in the input unit, as G10 sets them and #5001.. read: under G20
  // in inches (the tool nose tip #2301.. is a number).
  if (profile_.lathe()) {
    if (const double* field = lathe_offset_field(n)) return Value::of(offset_units(*field, !is_tip_variable(n)));
  } else if (const double* field = mill_offset_field(n)) {
    return Value::of(offset_units(*field));
  }
  switch (n) {
    case 3000: case 3006: return Value{};
    case 3001: return Value::of(result_.stats.seconds * 1000.0 - clock_base_ms_);
    case 3002: return Value::of(result_.stats.seconds / 3600.0);
    case 3003: case 3004: case 3005: {
      auto it = system_store_.find(n);
      return it == system_store_.end() ? Value::of(0) : it->second;
    }
    case 3011: case 3012: {  // date YYYYMMDD and time HHMMSS (local clock when read)
      std::time_t now = std::time(nullptr);
      std::tm t{};
      localtime_r(&now, &t);
      if (n == 3011) return Value::of((t.tm_year + 1900) * 10000.0 + (t.tm_mon + 1) * 100 + t.tm_mday);
      return Value::of(t.tm_hour * 10000.0 + t.tm_min * 100 + t.tm_sec);
    }
    case 3901: return Value::of(parts_done_);
    case 3902: return Value::of(parts_required_);
    default: break;
  }
  if (n >= 4001 && n <= 4022) return Value::of(modal_code(n - 4000) / 10.0);  // 54.1 for G54.1
  if (n >= 4101 && n <= 4130) {
    switch (n - 4100) {
      case 7: return Value::of(d_);
      case 9: return Value::of(inch_ ? feed_ / 25.4 : feed_);
      case 11: return Value::of(h_);
      case 13: return last_m_ < 0 ? Value{} : Value::of(last_m_);
      case 14: return last_sequence_ < 0 ? Value{} : Value::of(last_sequence_);
      case 15: return Value::of(prog_ && prog_->number >= 0 ? prog_->number : 0);
      case 19: return Value::of(speed_);
      case 20: return Value::of(tool_);
      case 30: return work_index_ > 6 ? Value::of(work_index_ - 6) : Value{};
      default: return Value{};
    }
  }
  if (n >= 5001 && n <= 5106) {
    int block = (n - 5001) / 20;  // 0: end point, 1: machine, 2: current, 3: skip, 4: tool length, 5: servo
    int a = axis_order((n - 5001) % 20);
    if (a < 0) alarm("PS0115", fmt::format("#{}: the machine has no such axis", n), column);
    // the current position (#5021.., #5041..) includes the cutter compensation: the tool centre (the
    // imaginary tip on a lathe) after the last move put out
    const bool offset = comp_ && (comp_->offset_mode() || comp_->tool_position());
    const double now = offset ? comp_->tool_now()[a] : pos_[a];
    switch (block) {
      case 0: return Value::of(program_units(a, xf_on_ ? program_position()[a] : pos_[a]));  // before transforms
      case 2: return Value::of(program_units(a, now));
      case 1: {
        double m = now + origin_[a] + tool_shift_[a];
        return Value::of(program_units(a, m));
      }
      case 3: return Value::of(program_units(a, skip_position_ ? (*skip_position_)[a] : pos_[a]));  // G31 (skip.cpp)
      case 4: return Value::of(program_units(a, tool_shift_[a]));
      default: return Value::of(0);
    }
  }
  if (n >= 5201 && n <= 5326) {
    int set = (n - 5201) / 20;
    int a = axis_order((n - 5201) % 20);
    if (a < 0 || set > 6) alarm("PS0115", fmt::format("#{}: no such work offset variable", n), column);
    return Value::of(offset_units(work_offsets_[set][a], a < 3));
  }
  if (n >= 7001 && n <= 7960) {
    int p = (n - 7001) / 20 + 1;
    int a = axis_order((n - 7001) % 20);
    if (a < 0) alarm("PS0115", fmt::format("#{}: no such work offset variable", n), column);
    auto it = extended_offsets_.find(p);
    const double v = it == extended_offsets_.end() ? 0.0 : it->second[a];
    return Value::of(offset_units(v, a < 3));
  }
  alarm("PS0115", fmt::format("#{} is not a variable of this control", n), column);
}

void Executor::write_system(int n, Value v, std::uint16_t column) {
  auto axis_order = [&](int k) -> int {
    if (k < 0 || k >= static_cast<int>(profile_.axes.size())) return -1;
    return axis_index(profile_.axes[k]);
  };
  if (n == 3000) {
    const double value = v.number();  // (in a wide type: a huge value must not overflow the alarm number)
    const long long code = std::isfinite(value) ? std::llround(std::clamp(value, -1e15, 1e15)) : 0;
    std::string text = block_ && block_->comment >= 0 ? prog_->comments[block_->comment] : "";
    alarm(fmt::format("MC{}", 3000 + code), text.empty() ? "alarm raised by #3000" : text, column);
  }
  if (n == 3006) {
    std::string text = block_ && block_->comment >= 0 ? prog_->comments[block_->comment] : "";
    emit_event(MoveKind::program_stop, 0);
    warn("MC3006", text.empty() ? "stop with message (#3006)" : "stop: " + text, column);
    return;
  }
  if (n >= 1100 && n <= 1135) { system_store_[n] = v; return; }
  // written in the input unit (under G20 inches), kept in mm
  if (profile_.lathe()) {
    if (double* field = lathe_offset_field(n)) {
      *field = offset_mm(v.number(), !is_tip_variable(n));
      return;
    }
  } else if (double* field = mill_offset_field(n)) {
    *field = offset_mm(v.number());
    return;
  }
  switch (n) {
    case 3001: clock_base_ms_ = result_.stats.seconds * 1000.0 - v.number(); return;
    case 3003: case 3004: case 3005: system_store_[n] = v; return;
    case 3901: parts_done_ = v.number(); return;
    case 3902: parts_required_ = v.number(); return;
    default: break;
  }
  if (n >= 5201 && n <= 5326) {
    int set = (n - 5201) / 20;
    int a = axis_order((n - 5201) % 20);
    if (a < 0 || set > 6) alarm("PS0115", fmt::format("#{}: no such work offset variable", n), column);
    work_offsets_[set][a] = offset_mm(v.number(), a < 3);
    set_origin();
    return;
  }
  if (n >= 7001 && n <= 7960) {
    int p = (n - 7001) / 20 + 1;
    int a = axis_order((n - 7001) % 20);
    if (a < 0) alarm("PS0115", fmt::format("#{}: no such work offset variable", n), column);
    extended_offsets_[p][a] = offset_mm(v.number(), a < 3);
    set_origin();
    return;
  }
  if ((n >= 1000 && n <= 1035) || (n >= 3001 && n <= 3012) || (n >= 4001 && n <= 4130) ||
      (n >= 5001 && n <= 5106))
    alarm("PS0116", fmt::format("#{} is read-only", n), column);
  alarm("PS0115", fmt::format("#{} is not a variable of this control", n), column);
}

}  // namespace ncurve::machine
