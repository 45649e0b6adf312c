// libFuzzer target: any bytes as a program, parsed and run with a step limit on a mill or a lathe
// (the first byte's lowest bit) whose offsets carry cutter and nose radii (D1..D9, lathe offsets 1..9
// with a nose radius and an imaginary tip), so that G41/G42 compensation runs; every move goes to
// the CSV, JSON Lines and G-code writers at once, writing to memory; on the mill every move is
// also cut into a small Z-map by a verifier with a tool in a holder and a clamp to meet.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "report/writers.hpp"
#include "sim/verifier.hpp"

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

// A 200 x 200 x 50 block on 100 x 100 cells, T1 a ball in a holder, a clamp beside the block.
const char* const kSetup = R"(tool_in_spindle = 1
[stock]
shape = "box"
min = [-100, -100, -50]
max = [100, 100, 0]
[[fixtures]]
name = "clamp"
shape = "box"
min = [100, -20, -50]
max = [130, 20, 10]
[tools.1]
kind = "ball"
diameter = 8
flute_length = 16
stick_out = 30
shank_diameter = 10
holder = [{ diameter = 30, length = 20 }, { diameter = [30, 40], length = 10 }]
)";

struct AllWriters final : machine::MoveSink {
  std::ostringstream csv_text, jsonl_text, gcode_text;
  report::CsvWriter csv;
  report::JsonlWriter jsonl;
  report::GcodeWriter gcode;
  machine::MoveSink* verify = nullptr;
  explicit AllWriters(const machine::MachineProfile& p)
      : csv(csv_text, p, 0.001), jsonl(jsonl_text, p), gcode(gcode_text, p, "fuzz.nc") {}
  void on_move(const machine::Move& m) override {
    if (verify) verify->on_move(m);
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
  static const sim::SetupFile setup = sim::parse_setup(kSetup, "fuzz.setup.toml");
  sim::MillTools tools(setup.tools, profile);
  sim::VerifyOptions vo;
  vo.min_cells = 100;
  vo.profile = &profile;
  std::optional<sim::Verifier> verifier;
  if (!profile.lathe()) {
    verifier.emplace(*setup.stock, tools, setup.tool_in_spindle, vo, setup.fixtures);
    sink.verify = &*verifier;
  }
  try {
    machine::RunResult result = interp.run(sink);
    if (result.alarm) sink.stopped(*result.alarm);
  } catch (const AllWriters::Enough&) {
  }
  sink.gcode.finish();
  return 0;
}
