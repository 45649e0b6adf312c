// The path the machine follows: the planned command, acc/dec after interpolation (a filter per
// axis) and a first-order position loop per axis with velocity feed-forward, stepped at the servo
// period; the contour error is the distance from the actual position to the commanded path.
#pragma once
#include <array>
#include <complex>
#include <cmath>
#include <deque>
#include <optional>
#include <functional>

#include "motion/planner.hpp"

namespace ncurve::motion {

using Point = std::array<double, 3>;

struct Tick {
  double t = 0;
  Point command{};  // interpolator output on the programmed path
  Point actual{};
  double contour_error = 0;  // mm, from actual to the commanded path
  const BlockTime* block = nullptr;  // the block being interpolated
};

struct ContourStats {
  std::uint64_t ticks = 0;
  double max_error = 0, rms = 0;
  double max_t = 0;
  Point max_actual{};
  std::uint32_t max_line = 0;  // the block the error peaks in (0: before any block)
  const nc::SourceFile* max_file = nullptr;
  double sum_sq = 0;
  void add(const Tick& t, const BlockTime* block);  // block: the one the tick belongs to
  void close() { rms = ticks ? std::sqrt(sum_sq / static_cast<double>(ticks)) : 0; }
};

class ServoSim {
public:
  using Callback = std::function<void(const Tick&)>;
  explicit ServoSim(const machine::MachineProfile& profile, Callback on_tick = {});
  void on_block(const BlockTime& b);  // in plan order, e.g. from Planner's callback
  void finish(double settle_seconds);  // runs on with the command at rest for this long; sets the RMS
  // Every tick from the first block on; the contour error while cutting (lines and arcs at feed);
  // and while positioning (rapids). A tick belongs to the block being interpolated, or at rest to
  // the block that moved last (the axes are still catching up with its end).
  const ContourStats& stats() const { return stats_; }
  const ContourStats& cutting() const { return cutting_; }
  const ContourStats& rapids() const { return rapids_; }

private:
  struct Segment {
    BlockTime block;
    double s0 = 0;  // arc length at its start along the whole path
  };
  void step_to(double t_end, const Segment* seg);
  Point path_point(const Segment& seg, double s) const;
  double distance_to(const Segment& seg, const Point& p) const;

  machine::MachineProfile profile_;
  Callback on_tick_;
  ContourStats stats_, cutting_, rapids_;
  std::optional<BlockTime> last_;  // the block that moved last
  std::deque<Segment> window_;  // recent blocks, for the contour error
  double path_length_ = 0;
  double t_ = 0;
  std::uint64_t k_ = 0;  // ticks done
  Point held_{};         // command when no block moves
  bool started_ = false;
  // per linear axis: filter and loop state
  std::array<std::deque<double>, 3> fir_;
  std::array<double, 3> fir_sum_{}, filtered_{}, previous_{}, error_{};
  std::array<int, 3> taps_{};
};

// Steady-state gain of one axis (filter and position loop) at angular frequency w (rad/s), for
// the closed forms beside the simulation.
std::complex<double> axis_response(const machine::MachineProfile& profile, int axis, double w);

}  // namespace ncurve::motion
