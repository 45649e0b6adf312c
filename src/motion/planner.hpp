// Feed planning and cycle time: when each move starts, how fast it goes, and where the control
// starves because blocks (or the macro statements between them) are not ready in time.
#pragma once
#include <cstdint>
#include <deque>
#include <functional>

#include "machine/move.hpp"
#include "machine/profile.hpp"

namespace ncurve::motion {

// What capped a block's feed.
enum class Limit : std::uint8_t { programmed, max_cutting, rapid, arc, block_time };
const char* to_string(Limit l);

// A change of speed by dv under acceleration a and jerk j (0 = unlimited): its time, and the
// distance covered going from v0 to v1 (symmetric S-curve, or a trapezoid ramp without jerk).
double change_time(double dv, double a, double j);
double change_distance(double v0, double v1, double a, double j);
// The highest speed at one end of a length L from which the speed v at the other end is reachable.
double reachable(double v, double L, double a, double j);

// One speed change inside a block: speed and distance at time tau from its start.
struct Ramp {
  double v0 = 0, v1 = 0, a = 0, j = 0;
  double duration() const { return change_time(v1 > v0 ? v1 - v0 : v0 - v1, a, j); }
  double speed(double tau) const;
  double distance(double tau) const;
};

// The planned feed profile of one motion: ramp up, cruise, ramp down (speeds in mm/s).
struct Profile {
  Ramp up, down;
  double cruise = 0;  // s at v_peak
  double v_peak = 0;
  double seconds() const { return up.duration() + cruise + down.duration(); }
  double distance(double tau) const;  // along the path, 0..length
};
Profile plan_profile(double length, double v_in, double v_cap, double v_out, double a, double j);

struct BlockTime {
  machine::Move move;   // the move as the interpreter gave it
  double length = 0;    // mm (or degrees for a rotary-only move)
  double programmed = 0;  // mm/min: the feed as programmed (rapid: traverse rate along the path)
  double cap = 0;       // mm/min: the highest feed the block allows
  Limit limit = Limit::programmed;
  double v_in = 0, v_peak = 0, v_out = 0;  // mm/min
  double start = 0;     // s from program start
  double seconds = 0;   // s of motion
  double wait = 0;      // s stood still before the block, waiting for it to be ready
  double settle = 0;    // s after the block: in-position check or filter tail
  double dwell = 0;     // s of dwell (G04) after the block
  bool starved = false; // the feed was cut because the block is shorter than one block processing time allows
  Profile profile;      // speeds in mm/s
};

struct PlanTotals {
  double seconds = 0;             // from program start to the end of the last motion, settling included
  double motion_seconds = 0;
  double wait_seconds = 0;        // stood still waiting for blocks (macro statements, block processing)
  double settle_seconds = 0;
  double dwell_seconds = 0;
  double programmed_seconds = 0;  // length / programmed feed, rapids at traverse rate: no dynamics
  std::uint64_t motions = 0, starved = 0, stops = 0, waits = 0;
  double feed_length = 0, feed_motion_seconds = 0;  // cutting moves: mean feed reached = length / time
  std::uint64_t macro_statements = 0, nc_blocks = 0;
  std::uint64_t without_lookahead = 0;  // motions made with look-ahead off (G05.1 Q0, G08 P0, ...)
};

// Streams moves from the interpreter; calls on_block for each motion once its timing is final.
// Memory stays bounded by the look-ahead, so a program of any length plans in constant memory.
class Planner final : public machine::MoveSink {
public:
  using Callback = std::function<void(const BlockTime&)>;
  explicit Planner(const machine::MachineProfile& profile, Callback on_block = {});
  void on_move(const machine::Move& m) override;
  // whether m is timed (on_block called for it): a motion of some length, or turning a rotary axis
  static bool plans(const machine::Move& m);
  void finish();  // after the run: plans the blocks still waiting for look-ahead
  const PlanTotals& totals() const { return totals_; }

private:
  struct Pending {
    BlockTime t;
    double cap = 0;       // mm/s
    double accel = 0;     // mm/s^2 along the path; 0 = unlimited (acc/dec after interpolation)
    double junction = 0;  // mm/s: largest speed at the block start (corner with the previous one)
    double compute = 0;   // s the control needs to read this block and the statements before it
    double ready = 0;
    bool ready_known = false;
    bool stop_after = false;
    bool exact_stop = false;
    double start_dir[3]{}, end_dir[3]{};
  };
  void add(const machine::Move& m);
  bool finalize_front();
  double ready_of(std::size_t k, double front_start);
  double start_of(std::int64_t index) const;

  machine::MachineProfile profile_;
  Callback on_block_;
  PlanTotals totals_;
  std::deque<Pending> pending_;      // blocks not yet final, oldest first
  std::deque<double> starts_;        // start times of the last look_ahead final blocks
  std::int64_t next_index_ = 0;      // index of pending_.front()
  double clock_ = 0;                 // end of the last final block (settle and dwell included)
  double last_ready_ = 0;
  double v_last_ = 0;                // mm/s at the end of the last final block
  double carry_compute_ = 0;         // statements read before the next motion
  bool ended_ = false;
};

}  // namespace ncurve::motion
