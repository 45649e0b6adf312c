// Material removal on a Z-map: 1,000,000 short moves of a ball end mill, a raster over a surface
// as CAM writes it, onto a 1000 x 1000 map (issue 36's target: under 5 s).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "sim/zmap.hpp"

using namespace ncurve::sim;

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

void cut(benchmark::State& state, const ToolShape& tool) {
  const auto points = raster();
  for (auto _ : state) {
    ZMap map(Box{{0, 0, -20}, {100, 100, 0}});
    for (std::size_t k = 1; k < points.size(); ++k) map.cut_line(tool, points[k - 1], points[k]);
    benchmark::DoNotOptimize(map.heights().data());
    state.counters["volume_mm3"] = map.volume_removed();
  }
  state.counters["moves"] = static_cast<double>(points.size() - 1);
  state.counters["moves_per_s"] =
      benchmark::Counter(static_cast<double>(points.size() - 1), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK_CAPTURE(cut, BallR3Raster, ToolShape::ball(3))->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK_CAPTURE(cut, BallR1Raster, ToolShape::ball(1))->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK_CAPTURE(cut, FlatR3Raster, ToolShape::flat(3))->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

BENCHMARK_MAIN();
