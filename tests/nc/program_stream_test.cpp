// A program read as a stream in small pieces against the same text read whole (nc::parse): the same
// problems, moves, alarms and warnings, where jumps, loops and problems cross pieces.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/summary.hpp"

namespace {
using namespace ncurve;

struct Lines final : machine::MoveSink {
  std::string out;
  void on_move(const machine::Move& m) override {
    out += fmt::format("{} {} {:.4f} {:.4f} {:.4f}\n", static_cast<int>(m.kind), m.line, m.end[0], m.end[1], m.end[2]);
  }
};

// What a run shows: its problems, moves, alarm, warnings and the source's counts.
std::string run(machine::ProgramLibrary& lib, std::vector<nc::Diagnostic> problems) {
  Lines moves;
  machine::Interpreter interp(machine::default_mill(), lib);
  const machine::RunResult r = interp.run(moves);
  if (lib.streamed()) problems = lib.streamed_problems();
  std::string out;
  for (const auto& d : problems) out += nc::format(d) + "\n";
  out += fmt::format("left out {} unchecked {}\n", lib.problems_left_out(), lib.unchecked_lines());
  out += moves.out;
  if (r.alarm) out += "alarm " + nc::format(*r.alarm) + "\n";
  for (const auto& w : r.warnings) out += nc::format(w) + "\n";
  const report::SourceStats s = report::source_stats(lib, lib.main()->file.get());
  out += fmt::format("blocks {} words {} programs {} bytes {} executed {}\n", s.blocks, s.words, s.programs, s.bytes,
                     r.stats.blocks);
  return out;
}

// The text read whole and read as a stream in pieces of `chunk` bytes.
void same_either_way(const std::string& text, std::size_t chunk) {
  const std::string path = fmt::format("{}stream_{}_{}.nc", ::testing::TempDir(),
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name(), ::getpid());
  {
    std::ofstream f(path, std::ios::binary);
    f << text;
  }
  machine::ProgramLibrary whole;
  const auto problems = whole.add_text(path, text, true);
  const std::string expected = run(whole, problems);
  machine::ProgramLibrary streamed;
  streamed.add_streamed(path, path, chunk);
  EXPECT_EQ(run(streamed, {}), expected) << "pieces of " << chunk << " bytes";
  std::remove(path.c_str());
}

std::string body(int n, int seed) {
  std::string s;
  for (int i = 0; i < n; ++i) s += fmt::format("G01 X{}.{} Y{}. F500\n", (i * seed) % 91, i % 10, -(i % 37));
  return s;
}
}  // namespace

TEST(ProgramStream, JumpsBackAndLoopsAcrossPieces) {
  const std::string text = "%\nO1000\n#1=0\nN10 #1=#1+1\n" + body(400, 3) + "IF [#1 LT 3] GOTO 10\n#2=0\n" +
                           "WHILE [#2 LT 2] DO1\n#3=0\nWHILE [#3 LT 2] DO2\n" + body(200, 7) +
                           "#3=#3+1\nEND2\n#2=#2+1\nEND1\n#4=0\nN20 #4=#4+1\nIF [#4 GT 2] GOTO 30\nM98 P2000\n"
                           "N30 M98 P3000\nM30\nO2000\n" + body(300, 5) + "M99 P20\nO3000\n" + body(50, 2) +
                           "M99\n%\nO4000\nG00 X1.\nM99\n";
  for (std::size_t chunk : {64, 1000, 1 << 20}) same_either_way(text, chunk);
}

TEST(ProgramStream, ProblemsCrossPiecesAsReadWhole) {
  // syntax errors, more than a hundred of them with junk after (lines no jump reaches are skipped),
  // a DO without END found at the program's end, a duplicate O number, mixed decimal points
  std::string text = "O1000\nG01 X1 Y2. F100\nWHILE [#1 LT 1] DO1\nG01 X3.\n";
  for (int i = 0; i < 150; ++i) text += fmt::format("G01 X1.. Y{}\nN{} G01 X@\n$$ junk\n", i, i + 1);
  text += "GOTO 5\nM30\nO2000\nG00 X1.\nM99\nO2000\nM99\n";
  for (std::size_t chunk : {64, 700, 1 << 20}) same_either_way(text, chunk);
}

TEST(ProgramStream, AnAlarmInACalledProgramAfterManyPieces) {
  const std::string text = "O1000\nM98 P2000\nM30\nO2000\n" + body(500, 11) + "G01 X1. F0\nM99\n";
  for (std::size_t chunk : {64, 4096}) same_either_way(text, chunk);
}

TEST(ProgramStream, AGotoIntoALoopAlarmsAcrossPieces) {
  const std::string text = "O1000\n#1=0\nGOTO 7\nWHILE [#1 LT 2] DO1\n" + body(300, 13) + "N7 #1=#1+1\nEND1\nM30\n";
  for (std::size_t chunk : {64, 4096}) same_either_way(text, chunk);
}

TEST(ProgramStream, ProgramsAfterTheEndFoundAtTheirLinesPastLongLines) {
  // lines after the closing '%' longer than a piece: the unread O2000 is named at its own line
  const std::string text = "%\nO1001 (THE CONTROL READS NOTHING AFTER THE PERCENT, A LONG COMMENT)\nM98 P2000\nM30\n%\n"
                           "(A COMMENT LINE AFTER THE END, LONGER THAN A PIECE OF EIGHT BYTES)\nG00 X0. Y0.\nO2000\nM99\n";
  for (std::size_t chunk : {8, 64}) same_either_way(text, chunk);
}

TEST(ProgramStream, AFileCutShortWhileReadEndsWithAnError) {
  // another program truncating the file mid-run: the stream stops with an error naming the file
  const std::string path = fmt::format("{}stream_cut_{}.nc", ::testing::TempDir(), ::getpid());
  const std::string text = "O1000\n" + body(2000, 3) + "M30\n";
  {
    std::ofstream f(path, std::ios::binary);
    f << text;
  }
  machine::ProgramLibrary lib;
  lib.add_streamed(path, path, 256);
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(text.size() / 2)), 0);
  try {
    run(lib, {});
    ADD_FAILURE() << "a file cut short ran to its end";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": error: the file became shorter while it was read"),
              std::string::npos)
        << e.what();
  }
  std::remove(path.c_str());
}
