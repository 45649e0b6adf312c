#include "report/writers.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string_view>

namespace ncurve::report {

using machine::Move;
using machine::MoveKind;

static double clean(double v) { return v == 0 ? 0.0 : v; }  // no "-0"

// A record into the stream's buffer directly (no sentry a record); a short write fails the stream.
static void put(std::ostream& out, const fmt::memory_buffer& b) {
  const auto n = static_cast<std::streamsize>(b.size());
  if (out.rdbuf()->sputn(b.data(), n) != n) out.setstate(std::ios::badbit);
}

void JsonlWriter::on_move(const Move& m) {
  if (m.file != last_file_) {
    last_file_ = m.file;
    file_json_ = nlohmann::json(m.file ? m.file->name() : std::string())
                     .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);  // not UTF-8: U+FFFD
  }
  fmt::memory_buffer& b = buffer_;  // kept: no run-time format parsing, no growth per record
  b.clear();
  auto it = fmt::appender(b);
  fmt::format_to(it, FMT_COMPILE(R"({{"kind":"{}","file":{},"line":{},"program":{})"), machine::to_string(m.kind),
                 file_json_, m.line, m.program);
  if (m.is_motion() || m.kind == MoveKind::dwell) {
    fmt::format_to(it, FMT_COMPILE(R"(,"start":[{},{},{}],"end":[{},{},{}])"), clean(frame_.x(m.start[0])),
                   clean(m.start[1]), clean(m.start[2]), clean(frame_.x(m.end[0])), clean(m.end[1]), clean(m.end[2]));
    bool rotary = m.start[3] != 0 || m.end[3] != 0 || m.start[4] != 0 || m.end[4] != 0 || m.start[5] != 0 ||
                  m.end[5] != 0;
    if (rotary)
      fmt::format_to(it, FMT_COMPILE(R"(,"start_abc":[{},{},{}],"end_abc":[{},{},{}])"), clean(m.start[3]),
                     clean(m.start[4]), clean(m.start[5]), clean(m.end[3]), clean(m.end[4]), clean(m.end[5]));
  }
  if (m.compensated)
    fmt::format_to(it, FMT_COMPILE(R"(,"compensated":true,"programmed_end":[{},{},{}]{})"),
                   clean(frame_.x(m.programmed_end[0])), clean(m.programmed_end[1]), clean(m.programmed_end[2]),
                   m.corner ? R"(,"corner":true)" : "");
  if (m.kind == MoveKind::arc)
    fmt::format_to(it, FMT_COMPILE(R"(,"center":[{},{},{}],"plane":"G{}","direction":"{}","sweep_deg":{})"),
                   clean(frame_.x(m.center[0])), clean(m.center[1]), clean(m.center[2]), m.plane,
                   m.clockwise ? "G02" : "G03", m.sweep * 180 / std::numbers::pi);
  if (m.kind == MoveKind::line || m.kind == MoveKind::arc)
    fmt::format_to(it, FMT_COMPILE(R"(,"f":{},"feed_unit":"{}")"), m.feed, m.feed_per_rev ? "mm/rev" : "mm/min");
  if (m.threading) {
    fmt::format_to(it, FMT_COMPILE(R"(,"threading":true)"));
    if (m.thread_start >= 0) fmt::format_to(it, FMT_COMPILE(R"(,"thread_start_deg":{})"), m.thread_start / 1000.0);
  }
  if (m.is_motion()) fmt::format_to(it, FMT_COMPILE(R"(,"length":{},"lookahead":{})"), m.length, m.lookahead);
  if (m.kind == MoveKind::dwell || m.is_motion()) fmt::format_to(it, FMT_COMPILE(R"(,"seconds":{})"), m.seconds);
  if (!m.is_motion() && m.kind != MoveKind::dwell) fmt::format_to(it, FMT_COMPILE(R"(,"code":{})"), m.code);
  b.push_back('}');
  b.push_back('\n');
  put(out_, b);
}

