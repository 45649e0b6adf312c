// The ncurve command line: every command's options on one CLI11 app. main() parses and runs the
// command; the command-line fuzzer (fuzz/fuzz_cli.cpp) parses alone.
#pragma once
#include <CLI/CLI.hpp>

#include <string>

#include "app/analyze_command.hpp"
#include "app/gen_command.hpp"
#include "app/helicoid_command.hpp"
#include "app/run_setup.hpp"
#include "app/run_verify.hpp"
#include "app/serve_args.hpp"

namespace ncurve::app {

inline constexpr const char* kDescription =
    "ncurve: run, generate and analyse FANUC Custom Macro B programs for non-circular curves";

struct RunArgs {
  RunInputs in;
  std::string format = "summary";
  double arc_tol = 0.001;
  std::string output;
  std::string dprnt;  // --dprnt FILE: the bytes POPEN/DPRNT/BPRNT/PCLOS sent
  bool json = false;
  std::string plot;  // --plot F.svg
  std::string view;  // --view xy|xz|yz|iso
  std::string html;  // --html F.html
  VerifyArgs verify;
};

// The commands' arguments, filled by parsing, and the subcommands to ask which one was given.
struct Commands {
  RunArgs run;
  GenArgs gen;
  HelicoidArgs helicoid;
  AnalyzeArgs analyze;
  ServeArgs serve;
  CLI::App* run_command = nullptr;
  CLI::App* completion = nullptr;
  CLI::App* man = nullptr;
};

void add_commands(CLI::App& app, Commands& c);

// "ncurve: 'X' is not a command ...\n" when the first argument names no command; else empty.
std::string not_a_command(CLI::App& app, int argc, const char* const* argv);

}  // namespace ncurve::app
