// The writer on a second core sees the moves and setups in the order the run gave them.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "report/background_sink.hpp"

namespace {
using namespace ncurve;

struct Log final : machine::MoveSink {
  std::string out;
  int throw_at = -1;
  int count = 0;
  void on_move(const machine::Move& m) override {
    if (count++ == throw_at) throw std::runtime_error("disk full");
    out += "m" + std::to_string(m.line) + " ";
  }
  void on_setup(const machine::Setup& s) override { out += "s" + std::to_string(s.work) + " "; }
  void stopped(const nc::Diagnostic& d) override { out += "stop " + d.code; }
};

std::string feed(machine::MoveSink& sink) {
  std::string expected;
  for (int i = 0; i < 10000; ++i) {
    if (i % 997 == 0 || i == 4095 || i == 4096) {
      machine::Setup s;
      s.work = i % 6 + 1;
      sink.on_setup(s);
      expected += "s" + std::to_string(s.work) + " ";
    }
    machine::Move m;
    m.line = static_cast<std::uint32_t>(i);
    sink.on_move(m);
    expected += "m" + std::to_string(i) + " ";
  }
  return expected;
}
}  // namespace

TEST(BackgroundSink, GivesTheWriterEveryMoveAndSetupInOrder) {
  Log log;
  report::BackgroundSink bg(log);
  std::string expected = feed(bg);
  bg.stopped(nc::Diagnostic{nc::Severity::error, "PS0011", "feed rate is zero", {}});
  expected += "stop PS0011";
  EXPECT_EQ(log.out, expected);
}

TEST(BackgroundSink, AWritersFailureReachesTheRun) {
  Log log;
  log.throw_at = 5000;
  report::BackgroundSink bg(log);
  feed(bg);
  EXPECT_THROW(bg.finish(), std::runtime_error);
}
