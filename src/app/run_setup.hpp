// What `ncurve run` and `ncurve analyze` share: the machine profile with --param overrides, the
// program and its macro folders, and the run options.
#pragma once
#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "report/summary.hpp"

namespace ncurve::app {

struct RunInputs {
  std::string program;
  std::string machine;
  std::vector<std::string> libs;
  std::vector<std::string> sets;    // "#100=5"
  std::vector<std::string> params;  // "6050=102"
  std::uint64_t max_steps = machine::RunOptions{}.max_steps;
  double max_seconds = machine::RunOptions{}.max_seconds;
  double max_memory_mb = 0;  // a file's compiled form at most; 0: nc::memory_bound's default
  bool nose_centre = false;
  bool stream = false;  // the program file read block by block as the run reaches it
  std::optional<std::string> text;          // the program's text, named `program` (not read from a file)
  std::optional<std::string> machine_text;  // a profile's TOML text, named `machine`
};

struct RunSetup {
  machine::MachineProfile profile = machine::default_mill();
  std::unique_ptr<machine::ProgramLibrary> lib = std::make_unique<machine::ProgramLibrary>();
  std::vector<nc::Diagnostic> problems;  // syntax found while reading the programs: the first 100
  std::size_t problems_left_out = 0;     // and how many more there are
  std::size_t unchecked_lines = 0;       // lines past those that no jump can reach, not parsed
  machine::RunOptions options;
  std::vector<std::string> inputs;  // every file read (program, macro folders' files, profile): never an output
};

// The options naming them: program (required unless program_required is false; a folder too
// where folder_ok), --machine, --lib, --param, --set, --max-steps, --max-seconds.
void add_run_inputs(CLI::App* command, RunInputs& in, bool program_required, bool folder_ok = false);
// Throws std::runtime_error with a message for the user (bad option, profile or file).
RunSetup prepare_run(const RunInputs& in);
// prepare_run as `run` reads its program: a file of kStreamFrom bytes or more, or one too large to
// read whole (--max-memory), as a stream.
RunSetup prepare_run_of_any_size(RunInputs in);
// The summary's report of a run of this setup, named `source` (its syntax problems copied).
report::RunReport run_report(const RunSetup& s, std::string source, const machine::RunResult& result,
                             const report::VerifyReport* verify = nullptr);
// A streamed program's problems once the run is over (the file is then read to its end).
void complete_problems(RunSetup& s);
// Program files of this many bytes and more are streamed by `run` (RunInputs::stream).
constexpr std::uintmax_t kStreamFrom = std::uintmax_t{8} << 20;
// Applies "--param N=V" overrides to a profile.
void apply_parameters(machine::MachineProfile& profile, const std::vector<std::string>& params);

}  // namespace ncurve::app
