// The `ncurve helicoid` subcommand.
#pragma once
#include <CLI/CLI.hpp>

#include <optional>
#include <stdexcept>
#include <string>

#include "helicoid/report.hpp"

namespace ncurve::app {

struct HelicoidArgs {
  std::string example;
  std::string profile;     // rotor or a curve of `ncurve gen --list`
  std::string profile_x, profile_y, u_range;
  std::string profile_csv;   // end profile as points x, y
  std::string cutter_profile;  // cutter axial profile: rho, w[, radius] vertices
  std::optional<double> lead;
  std::string hand = "right";
  std::optional<int> lobes;
  std::optional<double> cutter_diameter, corner_radius, included_angle, flank_depth;
  std::optional<double> ref_radius, crossing_angle, start_distance;
  double step = 1;
  std::optional<double> from, to;
  std::string method = "robust";
  double alpha_step = 0.05, s_step = 0.05;
  std::optional<double> alpha_range;
  bool csv = false, json = false, no_check = false;
  std::string output, program, plot;
  double length = 100, feed = 200;
  std::optional<double> program_tol;
  std::string final_motion = "x";  // x, z- (towards -Z) or z+
  std::string centre_distance;  // A, or FROM:TO:STEP
  std::optional<double> start_z;
  CLI::App* command = nullptr;
};

void add_helicoid_command(CLI::App& app, HelicoidArgs& args);
// Arguments the command refuses before it searches (it exits 2).
struct HelicoidRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// The contact table of the arguments (files, --plot and --program aside): the search and its job.
// Throws HelicoidRefused for bad arguments, std::runtime_error for a search that fails (exit 1).
void helicoid_job(const HelicoidArgs& a, std::optional<helicoid::ContactSearch>& search, helicoid::Job& job,
                  bool progress_shown);
int helicoid_command(const HelicoidArgs& args);

}  // namespace ncurve::app
