// The diagnostics path on 10 MB of junk: reading the file, the run that alarms, and the summary
// that prints its text problems (the first 100 and the counts). Peak RSS is per process: run one
// benchmark at a time (--benchmark_filter=NAME) to read it.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <random>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/summary.hpp"

using namespace ncurve;

namespace {

constexpr std::size_t kJunkBytes = 10 * 1024 * 1024;

// 0: random bytes (a line that starts with '%' ends the file, as on the control); 1: random
// printable ASCII but '%', and line ends: all 10 MB is read; 2: "X[[" lines (each a syntax error
// the expression parser finds); 3: lines of syntax errors, most with N, GOTO or a second N.
std::string junk(int kind) {
  std::mt19937 rng(1);
  std::string s;
  s.reserve(kJunkBytes);
  if (kind == 2) {
    while (s.size() + 4 <= kJunkBytes) s += "X[[\n";
    return s;
  }
  if (kind == 3) {
    static const char* lines[] = {"N1 X[[\n", "N2 G01 X1.2.3\n", "N3 #1=[[[\n", "N4 IF [1 GT] GOTO\n"};
    for (std::size_t i = 0; s.size() + 20 < kJunkBytes; ++i) s += lines[rng() % 4];
    return s;
  }
  while (s.size() < kJunkBytes) {
    const unsigned r = rng();
    if (kind == 0) s += static_cast<char>(r & 0xFF);
    else if (r % 96 == 95) s += '\n';
    else if (32 + r % 95 != '%') s += static_cast<char>(32 + r % 95);
  }
  return s;
}

void BM_JunkDiagnostics(benchmark::State& state) {
  const std::string text = junk(static_cast<int>(state.range(0)));
  const machine::MachineProfile profile = machine::default_mill();
  std::size_t printed = 0, problems = 0;
  for (auto _ : state) {
    machine::ProgramLibrary lib;
    std::vector<nc::Diagnostic> found = lib.add_text("junk.nc", text, true);
    machine::Interpreter interp(profile, lib);
    machine::NullSink sink;
    const machine::RunResult result = interp.run(sink);
    report::RunReport rep;
    rep.source = "junk.nc";
    rep.profile = &profile;
    rep.result = &result;
    rep.text_problems = std::move(found);
    rep.text_problems_left_out = lib.problems_left_out();
    rep.unchecked_lines = lib.unchecked_lines();
    const std::string summary = report::summary_text(rep);
    benchmark::DoNotOptimize(summary.data());
    printed = summary.size();
    problems = rep.text_problems.size() + rep.text_problems_left_out;
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(text.size()) * state.iterations());
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  state.counters["peak_rss_MB"] = static_cast<double>(u.ru_maxrss) / 1024.0;
  state.counters["summary_kB"] = static_cast<double>(printed) / 1024.0;
  state.counters["problems"] = static_cast<double>(problems);
}
BENCHMARK(BM_JunkDiagnostics)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->ArgName("kind")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
