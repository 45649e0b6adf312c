// libFuzzer target: any bytes as a program, run read whole and read as a stream in pieces of a few
// bytes (the first byte sets how many); the two must give the same problems, moves, alarm and
// warnings, or the target aborts.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"

namespace {
using namespace ncurve;

struct Lines final : machine::MoveSink {
  std::string out;
  void on_move(const machine::Move& m) override {
    out += fmt::format("{} {} {} {} {}\n", static_cast<int>(m.kind), m.line, m.end[0], m.end[1], m.end[2]);
  }
};

std::string shown(machine::ProgramLibrary& lib, std::vector<nc::Diagnostic> problems) {
  Lines moves;
  machine::RunOptions options;
  options.max_steps = 20000;
  machine::Interpreter interp(machine::default_mill(), lib, options);
  const machine::RunResult r = interp.run(moves);
  if (lib.streamed()) problems = lib.streamed_problems();
  std::string out;
  for (const auto& d : problems) out += nc::format(d) + "\n";
  out += fmt::format("{} {}\n", lib.problems_left_out(), lib.unchecked_lines()) + moves.out;
  if (r.alarm) out += nc::format(*r.alarm) + "\n";
  for (const auto& w : r.warnings) out += nc::format(w) + "\n";
  return out + fmt::format("{}\n", r.stats.blocks);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t chunk = 1 + data[0] % 64;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  struct TempFile {
    std::string path = fmt::format("/tmp/fuzz_stream_{}.nc", ::getpid());
    ~TempFile() { std::remove(path.c_str()); }
  };
  static const TempFile file;
  const std::string& path = file.path;
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << text;
  }
  std::string whole, streamed;
  try {
    machine::ProgramLibrary lib;
    whole = shown(lib, lib.add_text(path, text, true));
  } catch (const std::exception& e) {
    whole = std::string("refused: ") + e.what();
  }
  try {
    machine::ProgramLibrary lib;
    lib.add_streamed(path, path, chunk);
    streamed = shown(lib, {});
  } catch (const std::exception& e) {
    streamed = std::string("refused: ") + e.what();
  }
  if (whole != streamed) {
    std::fprintf(stderr, "read whole:\n%s\nstreamed in %zu-byte pieces:\n%s\n", whole.c_str(), chunk, streamed.c_str());
    std::abort();
  }
  return 0;
}
