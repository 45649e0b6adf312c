// libFuzzer target: any bytes as a setup file (TOML, src/sim/setup*): the reader refuses it with a
// message or reads it; a setup read gives its defaults in words and its tools' default box on a
// short list of moves, and a cylinder or tube stock is cut as a lathe's half-section by up to four of
// its tools on a line, a G18 arc and a facing cut past the centre, then revolved.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "machine/move.hpp"
#include "sim/lathe_section.hpp"
#include "sim/lathe_section_sink.hpp"
#include "sim/setup.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve;
  const std::string text(reinterpret_cast<const char*>(data), size);
  sim::SetupFile setup;
  try {
    setup = sim::parse_setup(text, "fuzz.setup.toml");
  } catch (const std::runtime_error&) {
    return 0;  // refused with a message
  }
  (void)sim::setup_defaults(&setup);
  std::vector<machine::Move> moves(3);
  moves[0].kind = machine::MoveKind::tool_change;
  moves[0].code = setup.tool_in_spindle.value_or(1);
  moves[1].kind = machine::MoveKind::line;
  moves[1].start = {0, 0, 5};
  moves[1].end = {10, 0, -2};
  moves[2].kind = machine::MoveKind::arc;
  moves[2].plane = 17;
  moves[2].start = {10, 0, -2};
  moves[2].end = {0, 10, -2};
  moves[2].center = {0, 0, -2};
  moves[2].sweep = 1.5707963267948966;
  (void)sim::default_stock_box(moves, [](int t) { return t > 0 ? 0.5 * t : 0.0; });
  if (const auto* bar = setup.stock ? std::get_if<sim::Cylinder>(&*setup.stock) : nullptr) {
    sim::LatheSection section(*bar);
    sim::LatheSectionSink sink(section, setup.tools);
    const double r = bar->diameter / 2, face = bar->face;
    int tools = 0;
    for (const auto& [number, tool] : setup.tools.tools) {
      if (++tools > 4) break;
      machine::Move m;
      m.kind = machine::MoveKind::tool_change;
      m.code = number <= 20'000'000 ? number * 100 + 1 : 1;
      sink.on_move(m);
      m.kind = machine::MoveKind::line;
      m.start = {r + 2, 0, face + 2};
      m.end = {0.8 * r, 0, face - 0.3 * bar->length};
      sink.on_move(m);
      m.kind = machine::MoveKind::arc;
      m.plane = 18;
      m.start = m.end;
      m.end = {0.8 * r, 0, face - 0.6 * bar->length};
      m.center = {0.8 * r, 0, face - 0.45 * bar->length};
      m.sweep = -3.141592653589793;
      sink.on_move(m);
      m.kind = machine::MoveKind::line;
      m.start = {r + 2, 0, face - 1};
      m.end = {-2, 0, face - 1};
      sink.on_move(m);
    }
    (void)section.volume_removed();
    (void)sink.volume_by_tool();
    (void)section.outer_radius(face - 0.5 * bar->length);
    (void)section.mesh(16);
  }
  return 0;
}
