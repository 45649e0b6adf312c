// Cutter radius compensation C and tool-nose radius compensation (G40/G41/G42) as FANUC controls
// do it: the programmed moves of the offset plane come in, in program order, and the tool-centre
// moves go out once the next move is known (the read-ahead), with the vectors of start-up, corners
// and cancel of the FANUC manuals' "Details of cutter compensation C".
#pragma once
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geom/plane.hpp"
#include "machine/move.hpp"
#include "machine/profile.hpp"

namespace ncurve::machine {

struct CompensationSettings {
  bool startup_type_b = false;  // No.5003#0 SUP: start-up and cancel of type B (intersection), else type A
  bool startup_type_c = false;  // No.5003#1 SUV: a G41/G42 or G40 block without motion shifts the tool itself
  int blocks_without_motion = 1;  // blocks without motion in the plane the read-ahead passes over
  bool interference_check = true;  // No.5008#1 CNC = 0
  double corner_vector_limit = 0;  // No.5010, mm: an outer-corner vector shorter than this is left out
};

using geom::V2;  // a point of the offset plane

class RadiusCompensation {
public:
  using Deliver = std::function<void(Move&)>;
  // Raises the alarm at the block of `at` (the callback throws).
  using Alarm = std::function<void(const Move& at, const std::string& code, const std::string& message)>;
  using Warn = std::function<void(const Move& at, const std::string& code, const std::string& message)>;

  RadiusCompensation(CompensationSettings settings, Deliver deliver, Alarm alarm, Warn warn)
      : settings_(settings), deliver_(std::move(deliver)), alarm_(std::move(alarm)), warn_(std::move(warn)) {}

  // A move in the offset plane. side: +1 G41 (tool left of the path), -1 G42, 0 the cancel block
  // (G40). radius: the offset in force. cancel_direction: I J K of a G40 block, in the plane.
  void element(const Move& programmed, int side, double radius, std::optional<V2> cancel_direction = {});
  // A move without motion in the plane, or an event: it happens where the tool centre is.
  void other(const Move& m);
  // An NC block without motion in the plane, which the read-ahead must pass to find the next move.
  void block_without_motion(const Move& at);
  // G41/G42 from cancel mode in a block without motion in the plane (`at`: that block, its modal
  // motion kind and feed). Type C: the tool shifts by the vector perpendicular to the next move at
  // its start, in this block; types A and B: nothing until the next move starts up.
  void startup_without_motion(const Move& at);
  // G40 without motion in the plane (`at`: that block): the vector ends perpendicular at the last
  // move's end; type C moves back to the programmed point in this block, types A and B start the
  // next move from there.
  void cancel_without_motion(const Move& at);
  // The work coordinate system moved by `delta` (G92, G52, G54..G59) in offset mode: the last move
  // ends with its perpendicular vector, the tool keeps its place in the new coordinates and the next
  // move starts up from there.
  void move_frame(const AxisVector& delta);
  // A lathe canned cycle's start point (G90/G92/G94/G76): the last move ends there without a vector;
  // the cycle's moves start up afresh.
  void cancel_at_end();
  // Program end or an alarm: the last move ends with its perpendicular vector; everything goes out.
  void finish();
  // After an alarm elsewhere: the moves read so far go out as at program end.
  void abandon() { finish(); }

  // Lathe tool-nose compensation: the imaginary tip from the nose centre; the moves put out are the
  // tip's, the vectors the nose centre's.
  void set_tip(V2 tip) {
    if (!offset_mode()) tip_ = tip;
  }
  bool offset_mode() const { return has_pending() || offset_mode_; }
  // Where the tool centre is, if it differs from the programmed position after a cancel.
  const std::optional<AxisVector>& tool_position() const { return tool_; }
  // Where the tool (centre, or imaginary tip) is after the last move put out, in offset mode.
  const AxisVector& tool_now() const { return tool_ ? *tool_ : tool_full_; }

private:
  struct Elem {
    Move move;
    bool arc = false;
    V2 s, e, c;
    double R = 0;
    int dir = 1;  // +1 counter-clockwise, -1 clockwise
    int side = 0;
    double r = 0;
    std::optional<V2> cancel_direction;
    V2 ts, te;  // the unit tangents at s and at e: set by make_into(), or by set_tangents() after a change
    V2 tangent_at(V2 p) const;
    void set_tangents() {
      ts = tangent_at(s);
      te = arc ? tangent_at(e) : ts;
    }
    V2 t_start() const { return ts; }
    V2 t_end() const { return te; }
  };
  // The extra moves' end points at a corner: three at most (an outer corner between two arcs).
  struct Inserted {
    V2 p[3];
    int n = 0;
    void push_back(V2 x) { p[n++] = x; }
    void clear() { n = 0; }
    bool empty() const { return n == 0; }
    const V2& front() const { return p[0]; }
    const V2* begin() const { return p; }
    const V2* end() const { return p + n; }
  };
  struct Corner {
    V2 end_a;           // where the first element's compensated path ends
    Inserted inserted;  // extra moves' end points (no heap: a corner is made for every block)
    V2 start_b;         // where the second element's compensated path starts
  };
  enum class Joint { offset, startup, cancel };

  Elem make(const Move& m, int side, double radius) const;
  Elem& make_into(Elem& el, const Move& m, int side, double radius) const;
  // The slot of elems_ that is not the pending element's: where the next element is built.
  Elem& spare() { return elems_[pending_ == 0 ? 1 : 0]; }
  bool has_pending() const { return pending_ >= 0; }
  Elem& pending() { return elems_[pending_]; }
  void set_pending(const Elem& el) { pending_ = &el == &elems_[0] ? 0 : 1; }
  Corner corner(const Elem& a, const Elem& b, Joint joint) const;
  std::optional<V2> intersect(const Elem& a, int side_a, double ra, const Elem& b, int side_b, double rb, V2 near) const;
  void emit_element(const Elem& e, V2 from, V2 to, bool plain_end = false);
  void emit_line(const Elem& attributed_to, V2 from, V2 to, bool corner = true);
  void end_perpendicular();
  void emit_after();
  void deliver_at(Move m, const AxisVector& at);
  void check_interference(const Elem& e, V2 from, V2 to);
  void warn_lost(const Elem& next);
  [[noreturn]] void fail(const Move& at, const std::string& code, const std::string& message);
  struct Lost {
    Elem element;  // the block whose end vector was left perpendicular
    Move at;       // the block without motion that went past the read-ahead
    int blocks = 0;
  };

  CompensationSettings settings_;
  Deliver deliver_;
  Alarm alarm_;
  Warn warn_;
  PlaneAxes pa_{0, 1, 2, 'I', 'J'};
  bool offset_mode_ = false;
  Elem elems_[2];                // the pending element and the next one, each built in its slot
  int pending_ = -1;             // the slot of the element whose end vector waits for the next, or -1
  V2 pending_start_;             // where its compensated path starts
  std::deque<Move> after_;       // moves and events read after it
  int blocks_after_ = 0;         // NC blocks without motion in the plane after it
  bool startup_pending_ = false;  // the pending element is the start-up block
  std::optional<Move> shift_;     // type C: the start-up block without motion, waiting for the next move
  std::optional<Lost> lost_;       // the read-ahead was lost: warned at the next element
  V2 tool_plane_;                 // the tool centre in the plane after the last emitted move
  AxisVector tool_full_{};        // and on every axis
  std::optional<AxisVector> tool_;
  V2 tip_;
};

}  // namespace ncurve::machine
