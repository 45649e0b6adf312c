// Fits the time planner's machine parameters to the times the seeds measured, by least squares on
// the relative residuals, and prints every cell's residual: a finding about those machines, not a
// test constant. Seed 000 Table 2 (48 mm spiral at F100: expansion 35 s, macro 73 s) and seed 001
// Table 3 (G102 spirals of one turn, 10 mm pitch, 1/5/10 degree steps on five radius bands).
// Usage: fit_seeds [SOURCE_DIR]   (default: the source tree this was built from)
#include <Eigen/Core>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>
#include <fmt/core.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "motion/planner.hpp"

using namespace ncurve;

namespace {

class Collect final : public machine::MoveSink {
public:
  void on_move(const machine::Move& m) override { moves.push_back(m); }
  std::vector<machine::Move> moves;
};

// Runs the main program (text, or the file `name` when text is empty) with the macro folder.
std::vector<machine::Move> interpret(const std::string& name, const std::string& text,
                                     const machine::MachineProfile& profile, const std::string& macros) {
  machine::ProgramLibrary lib;
  if (text.empty()) lib.add_file(name, true);
  else lib.add_text(name, text, true);
  lib.add_folder(macros);
  machine::Interpreter interp(profile, lib, {});
  Collect sink;
  auto result = interp.run(sink);
  if (!result.ok()) throw std::runtime_error(name + ": " + result.alarm->message);
  return sink.moves;
}

// One measured time and the moves that produce it; `feed` replaces the feed of the cutting moves
// when the feed is itself fitted (seed 001 does not publish its F).
struct Cell {
  std::string label;
  double measured = 0;  // s
  std::vector<machine::Move> moves;
  bool cutting_only = false;  // time of the cutting moves (a stopwatch on the cycle) or the whole program
};

double model_time(const Cell& c, const machine::MachineProfile& profile, double feed) {
  double cutting = 0;
  motion::Planner planner(profile, [&](const motion::BlockTime& b) {
    if (b.move.kind != machine::MoveKind::rapid) cutting += b.wait + b.seconds + b.settle;
  });
  for (machine::Move m : c.moves) {
    if (feed > 0 && (m.kind == machine::MoveKind::line || m.kind == machine::MoveKind::arc)) {
      m.feed = feed;
      m.seconds = m.length / (feed / 60);  // the planner takes the programmed speed from these
    }
    planner.on_move(m);
  }
  planner.finish();
  return c.cutting_only ? cutting : planner.totals().seconds;
}

// A parameter set as fitted: natural logarithms, so every parameter stays positive.
struct Parameter {
  std::string name, unit;
  double start;
  std::function<void(machine::MachineProfile&, double&, double)> apply;  // profile, feed, value
};

struct Fit {
  std::vector<double> values;
  std::vector<double> model;
  double rms = 0;  // of the relative residuals
};

struct Residuals {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const std::vector<Cell>* cells;
  const std::vector<Parameter>* params;
  machine::MachineProfile base;

  int inputs() const { return static_cast<int>(params->size()); }
  int values() const { return static_cast<int>(cells->size()); }

  std::vector<double> times(const Eigen::VectorXd& x) const {
    auto profile = base;
    double feed = 0;
    for (std::size_t i = 0; i < params->size(); ++i) (*params)[i].apply(profile, feed, std::exp(x[static_cast<int>(i)]));
    std::vector<double> out;
    for (const auto& c : *cells) out.push_back(model_time(c, profile, feed));
    return out;
  }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    auto t = times(x);
    for (std::size_t i = 0; i < t.size(); ++i) f[static_cast<int>(i)] = t[i] / (*cells)[i].measured - 1;
    return 0;
  }
};

// Levenberg-Marquardt from every corner of a coarse grid around the starting values (the planner's
// time is piecewise smooth in its parameters, so one start can end in a local minimum).
Fit fit(const std::vector<Cell>& cells, const std::vector<Parameter>& params, const machine::MachineProfile& base) {
  Residuals r{&cells, &params, base};
  Fit best;
  best.rms = INFINITY;
  const int n = static_cast<int>(params.size());
  int corners = 1;
  for (int i = 0; i < n; ++i) corners *= 3;
  for (int corner = 0; corner < corners; ++corner) {
    Eigen::VectorXd x(n);
    for (int i = 0, c = corner; i < n; ++i, c /= 3) x[i] = std::log(params[static_cast<std::size_t>(i)].start) + (c % 3 - 1) * std::log(4.0);
    Eigen::NumericalDiff<Residuals> diff(r, 1e-4);
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> lm(diff);
    lm.parameters.maxfev = 400;
    lm.minimize(x);
    Eigen::VectorXd f(static_cast<int>(cells.size()));
    r(x, f);
    double rms = std::sqrt(f.squaredNorm() / static_cast<double>(f.size()));
    if (rms < best.rms) {
      best.rms = rms;
      best.values.clear();
      for (int i = 0; i < n; ++i) best.values.push_back(std::exp(x[i]));
      best.model = r.times(x);
    }
  }
  return best;
}

