// libFuzzer target: any bytes as a program, parsed and run on a mill and a lathe with a step limit.
#include <cstddef>
#include <cstdint>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve::machine;
  std::string text(reinterpret_cast<const char*>(data), size);
  ProgramLibrary lib;
  try {
    lib.add_text("fuzz.nc", text, true);
  } catch (const std::runtime_error&) {
    return 0;  // no program in the file: reported, not a crash
  }
  MachineProfile profile = size > 0 && (data[0] & 1) ? default_lathe() : default_mill();
  profile.g_code_macros[0] = 102;
  profile.m_code_macros[0] = 50;
  RunOptions options;
  options.max_steps = 20000;
  Interpreter interp(profile, lib, options);
  NullSink sink;
  interp.run(sink);
  return 0;
}
