// The last stage before the caller's sink: the run's statistics (RunStats: counts, lengths, time,
// extent) and the Setup each move is made in, told to the sink before the first move and at each change.
#pragma once
#include "machine/interpreter.hpp"
#include "machine/path/stage.hpp"

namespace ncurve::machine {

// The work coordinate system and tool length offset in force, read at each move.
class SetupSource {
public:
  virtual Setup setup_now() const = 0;

protected:
  ~SetupSource() = default;
};

class Statistics final : public PathStage {
public:
  Statistics(RunStats& stats, const SetupSource& setup) : stats_(stats), setup_source_(setup) {}
  // A new run: the sink is told the Setup again before its first move.
  void restart() { setup_sent_ = false; }
  // A point the path reaches besides the moves' ends (an arc's quadrant points).
  void note_extent(const AxisVector& p);
  void on_move(const Move& m) override;

private:
  RunStats& stats_;
  const SetupSource& setup_source_;
  Setup setup_;  // the last one the sink was told
  bool setup_sent_ = false;
};

}  // namespace ncurve::machine
