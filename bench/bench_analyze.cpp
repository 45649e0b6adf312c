// Planning and servo-simulating a 1,000,000-block program: a spiral of 0.05 mm lines at
// 3000 mm/min (1 ms per block), look-ahead 30, servo at 1 kHz; the interpreter is not timed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "motion/planner.hpp"
#include "motion/servo.hpp"

using namespace ncurve;

namespace {

std::vector<machine::Move> spiral_moves(std::size_t n) {
  std::vector<machine::Move> moves;
  moves.reserve(n);
  double theta = 0, r = 5;
  machine::AxisVector p{r, 0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    machine::Move m;
    m.kind = machine::MoveKind::line;
    m.start = p;
    theta += 0.05 / r;
    r = 5 + 0.5 * theta;
    p[0] = r * std::cos(theta);
    p[1] = r * std::sin(theta);
    m.end = p;
    m.length = std::hypot(m.end[0] - m.start[0], m.end[1] - m.start[1]);
    m.feed = 3000;
    m.seconds = m.length / 50;
    m.nc_blocks = 1;
    moves.push_back(m);
  }
  return moves;
}

machine::MachineProfile profile() {
  auto p = machine::default_mill();
  p.motion.look_ahead = 30;
  p.motion.corner_speed = {400, 400, 400, 0, 0, 0};
  return p;
}

void BM_Plan1M(benchmark::State& state) {
  auto moves = spiral_moves(1'000'000);
  auto p = profile();
  double seconds = 0;
  for (auto _ : state) {
    motion::Planner planner(p);
    for (const auto& m : moves) planner.on_move(m);
    planner.finish();
    seconds = planner.totals().seconds;
  }
  state.counters["cycle_time_s"] = seconds;
  state.counters["blocks_per_s"] = benchmark::Counter(1e6, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Plan1M)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_PlanAndServo1M(benchmark::State& state) {
  auto moves = spiral_moves(1'000'000);
  auto p = profile();
  double ticks = 0, error = 0;
  for (auto _ : state) {
    motion::ServoSim sim(p);
    motion::Planner planner(p, [&](const motion::BlockTime& b) { sim.on_block(b); });
    for (const auto& m : moves) planner.on_move(m);
    planner.finish();
    sim.finish(0.2);
    ticks = static_cast<double>(sim.stats().ticks);
    error = sim.stats().max_error;
  }
  state.counters["servo_ticks"] = ticks;
  state.counters["max_contour_error_mm"] = error;
  state.counters["blocks_per_s"] = benchmark::Counter(1e6, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PlanAndServo1M)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
