// libFuzzer target: any bytes as a setup file (TOML, src/sim/setup*): the reader refuses it with a
// message or reads it; a setup read gives its defaults in words and its tools' default box on a
// short list of moves.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "machine/move.hpp"
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
  return 0;
}
