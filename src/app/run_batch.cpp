#include "app/run_batch.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <new>
#include <stdexcept>

#include "base/parallel.hpp"
#include "machine/library.hpp"
#include "nc/diagnostic.hpp"
#include "report/summary.hpp"

namespace ncurve::app {

namespace {

std::string alarm_words(const nc::Diagnostic& d) {
  return fmt::format("{} {}:{}: {}", d.code, d.span.file ? d.span.file->name() : "", d.span.line,
                     nc::escape_controls(d.message));
}

BatchRow run_one(RunInputs in, const std::string& program) {
  BatchRow row;
  row.program = program;
  in.program = program;
  try {
    RunSetup setup = prepare_run_of_any_size(in);
    machine::NullSink sink;
    machine::Interpreter interp(setup.profile, *setup.lib, setup.options);
    const machine::RunResult r = interp.run(sink);
    if (setup.lib->streamed()) complete_problems(setup);
    row.result = r.ok() ? "completed" : "alarm";
    row.blocks = r.stats.executed();
    row.motions = r.stats.motions;
    row.seconds = r.stats.seconds;
    row.warnings = r.warnings.size() + setup.problems.size() + setup.problems_left_out;
    if (r.alarm) {  // in words now: its file is the library's, gone with it
      row.alarm = alarm_words(*r.alarm);
      row.alarm_json = report::diagnostic_json(*r.alarm);
    }
  } catch (const std::bad_alloc&) {
    row.result = "error";
    row.error = "out of memory";
  } catch (const std::exception& e) {
    row.result = "error";
    row.error = nc::escape_controls(e.what());
  }
  return row;
}


}  // namespace

std::vector<std::string> batch_programs(const std::vector<std::string>& arguments) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  for (const std::string& a : arguments) {
    std::error_code ec;
    if (!fs::is_directory(a, ec)) {
      out.push_back(a);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& e : fs::directory_iterator(a, ec))
      if (e.is_regular_file(ec) && machine::program_file_name(e.path().string())) found.push_back(e.path().string());
    if (ec) throw std::runtime_error(fmt::format("{}: the folder cannot be read: {}", a, ec.message()));
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
  }
  return out;
}

std::vector<BatchRow> run_batch(const RunInputs& in, const std::vector<std::string>& programs) {
  std::vector<BatchRow> rows(programs.size());
  base::for_each_on_cores(programs.size(), [&](std::size_t k) { rows[k] = run_one(in, programs[k]); });
  return rows;
}

std::string batch_text(const std::vector<BatchRow>& rows) {
  std::size_t width = 7;
  for (const BatchRow& r : rows) width = std::min<std::size_t>(std::max(width, r.program.size()), 60);
  std::string out = fmt::format("{:<{}}  {:<9}  {:>10}  {:>9}  {:>12}  {:>8}  {}\n", "program", width, "result", "blocks",
                                "motions", "time (F) s", "warnings", "first alarm");
  std::size_t counts[3] = {0, 0, 0};
  for (const BatchRow& r : rows) {
    counts[r.result == "completed" ? 0 : r.result == "alarm" ? 1 : 2]++;
    if (r.result == "error") {
      out += fmt::format("{:<{}}  {:<9}  {}\n", r.program, width, "error", r.error);
      continue;
    }
    out += fmt::format("{:<{}}  {:<9}  {:>10}  {:>9}  {:>12.2f}  {:>8}  {}\n", r.program, width, r.result, r.blocks,
                       r.motions, r.seconds, r.warnings, r.alarm);
  }
  out += fmt::format("{} programs: {} completed, {} stopped on an alarm, {} not run\n", rows.size(), counts[0],
                     counts[1], counts[2]);
  return out;
}

std::string batch_json(const std::vector<BatchRow>& rows) {
  nlohmann::json programs = nlohmann::json::array();
  std::size_t counts[3] = {0, 0, 0};
  for (const BatchRow& r : rows) {
    counts[r.result == "completed" ? 0 : r.result == "alarm" ? 1 : 2]++;
    nlohmann::json j = {{"program", r.program}, {"result", r.result}};
    if (r.result == "error") {
      j["error"] = r.error;
    } else {
      // the keys of a single run's summary (ncurve run --json), the warnings and text problems counted
      j["ok"] = r.result == "completed";
      j["blocks_executed"] = r.blocks;
      j["motions"] = r.motions;
      j["time_at_programmed_feed_s"] = r.seconds;
      j["warning_count"] = r.warnings;
      j["alarm"] = r.alarm_json;
    }
    programs.push_back(j);
  }
  const nlohmann::json all = {{"programs", programs},
                              {"completed", counts[0]},
                              {"alarms", counts[1]},
                              {"errors", counts[2]}};
  return all.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

int batch_status(const std::vector<BatchRow>& rows) {
  int status = 0;
  for (const BatchRow& r : rows) status = std::max(status, r.result == "completed" ? 0 : r.result == "alarm" ? 1 : 2);
  return status;
}

}  // namespace ncurve::app
