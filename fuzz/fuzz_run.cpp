// libFuzzer target: any bytes as a program, parsed and run with a step limit on a mill or a lathe
// (the first byte's lowest bit) whose offsets carry cutter and nose radii (D1..D9, lathe offsets 1..9
// with a nose radius and an imaginary tip), so that G41/G42 compensation runs; every move goes to
// the CSV, JSON Lines and G-code writers at once, writing to memory.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "report/writers.hpp"

namespace {

using namespace ncurve;

machine::MachineProfile fuzz_profile(bool lathe) {
  machine::MachineProfile p = lathe ? machine::default_lathe() : machine::default_mill();
  p.g_code_macros[0] = 102;
  p.m_code_macros[0] = 50;
  for (int n = 1; n <= 9; ++n) {
    p.tool_offsets[n].geometry = 0.5 * n;   // D n and H n: 0.5 .. 4.5 mm
    p.tool_offsets[n].wear = -0.01 * n;
    p.tool_offsets[n].d_geometry = 0.75 * n;
    machine::LatheOffset& o = p.lathe_offsets[n];
    o.r = 0.2 * n;  // nose radius 0.2 .. 1.8 mm, tip 1 .. 9
    o.tip = n;
    o.x = 0.5 * n;
    o.z = -0.25 * n;
    o.r_wear = 0.01;
  }
  return p;
}

struct AllWriters final : machine::MoveSink {
  std::ostringstream csv_text, jsonl_text, gcode_text;
  report::CsvWriter csv;
  report::JsonlWriter jsonl;
  report::GcodeWriter gcode;
  explicit AllWriters(const machine::MachineProfile& p)
      : csv(csv_text, p, 0.001), jsonl(jsonl_text, p), gcode(gcode_text, p, "fuzz.nc") {}
  void on_move(const machine::Move& m) override {
    csv.on_move(m);
    jsonl.on_move(m);
    gcode.on_move(m);
    // the output of a run is as long as its moves make it (an arc: up to 100,000 CSV rows): 16 MB
    // is enough to have exercised the writers
    if (csv_text.tellp() > (16 << 20)) throw Enough{};
  }
  struct Enough {};
  void stopped(const nc::Diagnostic& alarm) override {
    csv.stopped(alarm);
    jsonl.stopped(alarm);
    gcode.stopped(alarm);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const machine::MachineProfile mill = fuzz_profile(false), lathe = fuzz_profile(true);
  std::string text(reinterpret_cast<const char*>(data), size);
  const machine::MachineProfile& profile = size > 0 && (data[0] & 1) ? lathe : mill;
  machine::ProgramLibrary lib(profile.parse_options());
  try {
    lib.add_text("fuzz.nc", text, true);
  } catch (const std::runtime_error&) {
    return 0;  // no program in the file: reported, not a crash
  }
  machine::RunOptions options;
  options.max_steps = 20000;
  machine::Interpreter interp(profile, lib, options);
  AllWriters sink(profile);
  try {
    machine::RunResult result = interp.run(sink);
    if (result.alarm) sink.stopped(*result.alarm);
  } catch (const AllWriters::Enough&) {
  }
  sink.gcode.finish();
  return 0;
}
