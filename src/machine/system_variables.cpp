// System variables (#1000 and up) as a FANUC control numbers them: one table of ranges says what
// each is and whether a program may read and write it; reads and writes both go by it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ctime>

#include "machine/executor.hpp"

namespace ncurve::machine {

using nc::Value;

namespace {

enum class SystemKind : std::uint8_t {
  input_signals, output_signals, alarm, clock_ms, clock_hours, stored, message_stop, unsimulated, date_time,
  parts_done, parts_required, modal_codes, unsimulated_modal, modal_words, positions, work_offsets,
  extended_offsets,
};

struct SystemRange {
  int first, last;
  SystemKind kind;
  bool readable;  // else reading it is PS0115, as for a number the control lacks
  bool writable;  // else writing it is PS0116 (read-only)
};

// The tool offsets (#2001.., #10001..) are not here: their numbers depend on the machine and the
// offset memory (mill_offset_field, lathe_offset_field).
constexpr SystemRange kSystemRanges[] = {
    {1000, 1035, SystemKind::input_signals, true, false},   // interface signals: no PMC attached
    {1100, 1135, SystemKind::output_signals, true, true},
    {3000, 3000, SystemKind::alarm, true, true},
    {3001, 3001, SystemKind::clock_ms, true, true},
    {3002, 3002, SystemKind::clock_hours, true, false},
    {3003, 3005, SystemKind::stored, true, true},           // single block, feed hold / override switches
    {3006, 3006, SystemKind::message_stop, true, true},
    {3007, 3010, SystemKind::unsimulated, false, false},
    {3011, 3012, SystemKind::date_time, true, false},
    {3901, 3901, SystemKind::parts_done, true, true},
    {3902, 3902, SystemKind::parts_required, true, true},
    {4001, 4022, SystemKind::modal_codes, true, false},
    {4023, 4100, SystemKind::unsimulated_modal, false, false},
    {4101, 4130, SystemKind::modal_words, true, false},
    {5001, 5106, SystemKind::positions, true, false},
    {5201, 5326, SystemKind::work_offsets, true, true},
    {7001, 7960, SystemKind::extended_offsets, true, true},
};

const SystemRange* system_range(int n) {
  for (const SystemRange& r : kSystemRanges)
    if (n >= r.first && n <= r.last) return &r;
  return nullptr;
}

}  // namespace

int Executor::axis_of_order(int k) const {
  if (k < 0 || k >= static_cast<int>(profile_.axes.size())) return -1;
  return axis_index(profile_.axes[k]);
}

Value Executor::read_system(int n, std::uint16_t column) {
  // Offsets are kept in mm and read in the input unit, as G10 sets them and #5001.. read: under G20
  // in inches (the tool nose tip #2301.. is a number).
  if (profile_.lathe()) {
    if (const double* field = lathe_offset_field(n)) return Value::of(offset_units(*field, !is_tip_variable(n)));
  } else if (const double* field = mill_offset_field(n)) {
    return Value::of(offset_units(*field));
  }
  const SystemRange* range = system_range(n);
  if (!range || !range->readable) alarm("PS0115", fmt::format("#{} is not a variable of this control", n), column);
  switch (range->kind) {
    case SystemKind::input_signals: case SystemKind::output_signals: case SystemKind::stored: {
      auto it = system_store_.find(n);
      return it == system_store_.end() ? Value::of(0) : it->second;
    }
    case SystemKind::alarm: case SystemKind::message_stop: return Value{};
    case SystemKind::clock_ms: return Value::of(result_.stats.seconds * 1000.0 - clock_base_ms_);
    case SystemKind::clock_hours: return Value::of(result_.stats.seconds / 3600.0);
    case SystemKind::date_time: {  // date YYYYMMDD and time HHMMSS (local clock when read)
      std::time_t now = std::time(nullptr);
      std::tm t{};
      localtime_r(&now, &t);
      if (n == 3011) return Value::of((t.tm_year + 1900) * 10000.0 + (t.tm_mon + 1) * 100 + t.tm_mday);
      return Value::of(t.tm_hour * 10000.0 + t.tm_min * 100 + t.tm_sec);
    }
    case SystemKind::parts_done: return Value::of(parts_done_);
    case SystemKind::parts_required: return Value::of(parts_required_);
    case SystemKind::modal_codes: return Value::of(modal_code(n - 4000) / 10.0);  // 54.1 for G54.1
    case SystemKind::modal_words:
      switch (n - 4100) {
        case 7: return Value::of(d_);
        case 9: return Value::of(modal_.inch ? feed_ / 25.4 : feed_);
        case 11: return Value::of(h_);
        case 13: return last_m_ < 0 ? Value{} : Value::of(last_m_);
        case 14: return last_sequence_ < 0 ? Value{} : Value::of(last_sequence_);
        case 15: return Value::of(prog_ && prog_->number >= 0 ? prog_->number : 0);
        case 19: return Value::of(speed_);
        case 20: return Value::of(tool_);
        case 30: return modal_.work_index > 6 ? Value::of(modal_.work_index - 6) : Value{};
        default: return Value{};
      }
    case SystemKind::positions: {
      int block = (n - 5001) / 20;  // 0: end point, 1: machine, 2: current, 3: skip, 4: tool length, 5: servo
      int a = axis_of_order((n - 5001) % 20);
      if (a < 0) alarm("PS0115", fmt::format("#{}: the machine has no such axis", n), column);
      // the current position (#5021.., #5041..) includes the cutter compensation: the tool centre (the
      // imaginary tip on a lathe) after the last move put out
      const bool offset = comp_ && (comp_->offset_mode() || comp_->tool_position());
      const double now = offset ? comp_->tool_now()[a] : coords_.pos[a];
      switch (block) {
        case 0: return Value::of(program_units(a, xf_on_ ? program_position()[a] : coords_.pos[a]));  // before transforms
        case 2: return Value::of(program_units(a, now));
        case 1: return Value::of(program_units(a, now + coords_.origin[a] + coords_.tool_shift[a]));
        case 3: return Value::of(program_units(a, skip_position_ ? (*skip_position_)[a] : coords_.pos[a]));  // G31 (skip.cpp)
        case 4: return Value::of(program_units(a, coords_.tool_shift[a]));
        default: return Value::of(0);
      }
    }
    case SystemKind::work_offsets: {
      int set = (n - 5201) / 20;
      int a = axis_of_order((n - 5201) % 20);
      if (a < 0 || set > 6) alarm("PS0115", fmt::format("#{}: no such work offset variable", n), column);
      return Value::of(offset_units(coords_.work_offsets[set][a], a < 3));
    }
    case SystemKind::extended_offsets: {
      int a = axis_of_order((n - 7001) % 20);
      if (a < 0) alarm("PS0115", fmt::format("#{}: no such work offset variable", n), column);
      auto it = coords_.extended.find((n - 7001) / 20 + 1);
      const double v = it == coords_.extended.end() ? 0.0 : it->second[a];
      return Value::of(offset_units(v, a < 3));
    }
    default: break;
  }
  alarm("PS0115", fmt::format("#{} is not a variable of this control", n), column);
}

void Executor::write_system(int n, Value v, std::uint16_t column) {
  const SystemRange* range = system_range(n);
  if (range && range->kind == SystemKind::alarm) {
    const double value = v.number();  // (in a wide type: a huge value must not overflow the alarm number)
    const long long code = std::isfinite(value) ? std::llround(std::clamp(value, -1e15, 1e15)) : 0;
    std::string text = block_ && block_->comment >= 0 ? unit_->comments[block_->comment] : "";
    alarm(fmt::format("MC{}", 3000 + code), text.empty() ? "alarm raised by #3000" : text, column);
  }
  if (range && range->kind == SystemKind::message_stop) {
    std::string text = block_ && block_->comment >= 0 ? unit_->comments[block_->comment] : "";
    emit_event(MoveKind::program_stop, 0);
    warn("MC3006", text.empty() ? "stop with message (#3006)" : "stop: " + text, column);
    return;
  }
  if (range && range->kind == SystemKind::output_signals) {
    system_store_[n] = v;
    return;
  }
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
  if (!range) alarm("PS0115", fmt::format("#{} is not a variable of this control", n), column);
  if (!range->writable) alarm("PS0116", fmt::format("#{} is read-only", n), column);
  switch (range->kind) {
    case SystemKind::clock_ms: clock_base_ms_ = result_.stats.seconds * 1000.0 - v.number(); return;
    case SystemKind::stored: system_store_[n] = v; return;
    case SystemKind::parts_done: parts_done_ = v.number(); return;
    case SystemKind::parts_required: parts_required_ = v.number(); return;
    case SystemKind::work_offsets: {
      int set = (n - 5201) / 20;
      int a = axis_of_order((n - 5201) % 20);
      if (a < 0 || set > 6) alarm("PS0115", fmt::format("#{}: no such work offset variable", n), column);
      coords_.work_offsets[set][a] = offset_mm(v.number(), a < 3);
      set_origin();
      return;
    }
    case SystemKind::extended_offsets: {
      int a = axis_of_order((n - 7001) % 20);
      if (a < 0) alarm("PS0115", fmt::format("#{}: no such work offset variable", n), column);
      coords_.extended[(n - 7001) / 20 + 1][a] = offset_mm(v.number(), a < 3);
      set_origin();
      return;
    }
    default: break;
  }
  alarm("PS0115", fmt::format("#{} is not a variable of this control", n), column);
}

}  // namespace ncurve::machine
