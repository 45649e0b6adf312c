// The checks of the main file beside its run (file_checks.cpp): what they keep while they run.
#pragma once
#include <memory>
#include <utility>
#include <vector>

#include "base/task_thread.hpp"
#include "machine/executor.hpp"
#include "machine/profile/profile_hints.hpp"

namespace ncurve::machine {

// NC2001's search of one program: its first word without a decimal point (not 0), and whether one has one.
struct DecimalPointSearch {
  bool with = false, without = false;
  char letter = 0;
  double value = 0;
  std::uint16_t column = 0;
  std::uint32_t line = 0;
  bool argument = false;
  bool in_cycle = false;  // a drilling canned cycle's mode, as the blocks read so far leave it
};

// The main file's checks of every program, made on a thread beside the run where there are two cores
// (a streamed file's as its pieces are read) and given at the end.
struct Executor::FileChecks {
  explicit FileChecks(const MachineProfile& start) : profile(start), hints(profile) {}
  MachineProfile profile;  // as the run starts (G10 L52 may change it): as the checks before a run see it
  ProfileHints hints;
  std::vector<std::pair<const nc::Program*, DecimalPointSearch>> programs;  // a streamed file's
  std::vector<nc::Diagnostic> found;  // a file read whole: its warnings
  std::unique_ptr<base::TaskThread> beside;  // last: finishes the checks before the rest goes
};

}  // namespace ncurve::machine
