#include "report/summary.hpp"

#include "report/verify_report.hpp"
#include "report/writers.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

namespace ncurve::report {

using machine::MoveKind;

SourceStats source_stats(const machine::ProgramLibrary& lib, const nc::SourceFile* file) {
  SourceStats s;
  if (file) s.bytes = file->size();
  for (const auto& p : lib.programs()) {
    if (p->file.get() != file) continue;
    ++s.programs;
    if (p->number >= 0) ++s.words;  // the O word
    nc::SourceCount count;
    if (!p->stream) count.add(*p);
    const nc::SourceCount& c = p->stream ? p->stream->count(p->stream_index) : count;
    s.blocks += c.blocks;
    s.words += c.words;
  }
  return s;
}

static std::string kind_counts(const machine::RunStats& s) {
  std::string out;
  for (int k = 0; k < 10; ++k) {
    if (!s.by_kind[k]) continue;
    if (!out.empty()) out += ", ";
    out += fmt::format("{} {}", s.by_kind[k], machine::to_string(static_cast<MoveKind>(k)));
  }
  return out.empty() ? "none" : out;
}

std::string summary_text(const RunReport& r) {
  const auto& res = *r.result;
  const auto& st = res.stats;
  const auto& prof = *r.profile;
  std::string out;
  out += fmt::format("ncurve run: {}\n", nc::escape_controls(r.source));
  out += fmt::format("  machine        {}\n", nc::escape_controls(prof.name));
  out += fmt::format("  source         {} bytes, {} words, {} blocks, {} program(s)\n", r.stats.bytes, r.stats.words,
                     r.stats.blocks, r.stats.programs);
  out += fmt::format("  executed       {} blocks\n", st.executed());
  out += fmt::format("  moves          {}\n", kind_counts(st));
  out += fmt::format("  path length    {:.3f} mm at feed, {:.3f} mm at rapid\n", st.feed_length, st.rapid_length);
  out += fmt::format("  time (F only)  {:.2f} s (programmed feed and rapid rates; no acceleration)\n", st.seconds);
  if (st.has_extent) {
    double xs = prof.lathe() && prof.diameter_x ? 2 : 1;
    for (char a : prof.axes) {
      int k = machine::axis_index(a);
      out += fmt::format("  extent {}{}      {:.4f} .. {:.4f}\n", a, k == 0 && xs == 2 ? "(dia)" : "     ",
                         st.min[k] * (k == 0 ? xs : 1), st.max[k] * (k == 0 ? xs : 1));
    }
  }
  std::vector<const nc::Diagnostic*> problems;
  for (const auto& d : r.text_problems)
    if (!res.alarm || res.alarm->span.line != d.span.line || res.alarm->span.file != d.span.file ||
        res.alarm->code != d.code)
      problems.push_back(&d);
  const std::size_t left_out = r.text_problems_left_out;
  if (!problems.empty())
    out += fmt::format("  text problems  {} more (each alarms when the control reaches its block){}\n",
                       problems.size() + left_out,
                       left_out ? fmt::format("; the first {} shown", problems.size()) : "");
  for (const auto* d : problems) out += nc::format(*d) + "\n";
  if (left_out) out += fmt::format("  ... and {} more text problems not shown\n", left_out);
  if (r.unchecked_lines)
    out += fmt::format("  ... and {} lines after them not checked: each follows a block that alarms and no jump can "
                       "reach it (no N, DO, WHILE, END or O)\n",
                       r.unchecked_lines);
  const auto& printed = res.output;
  if (!printed.lines.empty())
    out += fmt::format("  printed        {} line(s) by DPRNT/BPRNT (the bytes sent: --dprnt FILE)\n",
                       printed.lines.size() + printed.lines_left_out);
  for (const auto& line : printed.lines) out += fmt::format("    \"{}\"\n", line);
  if (printed.lines_left_out) out += fmt::format("    ... and {} more lines not shown\n", printed.lines_left_out);
  if (r.verify) out += verify_text(*r.verify);
  for (const auto& w : res.warnings) out += nc::format(w) + "\n";
  if (res.alarm) out += nc::format(*res.alarm) + "\n";
  out += res.ok() ? "  result         completed\n" : "  result         ALARM: execution stopped at the block above\n";
  return out;
}

nlohmann::json diagnostic_json(const nc::Diagnostic& d) {
  nlohmann::json j;
  j["severity"] = d.severity == nc::Severity::error ? "error" : d.severity == nc::Severity::warning ? "warning" : "note";
  j["code"] = d.code;
  j["message"] = d.message;
  if (d.span.file) {
    j["file"] = d.span.file->name();
    j["line"] = d.span.line;
    j["column"] = d.span.column;
    j["block"] = std::string(d.span.file->line(d.span.line));
  }
  if (!d.called_from.empty()) j["called_from"] = called_from_json(d);
  return j;
}

nlohmann::json summary_object(const RunReport& r) {
  const auto& res = *r.result;
  const auto& st = res.stats;
  const auto& prof = *r.profile;
  nlohmann::json j;
  j["source"] = r.source;
  j["machine"] = prof.name;
  j["source_bytes"] = r.stats.bytes;
  j["source_words"] = r.stats.words;
  j["source_blocks"] = r.stats.blocks;
  j["blocks_executed"] = st.executed();
  nlohmann::json moves = nlohmann::json::object();
  for (int k = 0; k < 10; ++k) moves[machine::to_string(static_cast<MoveKind>(k))] = st.by_kind[k];
  j["moves"] = moves;
  j["motions"] = st.motions;
  j["feed_length_mm"] = st.feed_length;
  j["rapid_length_mm"] = st.rapid_length;
  j["time_at_programmed_feed_s"] = st.seconds;
  if (st.has_extent) {
    nlohmann::json ext = nlohmann::json::object();
    double xs = prof.lathe() && prof.diameter_x ? 2 : 1;
    for (char a : prof.axes) {
      int k = machine::axis_index(a);
      ext[std::string(1, a)] = {st.min[k] * (k == 0 ? xs : 1), st.max[k] * (k == 0 ? xs : 1)};
    }
    j["extent"] = ext;
  }
  j["printed"] = res.output.lines;  // DPRNT/BPRNT lines, the first 1000
  j["printed_left_out"] = res.output.lines_left_out;
  j["warnings"] = nlohmann::json::array();
  for (const auto& w : res.warnings) j["warnings"].push_back(diagnostic_json(w));
  j["text_problems"] = nlohmann::json::array();
  for (const auto& d : r.text_problems) j["text_problems"].push_back(diagnostic_json(d));
  j["text_problems_left_out"] = r.text_problems_left_out;  // found beyond the first 100, counted only
  j["unchecked_lines"] = r.unchecked_lines;  // past those: lines no jump can reach, not parsed
  j["alarm"] = res.alarm ? diagnostic_json(*res.alarm) : nlohmann::json(nullptr);
  if (r.verify) j["verify"] = verify_json(*r.verify);
  j["ok"] = res.ok();
  return j;
}

std::string summary_json(const RunReport& r) {
  // a name that is not UTF-8 gets U+FFFD
  return summary_object(r).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace ncurve::report