void print(const std::string& title, const std::vector<Cell>& cells, const std::vector<Parameter>& params, const Fit& f) {
  fmt::print("\n{}\n  fitted:", title);
  for (std::size_t i = 0; i < params.size(); ++i) fmt::print(" {} = {:.4g} {}{}", params[i].name, f.values[i], params[i].unit, i + 1 < params.size() ? "," : "");
  fmt::print("\n  rms relative residual {:.1f} %\n", 100 * f.rms);
  fmt::print("  | cell | measured s | model s | residual s | residual % |\n  |---|---|---|---|---|\n");
  for (std::size_t i = 0; i < cells.size(); ++i)
    fmt::print("  | {} | {:.2f} | {:.2f} | {:+.2f} | {:+.1f} |\n", cells[i].label, cells[i].measured, f.model[i],
               f.model[i] - cells[i].measured, 100 * (f.model[i] / cells[i].measured - 1));
}

const Parameter kMacroTime{"macro_time", "s/statement", 0.01,
                           [](machine::MachineProfile& p, double&, double v) { p.motion.macro_time = v; }};
const Parameter kAcceleration{"acceleration", "mm/s^2", 200, [](machine::MachineProfile& p, double&, double v) {
                                for (int a = 0; a < 3; ++a) p.motion.acceleration[a] = v;
                              }};
const Parameter kFeed{"F", "mm/min", 2000, [](machine::MachineProfile&, double& feed, double v) { feed = v; }};

std::vector<Cell> seed000(const std::string& dir, const machine::MachineProfile& mill) {
  auto macro = interpret(dir + "/examples/spiral.nc", "", mill, dir + "/macros");
  auto expanded = macro;  // the same moves as plain blocks: no macro statements before them
  for (auto& m : expanded) m.macro_statements = 0;
  return {{"seed 000 expanded", 35, expanded, false}, {"seed 000 macro", 73, macro, false}};
}

// F is "the maximum possible value" in the seed's G102 description: the profile's cutting limit.
std::vector<Cell> seed001(const std::string& dir, const machine::MachineProfile& mill) {
  const double steps[] = {1, 5, 10};
  const double measured[5][3] = {{38.0, 13.5, 8.75}, {55.1, 17.2, 10.8}, {62.5, 19.2, 12.3}, {67.1, 20.9, 13.6}, {70.6, 23.5, 15.0}};
  std::vector<Cell> cells;
  for (int band = 0; band < 5; ++band)
    for (int s = 0; s < 3; ++s) {
      const double r0 = 10.0 * band;
      std::string text = fmt::format("%\nO1\nG90 G17 G21 G54\nG00 X{:.1f} Y0.\nG102 X{:.1f} Y0. I{:.1f} J0. Q10. A{:.1f} F{:.1f}\nM30\n%\n",
                                     r0, r0 + 10, -r0, steps[s], mill.max_cutting_feed);
      auto label = fmt::format("seed 001 {:g}-{:g} mm, {:g} deg", r0, r0 + 10, steps[s]);
      cells.push_back({label, measured[band][s], interpret(label, text, mill, dir + "/macros"), true});
    }
  return cells;
}

std::vector<Cell> join(const std::vector<Cell>& a, const std::vector<Cell>& b) {
  auto out = a;
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string dir = argc > 1 ? argv[1] : NCURVE_SOURCE_DIR;
    const auto buffered = machine::load_profile(dir + "/profiles/fanuc-mill.toml");
    auto unbuffered = buffered;
    unbuffered.motion.look_ahead = 0;
    const auto s000 = seed000(dir, buffered);
    const auto s001 = seed001(dir, buffered);
    const std::string base = "profiles/fanuc-mill.toml";
    print("Seed 000 Table 2 (examples/spiral.nc at F100, whole program), " + base + " (look_ahead 30):", s000, {kMacroTime},
          fit(s000, {kMacroTime}, buffered));
    print("Seed 000 Table 2, no buffer (look_ahead 0):", s000, {kMacroTime}, fit(s000, {kMacroTime}, unbuffered));
    print("Seed 001 Table 3 (G102 through macros/O9010.nc, cutting time), " + base + " (look_ahead 30), F fitted too:", s001,
          {kMacroTime, kAcceleration, kFeed}, fit(s001, {kMacroTime, kAcceleration, kFeed}, buffered));
    print("Seed 001 Table 3, no buffer (look_ahead 0), F = the profile's cutting limit:", s001, {kMacroTime, kAcceleration},
          fit(s001, {kMacroTime, kAcceleration}, unbuffered));
    const auto both = join(s000, s001);
    print("Both seeds as one machine, no buffer:", both, {kMacroTime, kAcceleration}, fit(both, {kMacroTime, kAcceleration}, unbuffered));
  } catch (const std::exception& e) {
    fmt::print(stderr, "fit_seeds: {}\n", e.what());
    return 1;
  }
}
