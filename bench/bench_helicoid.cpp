// Seed 004's example (73 steps of 1 degree): time and distance evaluations per step for each
// search method, on the default lattice (0.05 deg x 0.05 mm). Brute force is timed on 3 steps.
// Also the cusp-fitted choice of passes for the program.
#include <benchmark/benchmark.h>

#include "helicoid/contact.hpp"

using namespace ncurve::helicoid;

namespace {

ContactSearch seed(double included_angle) {
  Workpiece work{EndProfile::seed004_rotor(), 860, 1, 5};
  Lattice lattice;
  lattice.alpha_max = 30;
  return ContactSearch(work, DiscCutter::v_insert(252, 1.2, included_angle, 18), Setting{helix_angle(860, 43), 177.7},
                       lattice);
}

std::vector<double> steps(int n, double step) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(i * step);
  return v;
}

void run(benchmark::State& state, Method method, double angle, int n) {
  auto cs = seed(angle);
  auto psis = steps(n, 1);
  std::int64_t evaluations = 0;
  for (auto _ : state) {
    auto contacts = cs.run(psis, method);
    evaluations = 0;
    for (const auto& c : contacts) evaluations += c.evaluations;
    benchmark::DoNotOptimize(contacts);
  }
  double lattice = static_cast<double>(cs.lattice().size(cs.cutter().length()));
  state.counters["evals_per_step"] = static_cast<double>(evaluations) / n;
  state.counters["lattice_per_step"] = lattice;
  state.counters["fewer_than_lattice"] = lattice * n / static_cast<double>(evaluations);
}

// The program fitted to a cusp tolerance: the fewest of 289 passes (0.25 deg) within 0.05 mm.
void fewest_passes(benchmark::State& state) {
  auto cs = seed(35);
  auto contacts = cs.run(steps(289, 0.25), Method::robust);
  std::size_t passes = 0;
  for (auto _ : state) {
    auto plan = cs.fewest_passes(contacts, 0.05);
    passes = plan.passes.size();
    benchmark::DoNotOptimize(plan);
  }
  state.counters["passes"] = static_cast<double>(passes);
}

}  // namespace

BENCHMARK(fewest_passes)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, robust_35deg_73steps, Method::robust, 35.0, 73)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, robust_70deg_73steps, Method::robust, 70.0, 73)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, nine_point_35deg_73steps, Method::nine_point, 35.0, 73)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, brute_35deg_3steps, Method::brute, 35.0, 3)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
