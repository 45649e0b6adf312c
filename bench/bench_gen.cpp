// ncurve gen speed: equal-error lines for seed 000's spiral at 1 um and for a 100,000-segment
// expression curve, each emitted and round-tripped through the interpreter (segments per second).
#include <benchmark/benchmark.h>

#include "gen/generate.hpp"

using namespace ncurve;

namespace {

void run(benchmark::State& state, const geom::Curve& curve, gen::Options o) {
  std::size_t segments = 0;
  for (auto _ : state) {
    gen::Result r = gen::generate(curve, o);
    if (!r.within_tolerance) state.SkipWithError("not within the tolerance");
    segments = r.stats.points - 1;
    benchmark::DoNotOptimize(r.text.data());
  }
  state.counters["segments"] = static_cast<double>(segments);
  state.counters["segments_per_s"] =
      benchmark::Counter(static_cast<double>(segments), benchmark::Counter::kIsIterationInvariantRate);
}

void Spiral1um(benchmark::State& state) {
  geom::Curve spiral(*geom::find_curve("spiral"), {});
  gen::Options o;
  o.tol = 0.001;
  o.profile.increment = 0.0001;  // IS-C: at 1 um the IS-B rounding would take most of the tolerance
  run(state, spiral, o);
}
BENCHMARK(Spiral1um)->Unit(benchmark::kMillisecond)->UseRealTime();  // the fit runs on all cores

void Expression100k(benchmark::State& state) {
  geom::CurveSpec spec;
  using namespace std::string_literals;  // (GCC 12 warns falsely of an overlap on assigning a char*)
  spec.name = "expr"s;
  spec.x = "[R0+PITCH*t/360]*COS[t]"s;
  spec.y = "[R0+PITCH*t/360]*SIN[t]"s;
  spec.z = "0"s;
  spec.params = {{"R0", 5, ""}, {"PITCH", 2, ""}};
  spec.from = 0;
  spec.to = 360 * 106;  // 106 turns out to radius 217 mm: 100,744 segments
  geom::Curve curve(spec, {});
  gen::Options o;
  o.tol = 0.0003;
  o.profile.increment = 0.0001;
  run(state, curve, o);
}
BENCHMARK(Expression100k)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void AdaptiveMacroSpiral(benchmark::State& state) {
  geom::Curve spiral(*geom::find_curve("spiral"), {});
  gen::Options o;
  o.form = gen::Form::adaptive_macro;
  run(state, spiral, o);
}
BENCHMARK(AdaptiveMacroSpiral)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
