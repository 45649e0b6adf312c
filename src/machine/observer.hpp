// What the interpreter tells an observer while it runs (the debugger's execution trace): each
// block as it starts, each call and return, each variable written, each system variable read. Off
// (no observer) it costs a test of one pointer per block, per variable write and per system
// variable read.
#pragma once
#include <array>
#include <cstdint>

#include "nc/program.hpp"
#include "nc/value.hpp"

namespace ncurve::machine {

// One level of the call stack: the main program, an M98 subprogram (its locals are its caller's),
// or a macro (G65, G66, a custom G or M code) with locals of its own.
struct CallFrame {
  enum Kind : std::uint8_t { main, subprogram, macro } kind = main;
  int program = -1;                       // O number (-1: a file without one)
  std::int32_t level = 0;                 // local variable level: 0 the main program's, +1 a macro call
  bool custom = false;                    // called by a custom G/M code or the T code
  bool modal = false;                     // called by G66
  const nc::SourceFile* call_file = nullptr;  // the calling block (none for the main program)
  std::uint32_t call_line = 0;
};

// The modal state as the program reads it: #4001..#4022 (the modal G codes of groups 1 to 22)
// and the words D, F, H, M, S, T (#4107, #4109, #4111, #4113, #4119, #4120); vacant where the
// control gives no value.
inline constexpr std::array<int, 28> kModalVariables = {
    4001, 4002, 4003, 4004, 4005, 4006, 4007, 4008, 4009, 4010, 4011, 4012, 4013, 4014,
    4015, 4016, 4017, 4018, 4019, 4020, 4021, 4022, 4107, 4109, 4111, 4113, 4119, 4120};
using ModalReadout = std::array<nc::Value, kModalVariables.size()>;

// The tool offsets in force as a block starts (the debugger's tool at the step): on a mill the D
// offset and its cutter radius and the H offset's length; on a lathe the offset set, its nose
// radius and tip. Geometry plus wear, mm.
struct ToolInForce {
  std::int32_t offset = 0;  // D (mill) or the offset set of the T code (lathe)
  double radius = 0;        // D's cutter radius (mill) or the nose radius (lathe)
  double length = 0;        // H's length (mill)
  std::int32_t tip = 0;     // the imaginary tip 0..9 (lathe)
  bool operator==(const ToolInForce&) const = default;
};

class ExecutionObserver {
public:
  virtual ~ExecutionObserver() = default;
  // A block starts: `moves` moves were delivered before it, `modal` is the state it starts in.
  virtual void block(const nc::Program& program, const nc::Block& block, std::uint64_t moves,
                     const ModalReadout& modal) = 0;
  // The tool offsets in force for the block about to start (told before each block and before
  // finished()).
  virtual void tool(const ToolInForce& /*in_force*/) {}
  // A call pushed this frame (during the calling block); a macro's level starts all vacant, and
  // its arguments follow as variable writes.
  virtual void entered(const CallFrame& frame) = 0;
  // A return popped the innermost frame.
  virtual void left() = 0;
  // Variable #number was written (level: the local level for #1..#33, -1 otherwise).
  virtual void variable(int number, std::int32_t level, nc::Value old, nc::Value now) = 0;
  // The program read system variable #number (not a local or common) and got `value`.
  virtual void read(int /*number*/, nc::Value /*value*/) {}
  // The run ended (completed or alarmed) after `moves` moves, in this modal state.
  virtual void finished(std::uint64_t moves, const ModalReadout& modal) = 0;
};

}  // namespace ncurve::machine
