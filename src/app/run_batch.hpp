// `ncurve run A.nc B.nc ...` or `ncurve run FOLDER`: each program run on its own with the same
// machine, libraries and options, the programs shared between the cores, and a table of results
// (docs/run.md, "Many programs at once").
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/run_setup.hpp"

namespace ncurve::app {

struct BatchRow {
  std::string program;
  std::string result;  // "completed", "alarm" (the run stopped on one), "error" (not run: why in `error`)
  std::uint64_t blocks = 0, motions = 0;
  double seconds = 0;  // at programmed feed and rapid rates, as the summary's "time (F only)"
  std::size_t warnings = 0;
  std::string alarm;        // the first alarm in words ("PS0010 prog.nc:11: ..."), empty: none
  nlohmann::json alarm_json;  // and as the summary's JSON gives it (null: none)
  std::string error;
};

// The programs a batch runs: each argument a program file, or a folder whose program files (the
// extensions --lib reads) are taken in name order. Throws std::runtime_error for a folder that
// cannot be read.
std::vector<std::string> batch_programs(const std::vector<std::string>& arguments);

// Runs each program as `in` says (its `program` set to each in turn), on all cores; the rows in
// the programs' order.
std::vector<BatchRow> run_batch(const RunInputs& in, const std::vector<std::string>& programs);

// The table (a row a program, then the counts) and the same as JSON.
std::string batch_text(const std::vector<BatchRow>& rows);
std::string batch_json(const std::vector<BatchRow>& rows);
// 0 when every program completed, 1 when one stopped on an alarm, 2 when one could not be run.
int batch_status(const std::vector<BatchRow>& rows);

}  // namespace ncurve::app
