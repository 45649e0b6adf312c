// The last stage before the caller's sink: the run's statistics (RunStats: counts, lengths, time,
// extent) and the Setup each move is made in, told to the sink before the first move and at each change.
#pragma once
#include <algorithm>

#include "machine/interpreter.hpp"
#include "machine/path/stage.hpp"

namespace ncurve::machine {

// The control's work coordinate system and tool length offset, read at each move: where its state
// keeps them (a view, not a virtual call: the statistics are on every move's path).
struct SetupView {
  const int* work;
  const AxisVector* origin;
  const int* length_comp;
  const int* h;
  bool same_as(const Setup& s) const {
    return *work == s.work && *origin == s.origin && *length_comp == s.length_comp && *h == s.h;
  }
  Setup now() const { return {*work, *origin, *length_comp, *h}; }
};

class Statistics final : public PathStage {
public:
  Statistics(RunStats& stats, SetupView setup) : stats_(stats), setup_view_(setup) {}
  // A new run: the sink is told the Setup again before its first move.
  void restart() { setup_sent_ = false; }
  // A point the path reaches besides the moves' ends (an arc's quadrant points).
  void note_extent(const AxisVector& p) {
    if (!stats_.has_extent) {
      stats_.min = stats_.max = p;
      stats_.has_extent = true;
      return;
    }
    for (int a = 0; a < kAxes; ++a) {
      stats_.min[a] = std::min(stats_.min[a], p[a]);
      stats_.max[a] = std::max(stats_.max[a], p[a]);
    }
  }
  void on_move(const Move& m) override;

private:
  RunStats& stats_;
  SetupView setup_view_;
  Setup setup_;  // the last one the sink was told
  bool setup_sent_ = false;
};

}  // namespace ncurve::machine
