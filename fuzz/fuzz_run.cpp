// libFuzzer target: any bytes as a program, parsed and run on a mill and a lathe with a step limit;
// the text read in parts must give what reading it in one gives.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "nc/program.hpp"

namespace {

// Programs, blocks, words, code and diagnostics counted, and each block's line and words.
bool same(const ncurve::nc::ParseResult& a, const ncurve::nc::ParseResult& b) {
  if (a.programs.size() != b.programs.size() || a.diagnostics.size() != b.diagnostics.size()) return false;
  for (std::size_t n = 0; n < a.programs.size(); ++n) {
    const auto &p = *a.programs[n], &q = *b.programs[n];
    if (p.blocks.size() != q.blocks.size() || p.words.size() != q.words.size() || p.code.size() != q.code.size() ||
        p.comments != q.comments || p.sequence_index != q.sequence_index)
      return false;
    for (std::size_t i = 0; i < p.blocks.size(); ++i) {
      const auto &x = p.blocks[i], &y = q.blocks[i];
      if (x.line != y.line || x.kind != y.kind || x.words_begin != y.words_begin || x.words_end != y.words_end ||
          x.match != y.match || x.error != y.error || x.value.begin != y.value.begin)
        return false;
    }
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve::machine;
  std::string text(reinterpret_cast<const char*>(data), size);
  {
    auto file = std::make_shared<ncurve::nc::SourceFile>("fuzz.nc", text);
    ncurve::nc::ParseOptions one, parts;
    one.part_bytes = 0;
    parts.part_bytes = 1;
    parts.parts = 3;
    if (!same(ncurve::nc::parse(file, one), ncurve::nc::parse(file, parts))) __builtin_trap();
  }
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