CsvWriter::CsvWriter(std::ostream& out, const machine::MachineProfile& profile, double arc_tolerance)
    : out_(out), frame_(profile), arc_tolerance_(arc_tolerance) {
  out_ << "line,kind,x,y,z,f";
  for (char a : std::string_view("ABC"))
    if (profile.axes.find(a) != std::string::npos) {
      extra_.push_back(machine::axis_index(a));
      out_ << ',' << static_cast<char>(std::tolower(a));
    }
  out_ << '\n';
}

// The longest row of the fast columns: line, kind, f and six axes; the room RecentNumbers needs.
constexpr std::size_t kRowMost = 64 + 7 * (kFixed6Most + 32);
constexpr std::size_t kWriteAt = 1 << 16;  // an arc's rows go out in pieces of about this size

void CsvWriter::row(std::string_view line, std::string_view kind, const machine::AxisVector& p, double f) {
  fmt::memory_buffer& b = text_;
  const std::size_t used = b.size();
  b.try_resize(used + kRowMost);
  char* q = b.data() + used;
  std::memcpy(q, line.data(), line.size());
  q += line.size();
  *q++ = ',';
  std::memcpy(q, kind.data(), kind.size());
  q += kind.size();
  q = axis_[0].put(q, clean(frame_.x(p[0])));
  q = axis_[1].put(q, clean(p[1]));
  q = axis_[2].put(q, clean(p[2]));
  q = feed_.put(q, f);
  for (int a : extra_) q = axis_[a].put(q, clean(p[a]));
  *q++ = '\n';
  b.try_resize(static_cast<std::size_t>(q - b.data()));
  if (b.size() >= kWriteAt) write();
}

// The rows in pieces under 1 KiB, which a file stream keeps in its buffer as it kept single rows (a
// larger piece it writes at once): a small output still reaches the file only when it is committed,
// where a failed write (a full disk) is reported with its reason.
void CsvWriter::write() {
  constexpr std::size_t kPiece = 1000;
  std::streambuf& to = *out_.rdbuf();
  for (std::size_t at = 0; at < text_.size(); at += kPiece) {
    const auto n = static_cast<std::streamsize>(std::min(kPiece, text_.size() - at));
    if (to.sputn(text_.data() + at, n) != n) {
      out_.setstate(std::ios::badbit);
      break;
    }
  }
  text_.clear();
}

void CsvWriter::rows(const Move& m) {
  if (!m.is_motion() && m.kind != MoveKind::dwell) return;
  const std::string_view kind = machine::to_string(m.kind);
  const fmt::format_int number(m.line);
  const std::string_view line(number.data(), number.size());
  if (!started_) {
    row(line, kind, m.start, m.feed);
    started_ = true;
  }
  if (m.kind == MoveKind::arc) {
    machine::arc_points(m, arc_tolerance_, [&](const machine::AxisVector& p) { row(line, kind, p, m.feed); });
    return;
  }
  row(line, kind, m.end, m.feed);
}

void CsvWriter::on_move(const Move& m) {
  rows(m);
  if (text_.size()) write();
}

void CsvWriter::on_moves(std::span<const Move> moves) {
  for (const Move& m : moves) rows(m);
  if (text_.size()) write();
}

GcodeWriter::GcodeWriter(std::ostream& out, const machine::MachineProfile& profile, const std::string& source_name)
    : out_(out), profile_(profile), frame_(profile) {
  decimals_ = profile.increment < 0.001 ? 4 : 3;
  for (int k = 0; k < machine::kAxes; ++k) setup_.origin[k] = profile.work_offsets[0][k] + profile.work_offsets[1][k];
  out_ << "%\nO0001 (EXPANDED BY NCURVE FROM " << source_name << ")\n";
}

void GcodeWriter::on_setup(const machine::Setup& s) { setup_ = s; }

