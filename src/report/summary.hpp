// The run summary: what was executed, how far the tool went, what went wrong; as text or JSON.
#pragma once
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"

namespace ncurve::report {

struct SourceStats {
  std::size_t bytes = 0;
  std::size_t words = 0;   // address words (N and O included) plus one per macro statement
  std::size_t blocks = 0;  // non-empty blocks
  std::size_t programs = 0;
};

// Counts the files given (typically the main file only, as seed 000's Table 2 does).
SourceStats source_stats(const machine::ProgramLibrary& lib, const nc::SourceFile* file);

struct VerifyReport;

struct RunReport {
  std::string source;
  const machine::MachineProfile* profile = nullptr;
  const machine::RunResult* result = nullptr;
  SourceStats stats;
  std::vector<nc::Diagnostic> text_problems;  // syntax found by the parser, anywhere in the programs
  std::size_t text_problems_left_out = 0;     // found beyond those, counted only
  std::size_t unchecked_lines = 0;            // lines past those that can never run, not parsed
  const VerifyReport* verify = nullptr;       // --setup, --verify: the part
};

std::string summary_text(const RunReport& r);
std::string summary_json(const RunReport& r);
// The same as a JSON object (`ncurve serve` puts it in its answer), and one diagnostic's object.
nlohmann::json summary_object(const RunReport& r);
nlohmann::json diagnostic_json(const nc::Diagnostic& d);

}  // namespace ncurve::report
