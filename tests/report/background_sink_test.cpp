// The writer on a second core sees the moves and setups in the order the run gave them.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/background_sink.hpp"
#include "report/writers.hpp"

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

// The CSV writer takes a batch's moves at once (on_moves): its rows are those it writes a move at a
// time, across batches, work offset changes (setups), arcs, dwells and an alarm at the end.
TEST(BackgroundSink, CsvRowsAreThoseOfTheWriterAlone) {
  const std::string program =
      "G90 G17 G54 G00 X0. Y0. Z10.\nF300.\n#1=0\nWHILE [#1 LT 1500] DO1\n"
      "G01 X[#1*0.01] Y2.\nG02 X[#1*0.01+2.] Y2. R1.\nIF [#1 EQ 700] GOTO 10\nG00 Z[#1*0.001]\nN10 G04 P1\n"
      "IF [#1 NE 1000] GOTO 20\nG55\nN20 #1=#1+1\nEND1\n#3000=1 (STOP)\nM30\n";
  auto write = [&](bool background) {
    machine::ProgramLibrary lib;
    lib.add_text("b.nc", program, true);
    const machine::MachineProfile profile = machine::default_mill();
    std::ostringstream out;
    report::CsvWriter csv(out, profile, 0.001);
    std::optional<report::BackgroundSink> bg;
    if (background) bg.emplace(csv);
    machine::MoveSink& sink = bg ? static_cast<machine::MoveSink&>(*bg) : csv;
    machine::Interpreter in(profile, lib);
    const machine::RunResult r = in.run(sink);
    EXPECT_TRUE(r.alarm);
    if (r.alarm) sink.stopped(*r.alarm);
    if (bg) bg->finish();
    return out.str();
  };
  const std::string alone = write(false);
  EXPECT_GT(std::count(alone.begin(), alone.end(), '\n'), 3 * 2048);
  EXPECT_EQ(write(true), alone);
}