// The modal line before the first move, then a block for each change of the run's setup.
void GcodeWriter::write_setup() {
  const machine::Setup& s = setup_;
  const bool lathe = profile_.lathe();
  const bool system_a = lathe && profile_.gcode_system == 'A';
  auto work_code = [](int w) { return w <= 6 ? fmt::format("G{}", 53 + w) : fmt::format("G54.1 P{}", w - 6); };
  auto length_code = [](const machine::Setup& t) {
    return t.length_comp == 49 ? std::string("G49") : fmt::format("G{} H{}", t.length_comp, t.h);
  };
  if (!header_) {
    per_rev_ = profile_.power_on_feed_per_rev;
    per_rev_known_ = true;
    const char* feed_mode = system_a ? (per_rev_ ? "G99" : "G98") : (per_rev_ ? "G95" : "G94");
    std::string line = lathe ? fmt::format("G18 G21 G40{} {}", system_a ? "" : " G90", feed_mode)
                             : fmt::format("G17 G21 G40 G80 G90 {}", feed_mode);
    out_ << line << ' ' << work_code(s.work) << (lathe && s.length_comp == 49 ? "" : " " + length_code(s)) << '\n';
    local_.assign(profile_.axes.size(), num(0));
  } else {
    if (s.work != written_.work) out_ << work_code(s.work) << '\n';
    if (s.length_comp != written_.length_comp || s.h != written_.h) out_ << length_code(s) << '\n';
  }
  // what the origin holds beyond the profile's work offset (G52, G92, an offset changed by G10 or #5201..)
  const machine::AxisVector& work = s.work <= 6 ? profile_.work_offsets[s.work] : machine::AxisVector{};
  std::vector<std::string> local;
  for (char a : profile_.axes) {
    const int k = machine::axis_index(a);
    const double d = s.origin[k] - profile_.work_offsets[0][k] - work[k];
    local.push_back(num(k == 0 ? frame_.x(d) : d));
  }
  if (local != local_) {
    std::string line = "G52";
    for (std::size_t i = 0; i < local.size(); ++i) line += fmt::format(" {}{}", profile_.axes[i], local[i]);
    out_ << line << '\n';
    local_ = local;
  }
  if (!header_ || s.origin != written_.origin) at_known_.fill(false);
  written_ = s;
  header_ = true;
}

std::string GcodeWriter::num(double v) const {
  std::string s = fmt::format("{:.{}f}", clean(v), decimals_);
  while (!s.empty() && s.back() == '0') s.pop_back();  // keep the decimal point: "10." reads the same on any setting
  if (s == "-0.") s = "0.";
  return s;
}

