// Interpreter throughput: a macro loop, a long expanded program, G65-heavy code, and memory while streaming.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <sys/resource.h>

#include <random>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "nc/program.hpp"
#include "nc/source_file.hpp"

using namespace ncurve::machine;

namespace {

std::string spiral_loop(long points) {
  return fmt::format(
      "O1000\n#101=1.\n#102=2.\n#103=0.\n#110=360./{}\nG01 F1000.\nWHILE [#103 LT 360.] DO1\n#103=#103+#110\n"
      "#104=#101+#102*#103*3.1415927/180.\nG01 X[#104*COS[#103]] Y[#104*SIN[#103]]\nEND1\nM30\n",
      points);
}

std::string expanded(long points) {
  std::string s = "O1001\nG90 G01 F1000.\n";
  s.reserve(static_cast<std::size_t>(points) * 28);
  for (long i = 1; i <= points; ++i) {
    double t = 360.0 * i / points;
    double r = 1 + 2 * t * 3.14159265358979 / 180;
    fmt::format_to(std::back_inserter(s), "X{:.3f} Y{:.3f}\n", r * std::cos(t * 3.14159265358979 / 180),
                   r * std::sin(t * 3.14159265358979 / 180));
  }
  s += "M30\n";
  return s;
}

// 1,000,000 blocks of a closed contour of lines and arcs (100 turns of a 100 mm circle, each turn in
// 10,000 pieces alternating G01 and G03), with or without cutter compensation (G42, 5 mm, outside).
std::string contour(long blocks, bool compensated) {
  std::string s = fmt::format("O1002\nG10 L11 P1 R5.\nG90 G00 X100. Y0\n{} G01 X100. Y0 D1 F2000.\n",
                              compensated ? "G42" : "G40");
  s.reserve(static_cast<std::size_t>(blocks) * 32);
  const long per_turn = 10'000;
  for (long i = 1; i <= blocks; ++i) {
    double a = 2 * 3.14159265358979 * static_cast<double>(i % per_turn) / per_turn;
    if (i % 2) fmt::format_to(std::back_inserter(s), "G01 X{:.4f} Y{:.4f}\n", 100 * std::cos(a), 100 * std::sin(a));
    else fmt::format_to(std::back_inserter(s), "G03 X{:.4f} Y{:.4f} R100.\n", 100 * std::cos(a), 100 * std::sin(a));
  }
  s += "G40 G01 X150.\nM30\n";
  return s;
}

RunStats run_text(const std::string& text, std::uint64_t max_steps = 1'000'000'000) {
  ProgramLibrary lib;
  lib.add_text("bench.nc", text, true);
  RunOptions o;
  o.max_steps = max_steps;
  Interpreter in(default_mill(), lib, o);
  NullSink sink;
  RunResult r = in.run(sink);
  if (!r.ok()) throw std::runtime_error(r.alarm->message);
  return r.stats;
}

void BM_WhileLoop1M(benchmark::State& state) {
  std::string text = spiral_loop(1'000'000);
  std::uint64_t blocks = 0;
  for (auto _ : state) blocks += run_text(text).blocks;
  state.counters["blocks/s"] = benchmark::Counter(static_cast<double>(blocks), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WhileLoop1M)->Unit(benchmark::kMillisecond);

void BM_Expanded1M(benchmark::State& state) {
  std::string text = expanded(1'000'000);
  std::uint64_t blocks = 0;
  for (auto _ : state) blocks += run_text(text).blocks;
  state.SetBytesProcessed(static_cast<std::int64_t>(text.size()) * state.iterations());
  state.counters["blocks/s"] = benchmark::Counter(static_cast<double>(blocks), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Expanded1M)->Unit(benchmark::kMillisecond);

// The text of bench/vs_rs274.py's expanded workload: G01 X Y Z F1000, three seeded random decimals.
std::string cam_blocks(long blocks) {
  std::string s = "%\nO1000\nG21 G90 G17 G54\n";
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> xy(-100, 100), z(-20, 0);
  for (long i = 0; i < blocks; ++i)
    fmt::format_to(std::back_inserter(s), "G01 X{:.3f} Y{:.3f} Z{:.3f} F1000\n", xy(rng), xy(rng), z(rng));
  s += "M30\n%\n";
  return s;
}

// The parse alone of a stream's piece of a CAM program (256 KB; the summary's rate is parse and run together).
void BM_ParsePiece(benchmark::State& state) {
  const auto file = std::make_shared<ncurve::nc::SourceFile>("bench.nc", cam_blocks(7'000));
  for (auto _ : state) benchmark::DoNotOptimize(ncurve::nc::parse(file).programs.size());
  state.SetBytesProcessed(static_cast<std::int64_t>(file->size()) * state.iterations());
}
BENCHMARK(BM_ParsePiece)->Unit(benchmark::kMillisecond);

void BM_CamBlocks1M(benchmark::State& state) {
  const std::string text = cam_blocks(1'000'000);
  for (auto _ : state) benchmark::DoNotOptimize(run_text(text).blocks);
  state.SetBytesProcessed(static_cast<std::int64_t>(text.size()) * state.iterations());
}
BENCHMARK(BM_CamBlocks1M)->Unit(benchmark::kMillisecond);

void BM_Contour1M(benchmark::State& state) {
  std::string text = contour(1'000'000, state.range(0) != 0);
  std::uint64_t blocks = 0;
  for (auto _ : state) blocks += run_text(text).blocks;
  state.counters["blocks/s"] = benchmark::Counter(static_cast<double>(blocks), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Contour1M)->Arg(0)->Arg(1)->ArgName("compensated")->Unit(benchmark::kMillisecond);

// 100,000 holes of a G81 drilling cycle on a 1 mm grid, one X Y block a hole.
std::string drilling(long holes) {
  std::string s = "O1003\nG90 G00 X0 Y0 Z10.\nG99 G81 X0 Y0 Z-5. R2. F300.\n";
  s.reserve(static_cast<std::size_t>(holes) * 16);
  for (long i = 1; i < holes; ++i) fmt::format_to(std::back_inserter(s), "X{} Y{}\n", i % 1000, i / 1000);
  s += "G80\nM30\n";
  return s;
}

void BM_G81Holes100k(benchmark::State& state) {
  std::string text = drilling(100'000);
  std::uint64_t moves = 0;
  for (auto _ : state) moves += run_text(text).motions;
  state.counters["moves/s"] = benchmark::Counter(static_cast<double>(moves), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_G81Holes100k)->Unit(benchmark::kMillisecond);

void BM_G65Calls(benchmark::State& state) {
  std::string text =
      "O1002\n#1=0\nWHILE [#1 LT 100000] DO1\nG65 P9100 A#1 B0.002 X[#1*0.001]\n#1=#1+1\nEND1\nM30\n"
      "O9100\n#3=#1*#2\nG01 X#24 Y#3 F500.\nM99\n";
  std::uint64_t blocks = 0;
  for (auto _ : state) blocks += run_text(text).blocks;
  state.counters["blocks/s"] = benchmark::Counter(static_cast<double>(blocks), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_G65Calls)->Unit(benchmark::kMillisecond);

// 10 million moves streamed to a null sink: peak resident memory must not grow with the program.
void BM_Stream10MMovesPeakRss(benchmark::State& state) {
  std::string text = spiral_loop(10'000'000);
  for (auto _ : state) run_text(text);
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  state.counters["peak_rss_MB"] = static_cast<double>(u.ru_maxrss) / 1024.0;
}
BENCHMARK(BM_Stream10MMovesPeakRss)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
