// What the path stage tests share: a recording sink, hand-made moves and alarm callbacks.
#pragma once
#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "machine/path/stage.hpp"
#include "machine/path/statistics.hpp"

namespace ncurve::machine::path_test {

inline constexpr double kPi = std::numbers::pi;

// What reaches the end of the chain, in order: "setup" or the move's kind.
struct Recorder final : MoveSink {
  std::vector<Move> moves;
  std::vector<Setup> setups;
  std::vector<std::string> order;
  void on_move(const Move& m) override {
    moves.push_back(m);
    order.push_back(to_string(m.kind));
  }
  void on_setup(const Setup& s) override {
    setups.push_back(s);
    order.push_back("setup");
  }
};

// The control's setup the statistics read.
struct FixedSetup {
  Setup now;
  operator SetupView() const { return {&now.work, &now.origin, &now.length_comp, &now.h}; }
};

inline Move motion(MoveKind kind, AxisVector from, AxisVector to, double length, double seconds, std::uint32_t line = 1) {
  Move m;
  m.kind = kind;
  m.start = from;
  m.end = to;
  m.length = length;
  m.seconds = seconds;
  m.line = line;
  return m;
}

// The alarm callback of a stage: records the alarm, then stops the run as the Executor's does.
struct Raised {
  std::string code, message;
  std::uint32_t line = 0;
};
struct Stopped : std::runtime_error {
  Stopped() : std::runtime_error("alarm") {}
};
inline MoveAlarm recording_alarm(Raised& raised) {
  return [&raised](const Move& at, const std::string& code, const std::string& message) {
    raised = {code, message, at.line};
    throw Stopped();
  };
}

// A warning callback for stages that must not warn.
inline MoveAlarm no_warning() {
  return [](const Move&, const std::string& code, const std::string& message) {
    ADD_FAILURE() << code << " " << message;
  };
}

}  // namespace ncurve::machine::path_test