void GcodeWriter::on_move(const Move& m) {
  std::string line;
  const bool lathe = profile_.lathe();
  if (m.is_motion()) {  // a roll-over axis starts a move within one turn: carry the turns it made
    if (moved_)
      for (int a = 3; a < machine::kAxes; ++a) turns_[a] += last_end_[a] - m.start[a];
    last_end_ = m.end;
    moved_ = true;
  }
  if (!header_ || !(setup_ == written_)) write_setup();
  auto axes = [&](const machine::AxisVector& p) {  // the axes whose position changes
    std::string s;
    for (char a : profile_.axes) {
      const int k = machine::axis_index(a);
      if (!at_known_[k]) at_[k] = num(k == 0 ? frame_.x(m.start[k]) : m.start[k] + turns_[k]);
      at_known_[k] = true;
      std::string v = num(k == 0 ? frame_.x(p[k]) : p[k] + turns_[k]);
      if (v == at_[k]) continue;
      s += fmt::format(" {}{}", a, v);
      at_[k] = std::move(v);
    }
    if (s.empty())  // a move to where the tool is: a block without axis words would not move at all
      for (char a : profile_.axes) s += fmt::format(" {}{}", a, at_[machine::axis_index(a)]);
    return s;
  };
  auto feed_mode = [&]() -> std::string {  // G94/G95 (G98/G99 on a system A lathe) before the motion code
    if (per_rev_known_ && per_rev_ == m.feed_per_rev) return "";
    per_rev_ = m.feed_per_rev;
    per_rev_known_ = true;
    if (lathe && profile_.gcode_system == 'A') return m.feed_per_rev ? "G99 " : "G98 ";
    return m.feed_per_rev ? "G95 " : "G94 ";
  };
  auto feed_word = [&]() -> std::string {
    if (m.feed == feed_) return "";
    feed_ = m.feed;
    return fmt::format(" F{}", num(m.feed));
  };
  switch (m.kind) {
    case MoveKind::rapid:
      line = "G00" + axes(m.end);
      motion_ = 0;
      break;
    case MoveKind::line: {
      if (m.threading) {  // G32 (G33 on lathe systems B/C and on a mill): F is the lead whatever the feed mode; Q the start angle
        line = (lathe && profile_.gcode_system == 'A' ? "G32" : "G33") + axes(m.end) + feed_word();
        if (m.thread_start > 0) line += fmt::format(" Q{}", m.thread_start);
        motion_ = 32;
        break;
      }
      line = feed_mode() + "G01" + axes(m.end) + feed_word();
      break;
    }
    case MoveKind::arc: {
      std::string f = feed_word();
      line = feed_mode() + fmt::format("G{} ", m.plane) + (m.clockwise ? "G02" : "G03") + axes(m.end);
      static const char* letters = "IJK";
      int in_plane[2] = {0, 1};
      if (m.plane == 18) { in_plane[0] = 0; in_plane[1] = 2; }
      if (m.plane == 19) { in_plane[0] = 1; in_plane[1] = 2; }
      for (int k : in_plane) line += fmt::format(" {}{}", letters[k], num(m.center[k] - m.start[k]));
      line += f;
      break;
    }
    case MoveKind::dwell: line = fmt::format("G04 P{}", static_cast<long>(std::lround(m.seconds * 1000))); break;
    case MoveKind::tool_change: line = lathe ? fmt::format("T{:04}", m.code) : fmt::format("T{} M06", m.code); break;
    case MoveKind::spindle:
      line = m.code == 5 || m.code == 19 ? fmt::format("M{:02}", m.code)
                                         : fmt::format("S{} M{:02}", std::lround(m.spindle), m.code);
      break;
    case MoveKind::coolant: case MoveKind::program_stop: case MoveKind::m_code:
      line = fmt::format("M{:02}", m.code);
      // rigid tapping allows no axis move after M29 but its cycle's; the cycle comes expanded
      if (m.kind == MoveKind::m_code && m.code == 29) line = "(M29 RIGID TAPPING: ITS CYCLE EXPANDED BELOW)";
      break;
    case MoveKind::program_end:
      line = fmt::format("M{:02}", m.code);
      ended_ = true;
      break;
  }
  out_ << line << '\n';
}

void GcodeWriter::stopped(const nc::Diagnostic& alarm) {
  if (!header_) write_setup();
  // a comment holds no parentheses and, read by a control, printable upper-case text
  std::string text = fmt::format("ALARM {} AT {}:{}: {} - THE RUN STOPPED HERE", alarm.code,
                                 alarm.span.file ? alarm.span.file->name() : "", alarm.span.line, alarm.message);
  for (char& c : text) {
    if (c == '(') c = '[';
    else if (c == ')') c = ']';
    else if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    else c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  out_ << "(" << text << ")\n";
  stopped_ = true;
}

void GcodeWriter::finish() {
  if (!header_) write_setup();
  if (!ended_ && !stopped_) out_ << "M30\n";
  out_ << "%\n";
}

void CsvWriter::stopped(const nc::Diagnostic& alarm) {  // the header is out already (constructor)
  out_ << alarm.span.line << ",alarm:" << alarm.code << ",,,," << std::string(extra_.size(), ',') << "\n";
}

nlohmann::json called_from_json(const nc::Diagnostic& d) {
  nlohmann::json calls = nlohmann::json::array();
  for (const nc::Span& s : d.called_from)
    calls.push_back({{"file", s.file ? s.file->name() : std::string()},
                     {"line", s.line},
                     {"block", std::string(nc::block_text(s))}});
  return calls;
}

void JsonlWriter::stopped(const nc::Diagnostic& alarm) {
  nlohmann::json j;
  j["kind"] = "alarm";
  j["file"] = alarm.span.file ? alarm.span.file->name() : std::string();
  j["line"] = alarm.span.line;
  j["column"] = alarm.span.column;
  j["alarm"] = alarm.code;
  j["message"] = alarm.message;
  if (!alarm.called_from.empty()) j["called_from"] = called_from_json(alarm);
  out_ << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

}  // namespace ncurve::report
