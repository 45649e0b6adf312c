// What the interpreter emits: moves and machine events, each tied to its source block.
#pragma once
#include <cstdint>
#include <span>

#include "machine/profile.hpp"
#include "nc/diagnostic.hpp"

namespace ncurve::machine {

enum class MoveKind : std::uint8_t {
  rapid, line, arc, dwell,
  tool_change, spindle, coolant, program_stop, program_end, m_code,
};

const char* to_string(MoveKind k);

// The two in-plane axes of G17/G18/G19 (p to q is counter-clockwise about the plane normal), the
// normal axis, and the letters of the centre offsets along p and q.
struct PlaneAxes {
  int p, q, n;
  char ip, iq;
};
PlaneAxes plane_axes(int plane);

// The fields are ordered by size, with no padding between them but at the end: a Move is 256
// bytes, which the compiler copies with vector moves (a larger one with a string copy instruction).
struct Move {
  MoveKind kind = MoveKind::line;
  std::uint8_t plane = 17;     // 17 XY, 18 ZX, 19 YZ
  bool clockwise = false;      // arcs: G02
  bool feed_per_rev = false;   // F in mm/rev
  bool threading = false;      // a thread cut (G32/G92/G76): feed is the lead in mm/rev, held at 100 % (no override)
  bool exact_stop = false;     // G61 modal or G09 in the block: the feed comes to zero at the block end
  bool lookahead = true;       // look-ahead mode (G05.1 Q1, G08 P1, ...): the feed carries on into the next block
  bool compensated = false;    // a cutter / tool-nose radius compensated move: end is the tool centre (tip)
  bool corner = false;         // an extra move the compensation inserts at a corner
  int code = 0;                // T number, M code, spindle or coolant M code
  std::uint32_t macro_statements = 0;  // macro statements executed since the previous event (for the time planner)
  std::uint32_t nc_blocks = 0;         // NC blocks read since the previous event, this one included
  std::int32_t thread_start = -1;      // threading: spindle angle (Q, 0.001 deg) after the one-rotation signal;
                                       // -1: the cut continues the one before
  std::int32_t d_offset = 0;   // the D offset number in force (a mill's cutter radius)
  int program = -1;            // O number of the program holding the block
  std::uint32_t line = 0;      // 1-based line in file
  AxisVector start{};          // work coordinates, mm (lathe X as a radius), degrees for rotary axes
  AxisVector end{};
  AxisVector programmed_end{}; // compensated moves: the end point as programmed
  std::array<double, 3> center{};  // arcs: centre, work coordinates X Y Z
  double sweep = 0;            // arcs: signed angle in radians, counter-clockwise positive about the plane normal
  double feed = 0;             // mm/min, or mm/rev when feed_per_rev
  double spindle = 0;          // S in force, rev/min (or m/min under G96)
  double seconds = 0;          // dwell time; estimated time for other moves
  double length = 0;           // path length, mm
  const nc::SourceFile* file = nullptr;

  bool is_motion() const { return kind == MoveKind::rapid || kind == MoveKind::line || kind == MoveKind::arc; }
};
static_assert(sizeof(Move) <= 256, "a Move past 256 bytes is copied by a string instruction: see its field order");

// Where the moves after it are: the work coordinate system and tool length offset in force. An
// expanded program sets these up to put its moves at the same machine positions.
struct Setup {
  int work = 1;          // 1..6 = G54..G59, 7+ = G54.1 P(work - 6)
  AxisVector origin{};   // machine coordinates of the work zero: work offset, external, G52, G92
  int length_comp = 49;  // 43, 44, 49
  int h = 0;             // the H offset number of G43/G44
  bool operator==(const Setup&) const = default;
};

class MoveSink {
public:
  virtual ~MoveSink() = default;
  virtual void on_move(const Move& m) = 0;
  // Moves in order, as on_move one by one (a writer may write them at once).
  virtual void on_moves(std::span<const Move> moves) {
    for (const Move& m : moves) on_move(m);
  }
  // Before the first move and before any move whose Setup differs from the one before.
  virtual void on_setup(const Setup&) {}
  // The run stopped on this alarm after the last move: a writer marks its output as cut off.
  virtual void stopped(const nc::Diagnostic&) {}
};

class NullSink final : public MoveSink {
public:
  void on_move(const Move&) override {}
};

}  // namespace ncurve::machine
