// The ncurve command: argument parsing and output only; the work is done by libncurve.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <memory>

#include "app/gen_command.hpp"
#include "app/helicoid_command.hpp"
#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "report/summary.hpp"
#include "report/writers.hpp"

namespace {

using namespace ncurve;

struct RunArgs {
  std::string program;
  std::string machine;
  std::vector<std::string> libs;
  std::vector<std::string> sets;
  std::vector<std::string> params;
  std::string format = "summary";
  double arc_tol = 0.001;
  std::string output;
  std::uint64_t max_steps = machine::RunOptions{}.max_steps;
  bool json = false;
};

std::pair<int, double> parse_set(const std::string& s) {
  auto eq = s.find('=');
  if (s.empty() || s[0] != '#' || eq == std::string::npos)
    throw CLI::ValidationError("--set", fmt::format("'{}' is not of the form #100=5", s));
  try {
    std::size_t used = 0;
    int n = std::stoi(s.substr(1, eq - 1), &used);
    if (used != eq - 1) throw std::invalid_argument("number");
    std::string value = s.substr(eq + 1);
    double v = std::stod(value, &used);
    if (used != value.size()) throw std::invalid_argument("value");
    return {n, v};
  } catch (const std::exception&) {
    throw CLI::ValidationError("--set", fmt::format("'{}' is not of the form #100=5", s));
  }
}

int run_command(const RunArgs& a) {
  machine::MachineProfile profile = machine::default_mill();
  machine::ProgramLibrary lib;
  std::vector<nc::Diagnostic> problems;
  machine::RunOptions options;
  options.max_steps = a.max_steps;
  try {
    for (const auto& s : a.sets) options.presets.push_back(parse_set(s));
    if (!a.machine.empty()) profile = machine::load_profile(a.machine);
    for (const auto& p : a.params) {
      auto eq = p.find('=');
      std::size_t used = 0;
      double v = 0;
      try {
        if (eq == std::string::npos) throw std::invalid_argument(p);
        v = std::stod(p.substr(eq + 1), &used);
        if (used != p.size() - eq - 1) throw std::invalid_argument(p);
      } catch (const std::exception&) {
        throw CLI::ValidationError("--param", fmt::format("'{}' is not of the form 6050=102", p));
      }
      try {
        machine::set_parameter(profile, p.substr(0, eq), v);
      } catch (const std::runtime_error& e) {
        throw CLI::ValidationError("--param", e.what());
      }
    }
    problems = lib.add_file(a.program, true);
    for (const auto& dir : a.libs) {
      auto more = lib.add_folder(dir);
      problems.insert(problems.end(), more.begin(), more.end());
    }
  } catch (const CLI::ValidationError& e) {
    std::cerr << "ncurve run: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }

  std::ofstream file;
  if (!a.output.empty()) {
    file.open(a.output, std::ios::binary);
    if (!file) {
      std::cerr << fmt::format("{}: error: cannot write the output file\n", a.output);
      return 2;
    }
  }
  std::ostream& out = a.output.empty() ? std::cout : file;

  std::unique_ptr<machine::MoveSink> sink;
  report::GcodeWriter* gcode = nullptr;
  if (a.format == "jsonl") sink = std::make_unique<report::JsonlWriter>(out, profile);
  else if (a.format == "csv") sink = std::make_unique<report::CsvWriter>(out, profile, a.arc_tol);
  else if (a.format == "gcode") {
    auto g = std::make_unique<report::GcodeWriter>(out, profile, a.program);
    gcode = g.get();
    sink = std::move(g);
  } else sink = std::make_unique<machine::NullSink>();

  machine::Interpreter interp(profile, lib, options);
  machine::RunResult result = interp.run(*sink);
  if (gcode) gcode->finish();

  report::RunReport rep;
  rep.source = a.program;
  rep.profile = &profile;
  rep.result = &result;
  rep.stats = report::source_stats(lib, lib.main()->file.get());
  rep.text_problems = problems;
  std::string summary = a.json ? report::summary_json(rep) : report::summary_text(rep);
  if (a.format == "summary") out << summary;
  else if (!a.output.empty()) std::cout << summary;
  else if (!result.ok()) std::cerr << nc::format(*result.alarm) << "\n";
  return result.ok() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncurve: run, generate and analyse FANUC Custom Macro B programs for non-circular curves"};
  app.require_subcommand(1);
  RunArgs a;
  CLI::App* run = app.add_subcommand("run", "execute a part program as a FANUC control would and report the tool path");
  run->add_option("program", a.program, "part program (.nc)")->required()->check(CLI::ExistingFile);
  run->add_option("--machine", a.machine, "machine profile (TOML); default: FANUC 3-axis mill, factory parameters")
      ->check(CLI::ExistingFile);
  run->add_option("--lib", a.libs, "folder of macro programs (O9010.nc, ...); may be repeated")
      ->check(CLI::ExistingDirectory);
  run->add_option("--param", a.params,
                  "set a control parameter over the profile's, e.g. --param 6050=102 (G102 calls O9010); may be "
                  "repeated");
  run->add_option("--set", a.sets, "preset a variable before the run, e.g. --set \"#100=5\"; may be repeated");
  run->add_option("--format", a.format, "output: summary (default), jsonl, csv or gcode")
      ->check(CLI::IsMember({"summary", "jsonl", "csv", "gcode"}));
  run->add_option("--arc-tol", a.arc_tol, "csv: chord error allowed when arcs are written as points, mm")
      ->check(CLI::PositiveNumber);
  run->add_option("-o,--output", a.output, "write the output to this file (the summary then goes to the terminal)");
  run->add_option("--max-steps", a.max_steps, "stop a program that has not ended after this many blocks")
      ->check(CLI::PositiveNumber);
  run->add_flag("--json", a.json, "summary as JSON");
  app::GenArgs g;
  app::add_gen_command(app, g);
  app::HelicoidArgs h;
  app::add_helicoid_command(app, h);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (run->parsed()) return run_command(a);
  if (g.command->parsed()) return app::gen_command(g);
  if (h.command->parsed()) return app::helicoid_command(h);
  return 2;
}
