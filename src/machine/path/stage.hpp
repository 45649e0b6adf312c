// The path stages (path/): the chain a move goes through after the interpreter made it, built once:
// corner ,C ,R -> compensation -> developed-path conversion -> stroke limits -> nose centre ->
// statistics -> the caller's sink. Each stage is a MoveSink that forwards to the next one.
#pragma once
#include <functional>
#include <string>

#include "machine/move.hpp"

namespace ncurve::machine {

// Raises an alarm or a warning at the block of the move `at`; an alarm callback throws.
using MoveAlarm = std::function<void(const Move& at, const std::string& code, const std::string& message)>;

class PathStage : public MoveSink {
public:
  // The stage the moves go to next (link before the first move).
  void link(MoveSink& next) { next_ = &next; }
  void on_setup(const Setup& s) override { next_->on_setup(s); }
  void stopped(const nc::Diagnostic& d) override { next_->stopped(d); }

protected:
  MoveSink* next_ = nullptr;
};

}  // namespace ncurve::machine
