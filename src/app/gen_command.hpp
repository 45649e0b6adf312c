// The `ncurve gen` subcommand.
#pragma once
#include <CLI/CLI.hpp>

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "motion/planner.hpp"

namespace ncurve::app {

struct GenArgs {
  std::string curve;
  bool list = false;
  double tol = 0.005;
  std::string form = "expanded";
  std::string lines = "equal-error";
  std::string machine;
  std::optional<std::string> machine_text;  // a profile's TOML text (machine: where it came from)
  std::optional<double> from, to;
  std::string x, y, z, t_range;
  double feed = 0;
  double depth = 1;
  double step_down = 0;
  int tip = 0;
  int cycle_program = 0;
  bool macro_only = false;
  double clearance = 5;
  int program_number = 1000;
  double tool_radius = 0;
  std::string side = "left";
  std::string plot;
  std::string output;
  bool json = false;
  // set-up and units (gen::Options)
  int tool = 0;
  int spindle = 0;
  bool spindle_ccw = false;
  int css = 0;
  int max_rpm = 0;
  long max_moves = 200000;
  bool coolant = false;
  bool inch = false;
  CLI::App* command = nullptr;
};

void add_gen_command(CLI::App& app, GenArgs& args);
int gen_command(const GenArgs& args);

// The options and the curve the arguments ask for (extras: the curve's --NAME VALUE parameters;
// command and options: for messages, see CurveArgs). Throws std::runtime_error for the user.
struct GenJob {
  gen::Options options;
  geom::Curve curve;
};
GenJob gen_job(const GenArgs& args, const std::vector<std::string>& extras, const std::string& command,
               const std::vector<std::string>& options);
// What gen warns of before generating (a lathe curve on a mill ...), each without "warning: ".
std::vector<std::string> gen_warnings(const GenJob& job);
// The common variables (#100..#199, #500..#999) a program assigns, ascending; comments are skipped.
std::vector<int> common_variables_set(const std::string& text);
// "#100..#102, #110" for {100, 101, 102, 110}.
std::string variable_ranges(const std::vector<int>& numbers);
// The statistics of `ncurve gen --json`, with the program's text when program is given.
nlohmann::json gen_json(const GenJob& job, const gen::Result& result, const std::string* program);
// The program's cycle time as `ncurve analyze` estimates it and, for a macro form, that of the same
// curve as G01 lines (none where one does not run).
struct GenTimes {
  std::optional<motion::PlanTotals> form, expanded;
};
GenTimes gen_times(const GenJob& job, const gen::Result& result);
// The warning of a macro form much slower than the G01 lines; empty if it is not.
std::string slower_warning(const GenJob& job, const GenTimes& times);
// What `ncurve gen --json` adds to gen_json: cycle_time_s, expanded_cycle_time_s, common_variables.
void add_gen_times(nlohmann::json& j, const GenTimes& times, const std::string& program_text);

}  // namespace ncurve::app
