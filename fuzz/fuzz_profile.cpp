// libFuzzer target: any bytes as a machine profile (TOML, src/machine/profile.cpp); a profile that
// loads runs a short program touching its settings (offsets and cutter compensation, arcs and their
// radius check, a drilling cycle, a macro call, work offsets) to the CSV writer, in memory.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "report/writers.hpp"

namespace {

constexpr const char* kMill =
    "O1000\nG90 G17 G21 G54 G00 X0 Y0 Z5.\nT1 M06\nG43 H1 Z2.\nG41 D1 G01 X10. Y5. F300\nG02 X20. Y5. R5.\n"
    "G03 X10. Y5. I-5. J0\nG40 G01 X0 Y0\nG81 X5. Y5. Z-2. R1. F100\nG80\nG65 P9010 A1.\nG04 P100\nM30\n"
    "O9010\n#100=#1*2\nM99\n";
constexpr const char* kLathe =
    "O1000\nG21 G18 G00 X50. Z5.\nT0101\nG42 G01 X40. Z0 F0.2\nG02 X40. Z-20. R15.\nG40 G00 X60. Z5.\nM30\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve;
  const std::string text(reinterpret_cast<const char*>(data), size);
  machine::MachineProfile profile;
  try {
    profile = machine::parse_profile(text, "fuzz.toml");
  } catch (const std::runtime_error&) {
    return 0;  // refused with a message
  }
  machine::ProgramLibrary lib(profile.parse_options());
  try {
    lib.add_text("fuzz.nc", profile.lathe() ? kLathe : kMill, true);
  } catch (const std::runtime_error&) {
    return 0;
  }
  machine::RunOptions options;
  options.max_steps = 2000;
  machine::Interpreter interp(profile, lib, options);
  std::ostringstream out;
  report::CsvWriter csv(out, profile, 0.01);  // (a few arcs: at most 100,000 rows each)
  machine::RunResult result = interp.run(csv);
  if (result.alarm) csv.stopped(*result.alarm);
  return 0;
}
