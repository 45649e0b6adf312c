// The `ncurve analyze` subcommand: cycle time, servo contour error and shape error of a program;
// `ncurve analyze circle`: the circular test on the machine model.
#pragma once
#include <CLI/CLI.hpp>
#include <nlohmann/json_fwd.hpp>

#include <string>

#include "app/curve_args.hpp"
#include "app/run_setup.hpp"
#include "motion/circle.hpp"
#include "motion/planner.hpp"
#include "motion/servo.hpp"

namespace ncurve::app {

struct VerifyArgs;  // app/run_verify.hpp

struct AnalyzeArgs {
  RunInputs in;
  bool json = false;
  bool servo = false;
  std::string blocks;  // per-block timing CSV
  std::string plot;    // SVG
  CurveArgs curve;     // nominal curve for the shape error (name empty: none)
  std::string shape_csv;   // per-block shape error and seed 000's models
  std::string shape_plot;  // SVG: path coloured by deviation
  double tol = 0;          // mm: shape tolerance to mark (0: none)
  bool programmed = false; // --curve: the contour as programmed, not the compensated tool path
  std::string setup;       // --curve: the stock and tools the part is cut with (a mill)
  std::string wall = "auto";  // --curve: the design's walls (groove, edge, auto)
  std::size_t max_moves = 500000;  // --curve: contour moves kept (docs/analyze.md)
  double max_ticks = 50e6;         // --servo: servo periods simulated
  std::vector<std::string> kv;  // circle: KX[,KY]
  std::optional<double> feed_forward;
  double radius = 0, feed = 0;
  bool clockwise = false;
  CLI::App* command = nullptr;
  CLI::App* circle = nullptr;
};

void add_analyze_command(CLI::App& app, AnalyzeArgs& args);
int analyze_command(const AnalyzeArgs& args);

// The cycle time of `analyze --json` from the planner's totals (and the servo's contour error).
nlohmann::json analyze_json(const std::string& program, const machine::MachineProfile& profile,
                            const motion::PlanTotals& totals, const motion::ServoSim* sim);
// The cycle time analyze estimates for a program's text on a machine (feed planning, block and macro
// processing time). Throws std::runtime_error with the alarm when the program stops on one.
motion::PlanTotals program_time(const std::string& name, const std::string& text,
                                const machine::MachineProfile& profile);
// --kv and --feed-forward over the profile's servo settings; std::runtime_error for a bad gain.
void apply_servo_options(machine::MachineProfile& p, const AnalyzeArgs& a);
// --curve: how the part is cut and its walls measured (--setup, --wall, --tol, --max-moves).
VerifyArgs analyze_part(const AnalyzeArgs& a);
// base::BoundExceeded when the servo model would run past max_ticks periods at this block (--max-ticks).
void check_servo_ticks(const motion::BlockTime& b, const machine::MachineProfile& profile, double max_ticks);
// What `analyze circle --json` writes of a circular test.
nlohmann::json circle_json(const machine::MachineProfile& profile, const motion::CircleTest& test,
                           const motion::CircleResult& r);
// Lets the servo model settle after the last block (five time constants of the slowest loop).
void settle(motion::ServoSim& sim, const machine::MachineProfile& profile);

}  // namespace ncurve::app
