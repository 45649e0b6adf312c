// Material removal on a Z-map: 1,000,000 short moves of a ball end mill, a raster over a surface
// as CAM writes it, onto a 1000 x 1000 map (issue 36's target: under 5 s). A lathe's half-section:
// a G73/G70 program of 10,000 moves (issue 36's target: under 1 s), and the part as an STL.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "sim/lathe_section.hpp"
#include "sim/lathe_section_sink.hpp"
#include "sim/zmap.hpp"

using namespace ncurve::sim;
namespace machine = ncurve::machine;

namespace {

// 1000 rows 0.1 mm apart along X, back and forth, of 0.1 mm moves (a row's first move the step
// over from the row before): 1,000,000 moves, the tip on z = -5 + 2 sin(x / 10) cos(y / 15) over
// a 100 x 100 mm stock
std::vector<Point3> raster() {
  auto surface = [](double x, double y) { return -5 + 2 * std::sin(x / 10) * std::cos(y / 15); };
  std::vector<Point3> p;
  p.reserve(1'000'001);
  double x = 0, y = 0.05;
  p.push_back({x, y, surface(x, y)});
  for (int row = 0; row < 1000; ++row) {
    const double dir = row % 2 ? -0.1 : 0.1;
    if (row > 0) {
      y += 0.1;
      p.push_back({x, y, surface(x, y)});
    }
    for (int k = 0; k < (row > 0 ? 999 : 1000); ++k) {
      x += dir;
      p.push_back({x, y, surface(x, y)});
    }
  }
  return p;
}

// The raster cut in batches of ZMap::kBatchSweeps, as the Verifier cuts (its rows shared between the
// cores), or one move at a time (one core).
void cut(benchmark::State& state, const ToolShape& tool, bool batched) {
  const auto points = raster();
  std::vector<Sweep> batch;
  for (auto _ : state) {
    ZMap map(Box{{0, 0, -20}, {100, 100, 0}});
    for (std::size_t k = 1; k < points.size(); ++k) {
      if (!batched) {
        map.cut_line(tool, points[k - 1], points[k]);
        continue;
      }
      batch.push_back({tool, points[k - 1], points[k], std::nullopt, false});
      if (batch.size() == ZMap::kBatchSweeps || k + 1 == points.size()) {
        map.cut_batch(batch);
        batch.clear();
      }
    }
    benchmark::DoNotOptimize(map.heights().data());
    state.counters["volume_mm3"] = map.volume_removed();
  }
  state.counters["moves"] = static_cast<double>(points.size() - 1);
  state.counters["moves_per_s"] =
      benchmark::Counter(static_cast<double>(points.size() - 1), benchmark::Counter::kIsIterationInvariantRate);
}

// A shaft on a 50 mm bar: G73 pattern repeating in 10 passes 0.5 mm apart over a profile of 810 lines
// (a sine wave of 6 mm in diameter along 57 mm) and 100 arcs of R0.4 (alternating G02/G03), then G70
// along it: some 10,000 moves (the `moves` counter), with a CNMG R0.4 insert (tip 3). `cycle` is the
// roughing cycle's two blocks.
std::string shaft_program(const char* cycle) {
  std::string s = fmt::format("O0100\nG21 G99 G18 G40\nT0101\nG00 X64. Z2.\n{}\nN100 G00 X20. Z2.\nG01 Z0\n", cycle);
  const int lines = 810;
  double x = 0, z = 0;
  for (int i = 1; i <= lines; ++i) {
    z = -0.07 * i;
    x = 40 + 6 * std::sin(2 * std::numbers::pi * i / 200);
    fmt::format_to(std::back_inserter(s), "X{:.4f} Z{:.4f}\n", x, z);
  }
  for (int k = 0; k < 100; ++k) {
    z -= 0.5;
    fmt::format_to(std::back_inserter(s), "{} X{:.4f} Z{:.4f} R0.4\n", k % 2 ? "G03" : "G02", x, z);
  }
  fmt::format_to(std::back_inserter(s), "G01 Z{:.4f}\nN200 X64.\nG00 X64. Z2.\nG70 P100 Q200\nG00 X100. Z50.\nM30\n", z - 2);
  return s;
}

const std::string kPatternRepeating = shaft_program("G73 U5. W0.5 R10\nG73 P100 Q200 U0.4 W0.1 F0.2");
const std::string kStockRemoval = shaft_program("G71 U0.1 R0.05\nG71 P100 Q200 U0.4 W0.1 F0.2");  // type II
// Facing across the spindle axis, the direction Clipper's scan line does not run: 2,500 passes
// 0.02 mm apart (10,000 moves), each from X54 past the centre and back.
const std::string kFacing =
    "O0101\nG21 G99 G18 G40\nT0101\nG00 X54. Z2.\n#1=0\nWHILE[#1LT2500]DO1\nG00 Z[-#1*0.02]\nG01 X-1.6 F0.2\n"
    "G00 Z[1.-#1*0.02]\nX54.\n#1=#1+1\nEND1\nM30\n";

std::vector<machine::Move> lathe_moves(const std::string& program) {
  machine::ProgramLibrary lib;
  lib.add_text("shaft.nc", program, true);
  machine::Interpreter in(machine::default_lathe(), lib, {});
  struct Keep final : machine::MoveSink {
    std::vector<machine::Move> moves;
    void on_move(const machine::Move& m) override { moves.push_back(m); }
  } keep;
  const machine::RunResult r = in.run(keep);
  if (!r.ok()) throw std::runtime_error(r.alarm->message);
  return std::move(keep.moves);
}

ToolLibrary cnmg_r04() {
  ToolLibrary tools;
  LatheInsert cnmg;
  cnmg.nose_radius = 0.4;
  cnmg.tip = 3;
  tools.tools[1] = cnmg;
  return tools;
}

const Cylinder kBar{50, 0, 120, 0};

// The moves cut into a 50 mm bar in batches of state.range(0) sweeps, the volume removed read at the end.
void lathe_cut(benchmark::State& state, const std::string* program) {
  const auto moves = lathe_moves(*program);
  std::size_t motions = 0;
  for (const auto& m : moves) motions += m.is_motion();
  const ToolLibrary tools = cnmg_r04();
  for (auto _ : state) {
    LatheSection section(kBar, static_cast<int>(state.range(0)));
    LatheSectionSink sink(section, tools);
    for (const auto& m : moves) sink.on_move(m);
    state.counters["volume_mm3"] = section.volume_removed();
    double vertices = 0;
    for (const auto& p : section.polygons()) vertices += static_cast<double>(p.size());
    state.counters["vertices"] = vertices;
  }
  state.counters["moves"] = static_cast<double>(motions);
  state.counters["moves_per_s"] =
      benchmark::Counter(static_cast<double>(motions), benchmark::Counter::kIsIterationInvariantRate);
}

// The G73 shaft revolved in 256 steps and written as a binary STL to memory.
void lathe_mesh(benchmark::State& state) {
  LatheSection section(kBar);
  LatheSectionSink sink(section, cnmg_r04());
  for (const auto& m : lathe_moves(kPatternRepeating)) sink.on_move(m);
  for (auto _ : state) {
    const Mesh mesh = section.mesh(256);
    std::ostringstream out;
    write_stl(out, mesh);
    state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
    benchmark::DoNotOptimize(out.str().size());
  }
}

}  // namespace

BENCHMARK_CAPTURE(lathe_cut, G73G70Shaft, &kPatternRepeating)
    ->Arg(LatheSection::kDefaultBatch)->Arg(1)->Arg(16)->Arg(64)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(lathe_cut, G71G70Shaft, &kStockRemoval)->Arg(LatheSection::kDefaultBatch)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(lathe_cut, Facing, &kFacing)->Arg(LatheSection::kDefaultBatch)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(lathe_mesh)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(cut, BallR3Raster, ToolShape::ball(3), true)->Unit(benchmark::kSecond)->Iterations(1)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(cut, BallR1Raster, ToolShape::ball(1), true)->Unit(benchmark::kSecond)->Iterations(1)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(cut, FlatR3Raster, ToolShape::flat(3), true)->Unit(benchmark::kSecond)->Iterations(1)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(cut, BallR3RasterOneCore, ToolShape::ball(3), false)->Unit(benchmark::kSecond)->Iterations(1)->MeasureProcessCPUTime()->UseRealTime();

BENCHMARK_MAIN();
