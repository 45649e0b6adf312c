// Macro variables: locals and commons, the modal codes #4001..#4022 read, positions in program units
// (system variables: system_variables.cpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "machine/g_codes.hpp"
#include "machine/executor.hpp"

namespace ncurve::machine {

using nc::Value;


// The code (x10) in force in modal group `group`, as #4001..#4022 read it: from the state ncurve
// keeps, each code's group taken from the G-code table (the lathe's groups differ from the mill's);
// the table's power-on code for a group ncurve does not change; 0 for a group the control lacks.
int Executor::modal_code(int group) const {
  const GMachine m = g_machine(profile_);
  if (group == 1) return modal_.motion * 10;  // G60 too, modal with No.5431#0 MDL = 1
  if (group == 3 && m == kLatheA) return modal_.incremental ? 910 : 900;
  const int work = modal_.work_index > 6 ? 541 : 530 + 10 * modal_.work_index;
  const int state[] = {
      modal_.plane * 10,
      modal_.incremental ? 910 : 900,
      m == kLatheA ? (modal_.feed_per_rev ? 990 : 980) : (modal_.feed_per_rev ? 950 : 940),  // before the return level
      m == kLatheC ? (modal_.inch ? 700 : 710) : (modal_.inch ? 200 : 210),
      modal_.comp_side > 0 ? 410 : modal_.comp_side < 0 ? 420 : 400,
      modal_.length_comp * 10,
      modal_.stroke2_on ? 220 : 230,
      modal_.cycle == 0 ? 800 : modal_.cycle * 10,
      modal_.cycle_return_initial ? 980 : 990,
      modal_.css ? 960 : 970,
      modal_.speed_fluctuation_check ? 260 : 250,
      modal_.modal_call ? 660 : 670,
      work,
      modal_.exact_stop_code == 611 ? 611 : modal_.exact_stop_code * 10,
      developed_ && dev_->polar ? 121 : 131,
      xf_.scaling ? 510 : 500,
      xf_.rotating ? 680 : 690,
      modal_.polar ? 160 : 150,
      xf_.mirroring() ? 511 : 501,
  };
  for (const int g : state)
    if (g_group(g, m) == group) return g;
  return g_initial(group, m);
}

double Executor::program_units(int axis, double mm) const {
  double v = mm;
  if (axis == 0 && profile_.lathe() && profile_.diameter_x) v *= 2;
  if (modal_.inch && axis < 3) v /= 25.4;
  return v;
}

// An offset (tool, work) in mm as the program reads or writes it: a length in inches under G20; not
// a length (a rotary axis's degrees, a tool nose tip number) as it is.
double Executor::offset_units(double mm, bool length) const { return length && modal_.inch ? mm / 25.4 : mm; }
double Executor::offset_mm(double value, bool length) const { return length && modal_.inch ? value * 25.4 : value; }
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

}  // namespace ncurve::machine
