// Executes a Program as a FANUC 0i/30i control would, streaming Moves to a sink.
#pragma once
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "machine/library.hpp"
#include "machine/macro_output.hpp"
#include "machine/move.hpp"
#include "machine/observer.hpp"
#include "machine/profile.hpp"
#include "nc/program.hpp"

namespace ncurve::machine {

struct RunOptions {
  // a runaway program is stopped after this many steps: a block is one, an expression one an operation,
  // a move past a block's first one (a cycle's holes and pecks)
  std::uint64_t max_steps = 200'000'000;
  double max_seconds = 60;  // or after this long (wall clock); 0: no limit
  std::vector<std::pair<int, double>> presets;  // --set "#100=5"
  bool nose_centre = false;  // lathe: write the tool-nose centre's path, not the imaginary tip's
  double path_tolerance = 0.001;  // mm: G12.1/G07.1 moves are written within this of the contour (--arc-tol)
  const std::atomic<bool>* cancel = nullptr;  // when set, the run stops (NC9000) at its next bound check
  bool plain_lane = true;  // plain G00/G01 blocks by Executor::plain_motion_block (false: the general path, for tests)
};

struct RunStats {
  std::uint64_t blocks = 0;  // blocks run, macro statements and the shapes G70..G73 read included
  std::uint64_t shape_blocks = 0;  // of them: blocks a G71..G73 read for its shape, within the cycle block's step
  // The blocks executed as the debugger steps them and the summary counts them.
  std::uint64_t executed() const { return blocks - shape_blocks; }
  std::uint64_t motions = 0;
  std::array<std::uint64_t, 10> by_kind{};  // indexed by MoveKind
  double feed_length = 0;
  double rapid_length = 0;
  double seconds = 0;  // feed-rate estimate: length / F, rapids at the profile's rates, dwells
  bool has_extent = false;
  AxisVector min{}, max{};  // of the motion end points and arc extremes, work coordinates
};

// The G-code groups of the profile's G-code system (mill, lathe A, B or C), in order: those
// #4001.. of the control's modal state has.
std::vector<int> modal_groups(const MachineProfile& p);

// Least input increments per mm of the profile, as the control counts them.
double increments_per_mm(const MachineProfile& p);
// A dimension as the control takes it: a whole number of increments (halves away from zero), with
// per_unit increments a unit. Inline and without branches: the fit's path is read back with it too.
inline double round_to_increment(double value, double per_unit) {
  const double steps = value * per_unit;
  const double whole = std::floor(std::fabs(steps) + 0.5);
  return (steps < 0 ? -whole : whole) / per_unit;
}
// The length of a line move from `from` to `to` (X, Y and Z) as a Move gives it.
inline double line_length(const double* from, const double* to) {
  double sq = 0;
  for (int a = 0; a < 3; ++a) sq += (to[a] - from[a]) * (to[a] - from[a]);
  return std::sqrt(sq);
}

struct RunResult {
  bool ok() const { return !alarm.has_value(); }
  std::optional<nc::Diagnostic> alarm;
  std::vector<nc::Diagnostic> warnings;  // includes #3006 messages and M00/M01 stops
  RunStats stats;
  ExternalOutput output;  // what POPEN, DPRNT, BPRNT and PCLOS sent
};

class Executor;

// Runs programs on a machine: construct it with the machine and the program library, then run().
class Interpreter {
public:
  Interpreter(const MachineProfile& profile, const ProgramLibrary& library, RunOptions options = {});
  ~Interpreter();
  Interpreter(Interpreter&&) noexcept;
  Interpreter& operator=(Interpreter&&) noexcept;

  // Runs the library's main program from the power-on state, streaming its moves to sink.
  RunResult run(MoveSink& sink);
  // Variable value after (or during) a run, as a program would read it.
  nc::Value variable(int number);
  // Blocks the last runs made by the lane of plain motion (RunOptions::plain_lane), for the tests.
  std::uint64_t plain_lane_blocks() const;
  // Tell this observer each block, call, return and variable write of the next runs (null: none).
  void observe(ExecutionObserver* observer);
  // The imaginary tool tip's offset from the tool-nose centre (Z, X as a radius) for the move the
  // sink is given now: a lathe's, none on a mill or under G12.1/G07.1. The put-out arc's centre
  // under tool-nose radius compensation is the programmed arc's centre plus this.
  std::array<double, 2> nose_tip_now() const;

private:
  std::unique_ptr<Executor> executor_;
};

}  // namespace ncurve::machine
