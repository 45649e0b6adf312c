// Test helper: runs program text and keeps every move.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"

namespace ncurve::test {

class Collect final : public machine::MoveSink {
public:
  void on_move(const machine::Move& m) override { moves.push_back(m); }
  std::vector<machine::Move> moves;
};

struct Ran {
  std::unique_ptr<machine::ProgramLibrary> lib;
  std::unique_ptr<machine::Interpreter> interp;
  machine::RunResult result;
  std::vector<nc::Diagnostic> parse;
  std::vector<machine::Move> moves;

  std::vector<machine::Move> motions() const {
    std::vector<machine::Move> out;
    for (const auto& m : moves)
      if (m.is_motion()) out.push_back(m);
    return out;
  }
  double var(int n) const { return interp->variable(n).number(); }
  bool vacant(int n) const { return interp->variable(n).vacant; }
  std::string alarm_code() const { return result.alarm ? result.alarm->code : ""; }
  std::uint32_t alarm_line() const { return result.alarm ? result.alarm->span.line : 0; }
};

// The tests' mill: the factory-parameter mill with every work offset 0, so that it powers on with the
// tool at the work zero (reference position 1 at machine zero), as the values worked by hand in the
// tests assume. The shipped mill (machine::default_mill()) has its G54 below machine zero.
inline machine::MachineProfile zero_offset_mill() {
  machine::MachineProfile p = machine::default_mill();
  p.work_offsets = {};
  return p;
}

inline Ran run(const std::string& text, machine::MachineProfile profile = zero_offset_mill(),
               machine::RunOptions options = {}, const std::map<std::string, std::string>& library = {},
               const std::vector<std::string>& folders = {}) {
  Ran r;
  r.lib = std::make_unique<machine::ProgramLibrary>();
  r.parse = r.lib->add_text("test.nc", text, true);
  for (const auto& [name, body] : library) r.lib->add_text(name, body);
  for (const auto& f : folders) r.lib->add_folder(f);
  r.interp = std::make_unique<machine::Interpreter>(profile, *r.lib, options);
  Collect sink;
  r.result = r.interp->run(sink);
  r.moves = std::move(sink.moves);
  return r;
}

inline machine::MachineProfile calculator_mill() {
  auto p = machine::default_mill();
  p.decimal_calculator = true;
  return p;
}

}  // namespace ncurve::test
